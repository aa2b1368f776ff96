# Sourced by the benchmark scripts that run variations of a shipped scene.
# scene_copy SOURCE COPY [NAME VALUE]...: copies the parameter file SOURCE to
# COPY, then sets each entry whose line starts with NAME (after "set ") to
# VALUE in the copy; a NAME that matches no line stops the script (exit 2).
# A NAME may carry the entry's current value ("Tolerance = 1e-4") to pick one
# of several entries of the same name.
scene_copy() {
  local source=$1 copy=$2
  shift 2
  cp "$source" "$copy"
  while [ $# -ge 2 ]; do
    grep -q "^ *set $1" "$copy" || { echo "$(basename "$0"): no entry '$1' in $source" >&2; exit 2; }
    sed -i "\|^ *set $1|s|^\( *set ${1%% =*} *=\).*|\1 $2|" "$copy"
    shift 2
  done
  [ $# -eq 0 ] || { echo "$(basename "$0"): scene_copy: entry '$1' without a value" >&2; exit 2; }
}

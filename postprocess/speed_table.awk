# The table of a benchmark_contact output (speed-PLANNING.txt) in Markdown,
# for the documents: one row per grid, the columns named in words, the
# header's legend (its "# " lines after the table) as notes below it. The
# "# result" lines (each solve's A_nc and mean gap, for comparing builds)
# stay in the .txt.
# Usage: awk -f speed_table.awk speed-measure.txt > speed-measure.md
/^# FFTW planning/ { sub(/^# /, ""); header = $0; next }
/^# result/ || /^# +N \|/ { next }
/^ *[0-9]+ \|/ {
  split($0, f, "|"); split(f[2], a, " "); split(f[3], b, " "); split(f[4], c, " "); split(f[5], d, " ")
  rows[++n] = sprintf("| %d | %s | %s | %s | %s | %s | %s | %s + %s | %s | %s | %s | %s | %s | %s | %d |",
                      f[1], a[1], a[2], a[3], a[4], a[5], a[6], b[1], b[3], b[4], c[1], c[2], d[1], d[2], d[3], f[6])
  next }
/^# / { sub(/^# /, ""); notes[++m] = $0 }
END {
  print header
  print ""
  print "| N | iter | time (s) | s/iter | s/conv | iter/c | old res | cold iter (+ halved grids) | time (s) | iter6 | time6 (s) | iterA | timeA (s) | A_nc | MB/rank |"
  print "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  for (i = 1; i <= n; ++i) print rows[i]
  print ""
  for (i = 1; i <= m; ++i) print "- " notes[i]
}

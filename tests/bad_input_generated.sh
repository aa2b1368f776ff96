#!/usr/bin/env bash
# Usage: bad_input_generated.sh PENNY CASE EXPECTED
# Bad input too large or too bound to its own path to ship as a file, written
# here and checked by bad_input.sh:
#   include-in-output  an included file inside the output folder, which a run
#                 would replace
#   self-include  a parameter file that includes itself (by its absolute path)
#   huge-value    a 100 MB value, which the message must not echo whole
#   include-beside  an include of a file beside the parameter file, read from
#                 the working folder (deal.II's rule), where it is not
#   byte-order-mark  a UTF-8 byte-order mark before the first statement
#   nul-byte      a NUL byte inside a value, which cut the message there
#   json-nul      the same in a JSON value (an escaped \u0000)
#   json-array    a JSON array where an entry's value belongs
#   json-deep     JSON objects nested 100000 deep, which overflowed the stack
#                 of Boost's parser (a crash); json-deep-escaped with keys
#                 ending in an escaped backslash, xml-deep with '/>' in the
#                 text, which a first count of the depth missed
set -eu
penny=$1 case=$2 expected=$3
here=$(cd "$(dirname "$0")" && pwd)
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
prm=$folder/$case.prm
printf 'subsection Output\n  set Directory = out\nend\n' > "$prm"
case $case in
  include-in-output)
    mkdir "$folder/results"
    touch "$folder/results/.penny-results"
    printf 'subsection Output\n  set Directory = %s/results\nend\n' "$folder" > "$folder/results/inc.prm"
    echo "include $folder/results/inc.prm" > "$prm"
    ;;
  self-include)
    echo "include $prm" >> "$prm"
    ;;
  include-beside)
    printf 'subsection Material\n  set Poisson'"'"'s ratio nu = 0.3\nend\n' > "$folder/beside.prm"
    echo "include beside.prm" >> "$prm"
    ;;
  byte-order-mark)
    printf '\357\273\277set Scene = penny-gap\n' | cat - "$prm" > "$prm.new" && mv "$prm.new" "$prm"
    ;;
  json-nul)
    prm=$folder/$case.json
    printf '{"Scene": "penny-gap", "Output": {"Directory": "o\\u0000ut"}}' > "$prm"
    ;;
  json-array)
    prm=$folder/$case.json
    printf '{"Scene": ["penny-gap"]}' > "$prm"
    ;;
  json-deep)
    prm=$folder/$case.json
    /usr/bin/python3 -c "print('{\"a\": ' * 100000 + '1' + '}' * 100000)" > "$prm"
    ;;
  json-deep-escaped)
    prm=$folder/$case.json
    /usr/bin/python3 -c "print('{\"k\\\\\\\\\": ' * 100000 + '1' + '}' * 100000)" > "$prm"
    ;;
  xml-deep)
    prm=$folder/$case.xml
    /usr/bin/python3 -c "print('<ParameterHandler>' + '<a>/>' * 100000 + '</a>' * 100000 + '</ParameterHandler>')" > "$prm"
    ;;
  nul-byte)
    printf 'set Scene = penny\000gap\n' >> "$prm"
    ;;
  huge-value)
    /usr/bin/python3 -c "
import sys
with open(sys.argv[1], 'a') as prm:
    prm.write('subsection Material\n  set Young\'s modulus E = ' + '9' * 100000000 + '\nend\n')
" "$prm"
    ;;
esac
"$here/bad_input.sh" "$penny" "$prm" "$expected"

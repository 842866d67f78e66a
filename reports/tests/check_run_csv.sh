#!/usr/bin/env bash
# Checks a run folder's results.csv: one `test,Verdict,seconds` line per test
# (as many lines as SCENES_DIR has scenes times BACKENDS), and the verdicts named.
#
#   check_run_csv.sh RUN_DIR SCENES_DIR BACKENDS TEST=Verdict...
#
# Exit: 0 as expected; 1 not; 2 usage.
set -euo pipefail

if [ $# -lt 3 ]; then
  echo "usage: $0 RUN_DIR SCENES_DIR BACKENDS TEST=Verdict..." >&2
  exit 2
fi
csv="$1/results.csv"
scenes=$(find "$2" -name '*.json' | wc -l)
backends=$3
shift 3
status=0
lines=$(wc -l < "$csv")
if [ "$lines" -ne $((scenes * backends)) ]; then
  echo "$csv: $lines lines, expected $((scenes * backends)) (every test)" >&2
  status=1
fi
if grep -Evx '[^,]+,[A-Za-z]+,[0-9]+\.[0-9]{3}' "$csv" >&2; then
  echo "$csv: the lines above are not test,Verdict,seconds" >&2
  status=1
fi
for expectation in "$@"; do
  test=${expectation%%=*}
  verdict=${expectation#*=}
  if ! grep -Fq "$test,$verdict," "$csv"; then
    echo "$csv: no line '$test,$verdict,SECONDS'" >&2
    status=1
  fi
done
[ $status -ne 0 ] || echo "$csv: $lines tests, as expected"
exit $status

#!/usr/bin/env bash
# Passes when check_svgs_render.sh DIR fails for the reason given: a plot
# that drew nothing (exit 1 with a "BROKEN SVG" line, the default), or, with
# PATTERN, a BROKEN SVG line that also matches PATTERN (e.g. "overlaps: ",
# a label over another) -- not for any other reason.
#
#   bench_expect_svg_check_fails.sh DIR [PATTERN]
#
# Exit 77 (skip) when chromium is not installed.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dir=$1
pattern=${2:-}
output=$("$here/check_svgs_render.sh" "$dir" 2>&1)
status=$?
echo "$output"
[ $status -eq 77 ] && exit 77
if [ $status -eq 1 ] && grep '^BROKEN SVG ' <<<"$output" | grep -q -- "$pattern"; then
  echo "PASS: the broken plot was detected${pattern:+ ($pattern)}"
  exit 0
fi
echo "FAIL: expected the check to fail with BROKEN SVG${pattern:+ and '$pattern'}, it exited $status" >&2
exit 1

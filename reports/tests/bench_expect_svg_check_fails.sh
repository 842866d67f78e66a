#!/usr/bin/env bash
# Passes when check_svgs_render.sh DIR fails because a plot drew nothing
# (exit 1 with a "BROKEN SVG" line), not for any other reason.
# Exit 77 (skip) when chromium is not installed.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
output=$("$here/check_svgs_render.sh" "$@" 2>&1)
status=$?
echo "$output"
[ $status -eq 77 ] && exit 77
if [ $status -eq 1 ] && grep -q '^BROKEN SVG ' <<<"$output"; then
  echo "PASS: the broken plot was detected"
  exit 0
fi
echo "FAIL: expected the check to fail with BROKEN SVG, it exited $status" >&2
exit 1

#!/usr/bin/env bash
# Passes when check_images_load.sh RUN_DIR fails because an image did not
# load (exit 1 with a "NOT LOADED" line), not for any other reason.
# Exit 77 (skip) when chromium is not installed.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
output=$("$here/check_images_load.sh" "$@" 2>&1)
status=$?
echo "$output"
[ $status -eq 77 ] && exit 77
if [ $status -eq 1 ] && grep -q '^NOT LOADED: ' <<<"$output"; then
  echo "PASS: the missing image was detected"
  exit 0
fi
echo "FAIL: expected the check to fail with NOT LOADED, it exited $status" >&2
exit 1

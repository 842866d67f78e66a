#!/usr/bin/env bash
# The run report's light budgets (SPEC 5.5) for a run of
# limits.popping-64, per-object.eleven-lights and legacy.four-pixel-four-vertex:
# the two scenes whose budgets cut a light show their maps (reach, kept,
# loss; the animated one its strip of kept maps too) and per-light figures
# beside their verdicts, the legacy scene (4 pixel + 4 vertex lights, all
# kept) says in one line that nothing is cut, and every image of the page
# loads in headless Chromium (exit 77, a skip, without Chromium).
#
#   check_budget_report.sh RUN_DIR
set -euo pipefail
run_dir=$1
page=$run_dir/report/index.html
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -f "$page" ] || fail "no $page"
for scene in limits.popping-64 per-object.eleven-lights; do
  grep -q "id=\"budget-$scene\"" "$page" || fail "no budget section for $scene"
  for map in reach kept loss; do
    grep -q "src=\"../budgets/$scene/$map.png\"" "$page" || fail "$scene: no $map map"
    [ -s "$run_dir/budgets/$scene/$map.png" ] || fail "$scene: $map.png missing"
  done
done
grep -q 'src="../budgets/limits.popping-64/kept-strip.png"' "$page" || fail "popping-64: no strip of kept maps"
grep -q '<td>p0</td>' "$page" || fail "eleven-lights: p0's figures missing"
grep -q '<li>legacy.four-pixel-four-vertex: the budgets cut no light that reaches a pixel</li>' "$page" ||
  fail "the legacy scene's one line is missing"
exec "$(dirname "$0")/../reports/tests/check_images_load.sh" "$run_dir"

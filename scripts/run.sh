#!/usr/bin/env bash
# The project's main job on every backend that is present: the reference of
# every scene in suite/scenes/ (frame 0) under out/reference/<group>/<name>/,
# and `lightcts compare` of every scene on every backend, with the verdicts in
# out/compare/summary.txt and the evidence of each failure under
# out/compare/<group>.<name>.<backend>/. A backend that is not present is
# counted NotSupported, never a pass. `lightcts run` takes this over once the
# suite runner exists.
# Usage: scripts/run.sh [OUT_DIR]   (default: out)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}
bash scripts/build.sh
lightcts=build/release/app/lightcts

"$lightcts" backends
mkdir -p "$out/compare"
summary="$out/compare/summary.txt"
: > "$summary"
pass=0 fail=0 skip=0 error=0
for scene in suite/scenes/*/*.json; do
  group=$(basename "$(dirname "$scene")")
  name=$(basename "$scene" .json)
  "$lightcts" reference --scene "$scene" --out "$out/reference/$group/$name" >/dev/null || error=$((error + 1))
  # <test-name suffix>:<backend>:<driver>, as in suite/scene_tests.cmake.
  for combination in vulkan:vulkan: gl-egl:gl-egl:llvmpipe gl-osmesa:gl-osmesa:llvmpipe \
                     gl-egl-softpipe:gl-egl:softpipe gl-osmesa-softpipe:gl-osmesa:softpipe; do
    IFS=: read -r suffix backend driver <<<"$combination"
    driver_args=()
    [ -n "$driver" ] && driver_args=(--driver "$driver")
    case_name="$group.$name.$suffix"
    status=0
    "$lightcts" compare --scene "$scene" --backend "$backend" "${driver_args[@]}" \
      --evidence "$out/compare/$case_name" >>"$summary" 2>&1 || status=$?
    case $status in
      0) pass=$((pass + 1)) ;;
      1) fail=$((fail + 1)) ;;
      3) skip=$((skip + 1)); echo "NotSupported $case_name" >>"$summary" ;;
      *) error=$((error + 1)); echo "Crash $case_name (exit $status)" >>"$summary" ;;
    esac
  done
done
echo "run: $pass passed, $fail failed, $skip NotSupported, $error errors; verdicts in $summary"
[ $fail -eq 0 ] && [ $error -eq 0 ]

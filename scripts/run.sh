#!/usr/bin/env bash
# The project's main job on every backend that is present. Today: the
# double-precision reference of every scene in suite/scenes/ (frame 0), written
# under out/reference/<group>/<name>/. `lightcts run` takes over once the
# backends and the suite runner exist.
# Usage: scripts/run.sh [OUT_DIR]   (default: out)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}
bash scripts/build.sh
lightcts=build/release/app/lightcts

"$lightcts" backends
failed=0
for scene in suite/scenes/*/*.json; do
  group=$(basename "$(dirname "$scene")")
  name=$(basename "$scene" .json)
  "$lightcts" reference --scene "$scene" --out "$out/reference/$group/$name" || failed=1
done
echo "run: reference images under $out/reference/"
exit $failed

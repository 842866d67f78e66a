#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test with ctest (output on
# failure). Extra arguments go to ctest, e.g. scripts/test.sh -L unit.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --preset release -j"$(nproc)" "$@"

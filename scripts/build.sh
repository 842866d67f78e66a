#!/usr/bin/env bash
# Installs what is missing, then configures and builds the Release preset.
# Shared by run.sh and test.sh; safe to run again (an up-to-date build does nothing).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -- -j"$(nproc)"

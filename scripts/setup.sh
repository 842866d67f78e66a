#!/usr/bin/env bash
# Installs the Debian 12 packages lightcts builds and runs with, only those that
# are missing, quietly. Safe to run again: a machine that has everything does
# nothing here. Needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  # toolchain
  cmake g++ ninja-build pkg-config git
  make  # the build test configures with CMake's default generator, Unix Makefiles (cmake only recommends make)
  # the CPU model, the command line and the reference
  nlohmann-json3-dev libglm-dev libcli11-dev libopenimageio-dev
  libxxhash-dev  # XXH3, the bake cache file's checksum
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  libbenchmark-tools python3-scipy  # Google Benchmark's tools/compare.py reads bench.json (its test)
  python3  # the docs checks (docs/check_*.py) and the scripts of suite/ that tests run
  python3-numpy  # suite/gltf/check_same_images.py compares images as arrays
  # shaders: GLSL -> SPIR-V at build time (glslang), SPIR-V -> GLSL for OpenGL
  glslang-tools glslang-dev spirv-cross libspirv-cross-c-shared-dev
  # Vulkan on Mesa's lavapipe, with the validation layers for test runs
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  # OpenGL on Mesa (llvmpipe and softpipe) through EGL and OSMesa
  libegl-dev libgl-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
  # the report test: every image of report/index.html loads in headless Chromium
  # (about 350 MB installed; its test is skipped where it is missing)
  chromium
  # the plots' point labels are set in monospace, placed by its width
  # (reports/svg_labels.h): DejaVu Sans Mono, 0.6 em a glyph
  fonts-dejavu-core
  # the junit test: junit.xml validates against the JUnit XML schema (xmllint --schema)
  libxml2-utils
  # the evidence viewer's test reads the EXRs' floats exactly, independently
  # of the viewer's own data (OpenImageIO's Python module)
  python3-openimageio
  # glTF 2.0 import (SPEC 2.1): tinygltf keeps KHR_lights_punctual's intensity
  # and range apart (assimp folds intensity into the colour and drops range)
  libtinygltf-dev
  # real glTF content and deliberately broken files for the import's tests
  # (about 75 MB under /usr/share/assimp/models; their tests skip without it)
  assimp-testmodels
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 2; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

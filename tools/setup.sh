#!/usr/bin/env bash
# Installs the Debian 12 packages tidepool builds, runs and tests with.
# Idempotent: when every package is already installed it does nothing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  glslang-tools glslang-dev spirv-tools
  libglm-dev libopenimageio-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libglfw3-dev libimgui-dev libembree-dev python3-matplotlib
  xvfb xauth xdotool  # the viewer's tests open windows in Xvfb (xauth for xvfb-run) and type and click in them
  parallel  # the recipe in docs/rendering.md for a shot on one machine (tools/farm/parallel-shot.sh), tested
  clang libclang-rt-14-dev  # the sanitized CPU build and its libFuzzer targets (build-fuzz/)
  clang-format  # the house style, checked by the test `format`
  libtinygltf-dev  # glTF export: Debian builds tinygltf as a shared library (its images unused)
  libassimp-dev  # an independent reader of the exported OBJ and glTF, linked only by the tests
  blender  # the Cycles comparison test (cycles_reference) renders with it headless
  python3-numpy python3-openimageio  # that test's driver reads the EXRs and measures them (tools/cycles)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"

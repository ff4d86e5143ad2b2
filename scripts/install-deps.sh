#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# Installs the Debian 12 packages btFracture needs, but only those that are missing, and says
# which. Runs apt-get as root, or through sudo when available. Then the Khronos glTF-Validator
# (npm gltf-validator, the version in tools/gltf-validator/package-lock.json) into
# tools/gltf-validator/node_modules, unless it is there.
#   install-deps.sh          what the build, tests, demos and benchmarks need
#   install-deps.sh fuzz     plus clang, its libFuzzer runtime and OpenMP (make fuzz-short / fuzz-long)
#   install-deps.sh blender  plus Blender (make blender-check)
set -euo pipefail

packages=(
  cmake ninja-build g++ make pkg-config
  libbullet-dev libbullet-extras-dev libeigen3-dev libccd-dev
  libopenvdb-dev libtbb-dev libboost-dev libboost-iostreams-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libpng-dev
  parallel shellcheck clang-format python3-matplotlib nodejs
)
# Debian's npm; a Node.js from elsewhere (NodeSource) brings its own and conflicts with it.
command -v npm >/dev/null 2>&1 || packages+=(npm)
if [ "${1:-}" = fuzz ]; then
  packages+=(clang libclang-rt-14-dev libomp-dev)
fi
if [ "${1:-}" = blender ]; then
  packages+=(blender)
fi

validator="$(cd "$(dirname "$0")/.." && pwd)/tools/gltf-validator"
install_validator() {
  if [ ! -f "$validator/node_modules/gltf-validator/package.json" ]; then
    echo "install-deps: installing the glTF-Validator into $validator/node_modules"
    npm ci --prefix "$validator" --no-audit --no-fund --loglevel=error
  fi
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  install_validator
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  apt=(apt-get)
elif command -v sudo >/dev/null 2>&1; then
  apt=(sudo apt-get)
else
  echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${apt[@]}" update -qq
"${apt[@]}" install -y -qq --no-install-recommends "${missing[@]}"
install_validator

#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# Installs the Debian 12 packages btFracture needs, but only those that are missing, and says
# which. Runs apt-get as root, or through sudo when available.
#   install-deps.sh        what the build, tests, demos and benchmarks need
#   install-deps.sh fuzz   plus clang, its libFuzzer runtime and OpenMP (make fuzz-short / fuzz-long)
set -euo pipefail

packages=(
  cmake ninja-build g++ make pkg-config
  libbullet-dev libbullet-extras-dev libeigen3-dev libccd-dev
  libopenvdb-dev libtbb-dev libboost-dev libboost-iostreams-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libpng-dev
  parallel shellcheck
)
if [ "${1:-}" = fuzz ]; then
  packages+=(clang libclang-rt-14-dev libomp-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
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

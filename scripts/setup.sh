#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages) and builds the project in Release into build/.
set -euo pipefail
cd "$(dirname "$0")/.."

# libcgal-dev: the outside peer of the locate benchmarks and `dymesh bench`;
# chromium (and its driver): the report test renders report.html headless;
# pybind11-dev, python3-dev, python3-numpy: the Python module; pkg-config: the install test;
# librandom123-dev: the ensembles' counter-based streams; libopenmpi-dev, openmpi-bin: ensembles on MPI
packages=(build-essential cmake libeigen3-dev libembree-dev libtbb-dev libgtest-dev libbenchmark-dev
          nlohmann-json3-dev libcli11-dev libassimp-dev libcgal-dev chromium chromium-driver
          pybind11-dev python3-dev python3-numpy pkg-config librandom123-dev libopenmpi-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"

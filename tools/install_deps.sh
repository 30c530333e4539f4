#!/usr/bin/env bash
# Installs touchdown's build and run dependencies from Debian packages (Debian 12, as root).
# Idempotent and quiet: apt-get runs only when a package is missing.
set -euo pipefail
packages=(
  cmake g++ ninja-build pkg-config ccache
  libeigen3-dev libcgal-dev libsundials-dev
  libgtest-dev libbenchmark-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  gnuplot-nox
  libceres-dev
  libsqlite3-dev sqlite3 libopenmpi-dev openmpi-bin libboost-dev
  clang libclang-rt-14-dev
  pybind11-dev python3-dev python3-pybind11 python3-numpy python3-pandas python3-pytest python3-matplotlib python3-yaml
  python3-vtk9  # tests/python/test_vtk.py reads the ParaView output with VTK's own reader (18 s, 223 MB)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then echo "error: run as root to install packages" >&2; exit 1; fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >/dev/null
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

#!/usr/bin/env bash
# Installs what a purpose needs from Debian packages (Debian 12, as root), only what is missing:
# idempotent and quiet (apt-get runs only when a package is missing).
#   bash tools/install_deps.sh [PURPOSE ...]     (default: main)
#   main       build and run the main job (tools/run_main.sh): the compiler, CMake, the libraries
#              the `touchdown` executable and the Python module are built on, gnuplot for its plots
#   tests      the test suite (tools/run_tests.sh): GoogleTest, Google Benchmark, pytest and what
#              the Python tests read with (numpy, pandas, yaml, matplotlib, VTK's reader), tqdm
#              (the Python module's progress bars) and the notebook runner (nbclient, ipykernel)
#   mpi        `touchdown sweep` over MPI ranks (mpirun -np N): OpenMPI
#   hardening  the sanitizer and fuzzer build (tools/run_sanitized_tests.sh, run_fuzzers.sh): clang
#   package    the Debian package's Depends (`cpack -G DEB`): dpkg-shlibdeps
#   docs       the figures of docs/ made outside the commands: ParaView's pvbatch under xvfb
#              (tools/paraview_view.py), matplotlib (docs/python.md's example)
# A purpose builds on main's packages (tests on main's too), so each installs main's as well.
set -euo pipefail
main=(
  cmake g++ ninja-build pkg-config ccache
  libeigen3-dev libcgal-dev libsundials-dev libceres-dev libboost-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libsqlite3-dev
  pybind11-dev python3-dev  # the Python module (build/python)
  gnuplot-nox               # every command's plots
)
tests=(
  libgtest-dev libbenchmark-dev sqlite3
  python3-pytest python3-numpy python3-pandas python3-yaml python3-matplotlib python3-pybind11
  python3-vtk9  # tests/python/test_vtk.py reads the ParaView output with VTK's own reader (18 s, 223 MB)
  python3-tqdm  # the Python module's progress bars (tests/python/test_progress.py)
  python3-nbclient python3-nbformat python3-ipykernel  # tests/python/test_notebook.py runs examples/notebooks/
  dpkg-dev      # tests/install/debian_package.cmake packages with dpkg-shlibdeps
)
mpi=(libopenmpi-dev openmpi-bin)
hardening=(clang libclang-rt-14-dev)
package=(dpkg-dev)
docs=(paraview python3-paraview xvfb xauth python3-matplotlib)

purposes=("$@")
[ ${#purposes[@]} -gt 0 ] || purposes=(main)
packages=("${main[@]}")
for purpose in "${purposes[@]}"; do
  case "$purpose" in
    main) ;;
    tests) packages+=("${tests[@]}") ;;
    mpi) packages+=("${mpi[@]}") ;;
    hardening) packages+=("${hardening[@]}") ;;
    package) packages+=("${package[@]}") ;;
    docs) packages+=("${docs[@]}") ;;
    *) echo "error: unknown purpose '$purpose' (main, tests, mpi, hardening, package, docs)" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing (${purposes[*]}): ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then echo "error: run as root to install packages" >&2; exit 1; fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >/dev/null
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

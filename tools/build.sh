#!/usr/bin/env bash
# Configures and builds touchdown (Release) into build/ at the repository root.
#   bash tools/build.sh            the quick start's target `touchdown_quickstart` (tools/run_main.sh):
#                                  the `touchdown` executable and the Python module (build/python), so
#                                  everything `cmake --install build` installs
#   bash tools/build.sh all        every target: tests, benchmarks, tools (tools/run_tests.sh)
#   bash tools/build.sh T1 T2 ...  the named targets
#   bash tools/build.sh --package  the Debian package from a portable build (no -march=native) in
#                                  build-deb/: build-deb/touchdown_VERSION_amd64.deb, for any x86-64
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
targets=("$@")
if [ "${1:-}" = "--package" ]; then
  # Its own build folder: build/ is native, and a package of it runs only on CPUs like this one's.
  bash "$root/tools/install_deps.sh" main package
  source "$root/tools/compiler_cache.sh"
  cmake -S "$root" -B "$root/build-deb" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTOUCHDOWN_NATIVE=OFF \
    "${compiler_cache_args[@]}" >/dev/null
  cmake --build "$root/build-deb" --parallel "$(nproc)" --target touchdown_quickstart
  (cd "$root/build-deb" && cpack -G DEB)
  exit 0
fi
# The quick start needs only the main job's packages; anything more (`all`: the tests, benchmarks
# and MPI sweeps) the test suite's too, and builds the tests and benchmarks, which a build
# configured on main's packages alone leaves out (top-level CMakeLists.txt).
options=()
if [ ${#targets[@]} -eq 0 ]; then
  targets=(touchdown_quickstart)
  bash "$root/tools/install_deps.sh" main
else
  bash "$root/tools/install_deps.sh" main tests mpi
  options=(-DTOUCHDOWN_BUILD_TESTS=ON -DTOUCHDOWN_BUILD_BENCH=ON)
fi
# Native instruction set (-march=native): the in-tree runs are on the machine that built them; an
# install for other machines is configured without it (docs/install.md).
source "$root/tools/compiler_cache.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTOUCHDOWN_NATIVE=ON \
  "${compiler_cache_args[@]}" "${options[@]}" >/dev/null
start=$SECONDS
cmake --build "$root/build" --parallel "$(nproc)" --target "${targets[@]}"
echo "build (${targets[*]}): $((SECONDS - start)) s on $(nproc) cores"

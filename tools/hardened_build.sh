#!/usr/bin/env bash
# Configures the clang AddressSanitizer + UndefinedBehaviorSanitizer build in build-hard/
# (TOUCHDOWN_HARDENING_DIR overrides) and builds the targets given (default: all of it). One
# configuration serves tools/run_sanitized_tests.sh and tools/run_fuzzers.sh, so the second
# reuses every object of the first.
#
# Portable (TOUCHDOWN_NATIVE=OFF, no -march=native, as the Debian package is built): the suite runs
# on both instruction-set builds in CI, the README's native one and this one, so a test that holds
# only with one CPU's rounding fails here.
# Optimised at -O1 with line tables only (-g1): enough for symbolised reports, and it keeps the
# CGAL translation units' compile time and the suite's run time in CI's budget. What no sanitized
# test runs is left out: the benchmarks, the derivation programs of tools/ and the Python module
# (an ASan-instrumented extension cannot be loaded into an uninstrumented python3).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${TOUCHDOWN_HARDENING_DIR:-$root/build-hard}
jobs=${TOUCHDOWN_JOBS:-$(nproc)}
bash "$root/tools/install_deps.sh" main tests mpi hardening
source "$root/tools/compiler_cache.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${compiler_cache_args[@]}" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DTOUCHDOWN_SANITIZE=ON -DTOUCHDOWN_FUZZ=ON -DTOUCHDOWN_BUILD_BENCH=OFF -DTOUCHDOWN_BUILD_TOOLS=OFF \
  -DTOUCHDOWN_NATIVE=OFF >/dev/null
start=$SECONDS
cmake --build "$build" --parallel "$jobs" ${1:+--target "$@"}
echo "sanitized build (${*:-all}): $((SECONDS - start)) s on $jobs jobs"

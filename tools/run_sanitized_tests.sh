#!/usr/bin/env bash
# The whole test suite a second time, built with AddressSanitizer and UndefinedBehaviorSanitizer
# in build-asan/. Any sanitizer report aborts the test that triggered it, so CI fails on it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/tools/install_deps.sh"
cmake -S "$root" -B "$root/build-asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTOUCHDOWN_SANITIZE=ON -DTOUCHDOWN_BUILD_BENCH=OFF >/dev/null
cmake --build "$root/build-asan" --parallel "$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$root/build-asan"
ctest --output-on-failure --parallel "$(nproc)" --timeout 900

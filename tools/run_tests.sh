#!/usr/bin/env bash
# The whole test suite: install dependencies, build, run every GoogleTest case through CTest.
# Prints the build's and the run's times and the slowest tests (what to look at when CI's budget
# is tight: tools/run_sanitized_tests.sh reuses these timings to schedule its own run).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/tools/build.sh" all
cd "$root/build"
start=$SECONDS
ctest --output-on-failure --parallel "$(nproc)" --timeout 600
echo "ctest: $((SECONDS - start)) s on $(nproc) cores"
bash "$root/tools/slowest_tests.sh" "$root/build" 10

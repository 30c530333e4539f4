#!/usr/bin/env bash
# The whole test suite: install dependencies, build, run every GoogleTest case through CTest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/tools/build.sh" all
cd "$root/build"
ctest --output-on-failure --parallel "$(nproc)" --timeout 600

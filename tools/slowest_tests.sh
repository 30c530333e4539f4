#!/usr/bin/env bash
# bash tools/slowest_tests.sh BUILD [N]: the N (default 10) slowest tests of BUILD's last CTest
# run, from CTest's own timing record (Testing/Temporary/CTestCostData.txt: name, runs, seconds).
set -euo pipefail
costs="$1/Testing/Temporary/CTestCostData.txt"
[ -f "$costs" ] || { echo "no test timings in $1"; exit 0; }
echo "slowest tests (s):"
awk 'NF == 3 && $1 != "---" { printf "%8.1f  %s\n", $3, $1 }' "$costs" | sort -rn | head -"${2:-10}"

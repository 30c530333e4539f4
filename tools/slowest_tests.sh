#!/usr/bin/env bash
# bash tools/slowest_tests.sh BUILD [N]: the N (default 10) slowest tests of BUILD's last CTest
# run, from CTest's own timing record (Testing/Temporary/CTestCostData.txt: name, runs, seconds).
set -euo pipefail
costs="$1/Testing/Temporary/CTestCostData.txt"
[ -f "$costs" ] || { echo "no test timings in $1"; exit 0; }
echo "slowest tests (s):"
# The last stage reads all its input (head would exit early, and with pipefail sort's SIGPIPE,
# status 141, would fail the script once the list outgrows the pipe's buffer).
awk 'NF == 3 && $1 != "---" { printf "%8.1f  %s\n", $3, $1 }' "$costs" | sort -rn | awk -v n="${2:-10}" 'NR <= n'

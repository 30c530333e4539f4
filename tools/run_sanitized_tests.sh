#!/usr/bin/env bash
# The test suite a second time (all but the two documentation-example tests, below), built with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-hard/ (TOUCHDOWN_HARDENING_DIR overrides). Every report is
# fatal (-fno-sanitize-recover=all, halt_on_error, abort_on_error): the test that triggered it
# fails, and so does this script. The same build also holds the libFuzzer targets, so
# tools/run_fuzzers.sh afterwards only runs them (one clang build serves both).
#
# (The MPI sweep test turns LeakSanitizer off for its mpirun ranks only: OpenMPI's exit-time
# allocations come from plugins it has unloaded, which no suppression can name.)
#
# Optimised at -O1 with line tables only (-g1): enough for symbolised reports, and it keeps the
# CGAL translation units' compile time and the suite's run time in CI's budget.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${TOUCHDOWN_HARDENING_DIR:-$root/build-hard}
jobs=${TOUCHDOWN_JOBS:-$(nproc)}
bash "$root/tools/install_deps.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DTOUCHDOWN_SANITIZE=ON -DTOUCHDOWN_FUZZ=ON -DTOUCHDOWN_BUILD_BENCH=OFF -DTOUCHDOWN_NATIVE=ON >/dev/null
cmake --build "$build" --parallel "$jobs"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
# Left out here, run by tools/run_tests.sh: the two tests that run every example of the README and of
# each command's --help as written. They check the documentation against the program; under the
# sanitizers they cost 370 CPU-s (a quarter of this stage) while the commands they run are each run
# here by their own CLI tests (cli, stability, robustness, determinism, output and plot tests).
docs_examples='^(CliHelp\.EveryCommandsExamplesRunAsWritten|Readme\.EveryExampleRunsAsWritten)$'
ctest --output-on-failure --parallel "$jobs" --timeout 900 -E "$docs_examples"

#!/usr/bin/env bash
# The test suite a second time (all but the tests named below), built with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer in build-hard/ (TOUCHDOWN_HARDENING_DIR overrides;
# tools/hardened_build.sh configures it). Every report is fatal (-fno-sanitize-recover=all,
# halt_on_error, abort_on_error): the test that triggered it fails, and so does this script. The
# same build also holds the libFuzzer targets, so tools/run_fuzzers.sh afterwards only runs them
# (one clang build serves both).
#
# (The MPI sweep test turns LeakSanitizer off for its mpirun ranks only: OpenMPI's exit-time
# allocations come from plugins it has unloaded, which no suppression can name.)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${TOUCHDOWN_HARDENING_DIR:-$root/build-hard}
jobs=${TOUCHDOWN_JOBS:-$(nproc)}
bash "$root/tools/hardened_build.sh"

# Stack use after return is looked for by the fuzzers (tools/run_fuzzers.sh), on the parsers' varied
# inputs, not here: its fake stacks cost 15-30 % of this suite's CPU (pad, multibody and drop tests,
# measured 2026-11-27), and the compilers' -Wreturn-local-addr / -Wreturn-stack-address catch the
# plain cases at build time.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=0:check_initialization_order=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
# Without a timing history (a clean clone) CTest starts tests in the order they are listed, and a
# long one started last runs alone on one core. The plain run's timings (tools/run_tests.sh, same
# test names, each about 4x faster than here) order this run longest first.
costs=Testing/Temporary/CTestCostData.txt
if [ ! -f "$costs" ] && [ -f "$root/build/$costs" ]; then
  mkdir -p Testing/Temporary
  cp "$root/build/$costs" "$costs"
fi
# Left out here, run by tools/run_tests.sh: tests that only repeat, at great cost under the
# sanitizers, code paths that the tests run here cover already. What they check beyond those paths
# is not what a sanitizer finds:
# - the two tests that run every example of the README and of each command's --help as written:
#   they check the documentation against the program; each command they run has CLI tests of its
#   own that do run here (cli, stability, robustness, output and plot tests).
# - OutputReplaceKill.*: each runs a command about 20 times and kills it at random moments to check
#   that the old or the new output is left whole. A killed process reports nothing to a sanitizer;
#   the writer's code (drop_tests/formats/output_path.cpp) runs here through its unit tests
#   (tests/drop_tests/formats/output_path_test.cpp) and every command's outputs.
# - Determinism.* and StabilityCli.PatchFieldsPerLandingAreTheSameOnOneThreadAndOnTwo: the same
#   drop, campaign, lander run, sweep or patchy-ground study again (twice, on 1 and 2 threads, in
#   shards) to compare bytes; every one of those commands runs here in its own CLI tests, the
#   threaded sweep and shards and merges included (apps/stability_cli_test.cpp, sweep tests), and
#   the patch field in scenario and stability tests. (The patchy-ground comparison alone took 200
#   s of this suite's CPU.) Likewise the byte comparisons of a sweep's export with the in-memory
#   dataset and of the evaluation limit at two thread counts (SweepControl.ExportStreams...,
#   SweepControl.TheEvaluationLimitFails...AnyThreadCount...): the export and the limit each run
#   here in their own tests.
# - LanderSimilitude.FullScale...: one asymmetric landing at full and at model scale, at rtol 1e-9,
#   compared to 1e-6 (a physics identity; the lander code runs here in the multibody, scenario and
#   stability tests), and install_package and debian_package (cmake --install, cpack's package, and
#   a consumer built against each: the packaging, not our code's memory, is what they check).
# - The same workflow on other data: Library/HiddenEffect.* runs `diagnose` end to end once per
#   hidden effect, and EveryShippedPad/ShippedPadFreeDrop.* a free drop of each shipped pad at every tilt.
#   Here the first for a hidden inertial drag and a gas cushion, the second for the curved (revolved)
#   and the hex (mesh) pad; each effect's and each pad's own code has unit tests that run here
#   (tests/drop_tests/model/effects_test.cpp, tests/lander/pad/).
#   RareEventStudy.ImportanceReusesTheSubsetRunsLandings runs 57 landings to check which folder
#   holds them; the importance estimator's code runs here on analytic limit states
#   (tests/drop_tests/stability/rare_event_test.cpp) and the landing passes in the subset tests.
#   Diagnose.EffectOutsideTheLibraryIsNotNamedConfidently and
#   Diagnose.WithoutTheTermTheFloorNamesNoLibraryEffect, `diagnose` on a control whose effect lies
#   outside the library, are left out for the same reason (63 s here, the costliest tests); the
#   other Diagnose.* cases run the same command here, and the selection rule they check runs here
#   on scored models (tests/drop_tests/gap/diagnose_selection_test.cpp).
left_out='^(CliHelp\.EveryCommandsExamplesRunAsWritten|Readme\.EveryExampleRunsAsWritten|OutputReplaceKill\..*|Determinism\..*|StabilityCli\.PatchFieldsPerLandingAreTheSameOnOneThreadAndOnTwo|SweepControl\.ExportStreamsTheSameFilesAsTheInMemoryDataset|SweepControl\.TheEvaluationLimitFailsTheSameDropsAtAnyThreadCountNamingTheLimit|LanderSimilitude\.FullScaleAtASixthOfTheGravityLandsAsTheModelWithDepthsAndTimesTimesSix|Diagnose\.EffectOutsideTheLibraryIsNotNamedConfidently|Diagnose\.WithoutTheTermTheFloorNamesNoLibraryEffect|RareEventStudy\.ImportanceReusesTheSubsetRunsLandings|install_package|debian_package)$|^Library/HiddenEffect\..*/(added_mass|sensor_offset|compaction_peak|depth_exponent|rate_damping)|^EveryShippedPad/ShippedPadFreeDrop\..*/(flat|c4)'
start=$SECONDS
ctest --output-on-failure --parallel "$jobs" --timeout 900 -E "$left_out"
echo "sanitized ctest: $((SECONDS - start)) s on $jobs jobs"
bash "$root/tools/slowest_tests.sh" "$build" 10

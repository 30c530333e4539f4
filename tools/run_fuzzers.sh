#!/usr/bin/env bash
# Runs every libFuzzer target for a bounded time (FUZZ_SECONDS, default 12) from its seed corpus
# in tests/fuzz/corpus/<name>/ (target fuzz_<name>), FUZZ_PARALLEL targets at a time (default:
# the number of cores). The targets are built with clang, ASan and UBSan in build-hard/ (the
# build tools/run_sanitized_tests.sh uses, tools/hardened_build.sh; configured here if it does not exist yet). Any crash,
# sanitizer report, timeout (10 s per input) or out-of-memory (2 GB) fails the script and leaves
# the input in build-hard/fuzz/crashes/; fix the parser and add the input to the parser's unit
# tests (tests/<module>/<unit>_test.cpp). New inputs libFuzzer found stay in
# build-hard/fuzz/work/<name>/ (the seed corpus itself is never modified).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${TOUCHDOWN_HARDENING_DIR:-$root/build-hard}
seconds=${FUZZ_SECONDS:-12}
parallel=${FUZZ_PARALLEL:-$(nproc)}
bash "$root/tools/hardened_build.sh" touchdown_fuzzers  # already built when run_sanitized_tests.sh ran first

targets=$(cd "$root/tests/fuzz/corpus" && ls)
out="$build/fuzz"
mkdir -p "$out/crashes" "$out/work" "$out/logs"
export TOUCHDOWN_DATA_DIR="$root/data"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:halt_on_error=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

fuzz_one() {
  local t=$1 work="$out/work/$1" log="$out/logs/$1.log"
  rm -rf "$work" && mkdir -p "$work"
  # Fuzz into a scratch copy; the seeds are read from the corpus directory as well.
  if "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$out/crashes/$t-" -print_final_stats=1 "$work" "$root/tests/fuzz/corpus/$t" >"$log" 2>&1; then
    echo "fuzz_$t: ok, $(grep -m1 -oE 'stat::number_of_executed_units: [0-9]+' "$log" | grep -oE '[0-9]+') runs in ${seconds}s"
  else
    echo "fuzz_$t: FAILED (crash, sanitizer report, timeout or out-of-memory): see $log and $out/crashes/" >&2
    grep -E "ERROR|SUMMARY|==[0-9]+==|Test unit written" "$log" | head -20 >&2 || true
    return 1
  fi
}

status=0
pids=()
names=()
for t in $targets; do
  [ -x "$build/tests/fuzz/fuzz_$t" ] || { echo "no fuzz target fuzz_$t for tests/fuzz/corpus/$t" >&2; status=1; continue; }
  fuzz_one "$t" &
  pids+=($!)
  names+=("$t")
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do sleep 1; done
done
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || status=1
done
exit $status

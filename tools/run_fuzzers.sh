#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (build-fuzz/) and runs each for a bounded time
# (FUZZ_SECONDS, default 30) from its seed corpus in tests/fuzz/corpus/<name>/. A crash leaves
# its input in build-fuzz/crashes/ and fails; add it to tests/fuzz/regressions/<name>/ so the
# normal test suite replays it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${FUZZ_SECONDS:-30}
bash "$root/tools/install_deps.sh"
CXX=clang++ CC=clang cmake -S "$root" -B "$root/build-fuzz" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTOUCHDOWN_FUZZ=ON -DTOUCHDOWN_BUILD_TESTS=OFF -DTOUCHDOWN_BUILD_BENCH=OFF >/dev/null
targets=$(cd "$root/tests/fuzz/corpus" && ls)
cmake --build "$root/build-fuzz" --parallel "$(nproc)" --target $(for t in $targets; do echo "fuzz_$t"; done)
mkdir -p "$root/build-fuzz/crashes" "$root/build-fuzz/work"
export TOUCHDOWN_DATA_DIR="$root/data"
status=0
for t in $targets; do
  work="$root/build-fuzz/work/$t"
  rm -rf "$work" && mkdir -p "$work" && cp "$root/tests/fuzz/corpus/$t/"* "$work/"
  echo "fuzzing $t for ${seconds}s"
  if ! "$root/build-fuzz/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$root/build-fuzz/crashes/$t-" -print_final_stats=1 "$work" >"$root/build-fuzz/$t.log" 2>&1; then
    echo "fuzz_$t found a crash: see build-fuzz/$t.log and build-fuzz/crashes/" >&2
    tail -40 "$root/build-fuzz/$t.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units" "$root/build-fuzz/$t.log" | sed "s/^/  $t: /" || true
  fi
done
exit $status

#!/usr/bin/env bash
# gapbench matrix runner: every generated set through `touchdown import` (raw sets) and
# `touchdown diagnose` (default options), two sets at a time. A set that fails is recorded, never
# aborts the matrix.
#
#   tools/gapbench/run_matrix.sh BUILD_DIR SETS_DIR OUT_DIR
#
# SETS_DIR: generate.py's OUT_DIR (holding sets/) or its sets/ folder. Per set S it writes
#   OUT_DIR/S/dataset/        (raw sets: `touchdown import SETS/S/import.yaml --out ...`)
#   OUT_DIR/S/diagnose/       (`touchdown diagnose <dataset> --out ...`)
#   OUT_DIR/S/{import,diagnose}.log, OUT_DIR/S/status.csv
# and OUT_DIR/matrix_status.csv (one row per set). Raw sets run first.
# Environment: GAPBENCH_JOBS (2), GAPBENCH_TIMEOUT seconds per command (3600), GAPBENCH_NICE (10),
# GAPBENCH_DIAGNOSE_ARGS (extra diagnose options; empty = the defaults, as the blind test needs).
set -u
if [ $# -ne 3 ]; then
  echo "usage: $0 BUILD_DIR SETS_DIR OUT_DIR" >&2
  exit 2
fi
BUILD_DIR=$(cd "$1" && pwd) || exit 2
SETS_DIR=$(cd "$2" && pwd) || exit 2
[ -d "$SETS_DIR/sets" ] && SETS_DIR="$SETS_DIR/sets"
mkdir -p "$3" || exit 2
OUT_DIR=$(cd "$3" && pwd)
TD="$BUILD_DIR/apps/touchdown"
if [ ! -x "$TD" ]; then
  echo "no executable $TD" >&2
  exit 2
fi
HERE=$(cd "$(dirname "$0")" && pwd)
# The repository's catalogue unless the caller names another.
export TOUCHDOWN_DATA_DIR=${TOUCHDOWN_DATA_DIR:-$(cd "$HERE/../.." && pwd)/data}
export TD OUT_DIR SETS_DIR
export GAPBENCH_TIMEOUT=${GAPBENCH_TIMEOUT:-3600}
export GAPBENCH_NICE=${GAPBENCH_NICE:-10}
export GAPBENCH_DIAGNOSE_ARGS=${GAPBENCH_DIAGNOSE_ARGS:-}
JOBS=${GAPBENCH_JOBS:-2}

run_one() {
  local set_dir=$1
  local name form o data rc_i rc_d status t0 t1
  name=$(basename "$set_dir")
  o="$OUT_DIR/$name"
  rm -rf "$o/dataset" "$o/diagnose" "$o/status.csv"
  mkdir -p "$o"
  t0=$(date +%s)
  rc_i=""
  if [ -f "$set_dir/import.yaml" ]; then
    form=raw
    nice -n "$GAPBENCH_NICE" timeout "$GAPBENCH_TIMEOUT" \
      "$TD" import "$set_dir/import.yaml" --out "$o/dataset" >"$o/import.log" 2>&1
    rc_i=$?
    data="$o/dataset"
  else
    form=dataset
    data="$set_dir/dataset"
  fi
  if [ -n "$rc_i" ] && [ "$rc_i" -ne 0 ]; then
    rc_d=""
    status=import_failed
  else
    # shellcheck disable=SC2086
    nice -n "$GAPBENCH_NICE" timeout "$GAPBENCH_TIMEOUT" \
      "$TD" diagnose "$data" --out "$o/diagnose" $GAPBENCH_DIAGNOSE_ARGS >"$o/diagnose.log" 2>&1
    rc_d=$?
    if [ "$rc_d" -eq 0 ] && [ -f "$o/diagnose/diagnosis.json" ]; then
      status=ok
    elif [ "$rc_d" -eq 124 ]; then
      status=diagnose_timeout
    else
      status=diagnose_failed
    fi
  fi
  t1=$(date +%s)
  printf 'set,form,import_rc,diagnose_rc,status,seconds\n%s,%s,%s,%s,%s,%s\n' \
    "$name" "$form" "$rc_i" "$rc_d" "$status" "$((t1 - t0))" >"$o/status.csv"
  echo "$name $form $status $((t1 - t0)) s"
  return 0
}
export -f run_one

{
  for s in "$SETS_DIR"/*/; do [ -f "$s/import.yaml" ] && echo "${s%/}"; done
  for s in "$SETS_DIR"/*/; do [ -f "$s/import.yaml" ] || { [ -d "$s/dataset" ] && echo "${s%/}"; }; done
} >"$OUT_DIR/matrix_queue.txt"
n=$(wc -l <"$OUT_DIR/matrix_queue.txt")
echo "gapbench: $n sets, $JOBS at a time, TOUCHDOWN_DATA_DIR=$TOUCHDOWN_DATA_DIR"
xargs -a "$OUT_DIR/matrix_queue.txt" -d '\n' -P "$JOBS" -I{} bash -c 'run_one "$1"' _ {} || true

{
  echo "set,form,import_rc,diagnose_rc,status,seconds"
  while read -r s; do
    f="$OUT_DIR/$(basename "$s")/status.csv"
    if [ -f "$f" ]; then tail -n 1 "$f"; else echo "$(basename "$s"),,,,not_run,"; fi
  done <"$OUT_DIR/matrix_queue.txt"
} >"$OUT_DIR/matrix_status.csv"
echo "gapbench: done; $(grep -c ',ok,' "$OUT_DIR/matrix_status.csv") of $n sets diagnosed; $OUT_DIR/matrix_status.csv"
exit 0

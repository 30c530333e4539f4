#!/usr/bin/env bash
# Golden comparison for refactors that must not change a result: runs one touchdown executable
# over a fixed set of jobs (the paper campaign, rig and free drops with an explicit --zeta, a
# sweep and its export, lander cases A/B/C, 24 landings of the lunar stability study, a diagnose
# and a calibrate) and writes every output
# under OUT. Run it with the executable before and after a change, then compare the two folders:
#
#   tools/golden_outputs.sh OLD/build/apps/touchdown /tmp/golden_old
#   tools/golden_outputs.sh build/apps/touchdown     /tmp/golden_new
#   tools/golden_outputs.sh --compare /tmp/golden_old /tmp/golden_new
#
# Every file is compared byte for byte, plots included, except the lines that report wall-clock
# time (diagnose's "seconds") and the sweep's lock file (a process id). OUT must not exist yet.
set -euo pipefail
if [[ $# -eq 3 && $1 == --compare ]]; then
  diff -r -x sweep.lock -I '"seconds":' -I 'simulated drops in .* s\.$' "$2" "$3"
  echo "bit-identical: $2 and $3"
  exit 0
fi
if [[ $# -ne 2 ]]; then
  echo "usage: $0 TOUCHDOWN_EXECUTABLE OUT | $0 --compare OUT_A OUT_B" >&2
  exit 2
fi
td=$(realpath "$1")
out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
export TOUCHDOWN_DATA_DIR="$root/data"
if [[ -e "$out" ]]; then
  echo "$out: exists; give a new folder" >&2
  exit 2
fi
mkdir -p "$out/drops"
cd "$out"

"$td" campaign "$root/data/scenarios/sutoh2017_single_footpad.yaml" --out campaign

# Rig drops and free 6-DOF drops; --zeta overrides the soil's scaling factor.
n=0
for args in "--pad flat --soil fjs1_lp --speed 1.0 --zeta 0.8" \
            "--pad curved --soil fjs1_cp --speed 1.5 --zeta 2.1 --gravity 1.62" \
            "--pad c4 --soil fjs1_lp --speed 0.7 --zeta 1.1 --mass 3.0" \
            "--pad flat --soil fjs1_lp --speed 1.0 --zeta 0.9 --free --tilt-deg 10 --tilt-axis x" \
            "--pad curved --soil fjs1_lp --speed 1.2 --zeta 1.0 --free --horizontal-speed 0.4 --law agarwal2023" \
            "--pad hex --soil fjs1_cp --speed 1.0 --zeta 1.5 --free --tilt-deg 5 --tilt-axis y --omega 0 0 2"; do
  n=$((n + 1))
  # shellcheck disable=SC2086  # the argument list is split on purpose
  "$td" drop $args --trace "drops/trace_$n.csv" > "drops/summary_$n.txt"
done

"$td" sweep "$root/data/sweeps/pad_trade.yaml" --out sweep --threads 2 --progress none > /dev/null
"$td" export sweep --to sweep_export > /dev/null
"$td" export sweep --to sweep_export_full --full-traces --threads 2 > /dev/null
# The database itself holds timestamps; its results are compared through the export.
rm -f sweep/results.sqlite*

for c in A B C; do
  "$td" lander "$root/data/scenarios/lander_case_$c.yaml" --out "lander_case_$c"
done

"$td" stability "$root/data/studies/lunar_paper_lander.yaml" --out stability --samples 24 --threads 2 \
  --progress none > /dev/null
# Timestamps, in the study's database and in those of its follow-ups (joint_range_x*/, recheck/);
# the landings are compared through the summary and tables.
find stability -name 'results.sqlite*' -delete

"$td" diagnose "$root/data/datasets/air_vs_vacuum_synthetic" --out diagnose --threads 2 > diagnose.txt
"$td" calibrate "$root/data/datasets/air_vs_vacuum_synthetic" --out calibrate_model.yaml > calibrate.txt
echo "golden outputs in $out"

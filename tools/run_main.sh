#!/usr/bin/env bash
# The main job on the bundled data: install, build (the `touchdown` executable and the Python
# module in build/python, what the README's quick start promises: tools/build.sh), and reproduce the
# paper's single-footpad drop campaign in vacuum. Results, traces and plots go to results/ (or the
# folder given).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-"$root/results"}
bash "$root/tools/build.sh"
td="$root/build/apps/touchdown"
mkdir -p "$out"
"$td" campaign "$root/data/scenarios/sutoh2017_single_footpad.yaml" --out "$out/single_footpad"
# The paper's four-legged lander, Table II cases A (LP LP LP LP), B (CP LP LP LP) and C
# (CP CP LP LP), in vacuum (each well under a second of CPU: docs/lander_dynamics.md, "Speed"):
# with the shipped soils (derived from the paper's data sheets), then with the soils fitted on the
# paper's single-pad findings (calibrate --targets: docs/calibration_targets.md, a second), for
# which the lander's roll and pitch are predictions. Case B keeps its ParaView series (vtk/, the
# one docs/paraview.md opens); the others leave theirs out (--no-vtk: 58-79 MB of text each).
# Each run's summary is its summary.json (written by touchdown; this script writes no file of its
# own), and the table below reads the angles from it.
"$td" calibrate --targets "$root/data/targets/sutoh2017.yaml" --out "$out/sutoh2017_fitted_soils.yaml" > /dev/null
for c in A B C; do
  vtk=--no-vtk
  [ "$c" = B ] && vtk=
  "$td" lander "$root/data/scenarios/lander_case_$c.yaml" --out "$out/lander_case_$c" $vtk > /dev/null
  "$td" lander "$root/data/scenarios/lander_case_$c.yaml" --model "$out/sutoh2017_fitted_soils.yaml" \
    --out "$out/lander_case_${c}_fitted_soils" --no-vtk > /dev/null
done
# A number of a summary.json written by touchdown (one "key": value per line).
# (Rounded to ${3:-2} decimals; a value that rounds to zero is shown as 0.00, not -0.00.)
number() {
  awk -v k="\"$2\":" -v n="${3:-2}" '$1 == k { gsub(",", "", $2); v = $2 + 0; if (v < 0.5 * 10 ^ -n && v > -0.5 * 10 ^ -n) v = 0
    printf "%." n "f", v; exit }' "$1"
}
band() { awk '$1 == "\"within_paper_band\":" { print ($2 ~ /true/) ? "within" : "outside"; exit }' "$1"; }
echo
echo "lander: final roll / pitch [deg]; the paper (Sutoh et al. 2017, Sec. IV-C) reads both within +-0.5 deg"
printf '%-6s %-14s %-28s %s\n' case ground "shipped soils" "soils fitted on the single-pad findings"
for c in A B C; do
  shipped="$out/lander_case_$c/summary.json" fitted="$out/lander_case_${c}_fitted_soils/summary.json"
  ground=$(awk '$1 == "\"paper_ground_case\":" { gsub(/[",]/, ""); $1 = ""; print substr($0, 2); exit }' "$shipped")
  printf '%-6s %-14s %-28s %s\n' "$c" "$ground" \
    "$(number "$shipped" final_roll_deg) / $(number "$shipped" final_pitch_deg)  $(band "$shipped")" \
    "$(number "$fitted" final_roll_deg) / $(number "$fitted" final_pitch_deg)  $(band "$fitted")"
done
# Model-gap workflow on the shipped SYNTHETIC air-vs-vacuum dataset (gas cushion hidden in the air drops).
"$td" diagnose "$root/data/datasets/air_vs_vacuum_synthetic" --out "$out/diagnose_air_vs_vacuum" > /dev/null
d="$out/diagnose_air_vs_vacuum/diagnosis.json"
# The held-out force NRMSE of diagnosis.json's gap_before or gap_after block.
nrmse() { awk -v s="\"$2\":" '$1 == s { inside = 1 } inside && $1 == "\"force_nrmse\":" { gsub(",", "", $2); printf "%.3f", $2; exit }' "$1"; }
echo
echo "diagnose (SYNTHETIC dataset, a gas cushion hidden in its air drops): named" \
  "$(awk '$1 == "\"named_effect\":" { gsub(/[",]/, "", $2); print $2; exit }' "$d"), held-out force NRMSE" \
  "$(nrmse "$d" gap_before) -> $(nrmse "$d" gap_after)"
echo
echo "main job done: every output is in $out/"

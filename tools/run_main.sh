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
# (CP CP LP LP), in vacuum (each well under a second of CPU: docs/lander_dynamics.md, "Speed").
for c in A B C; do
  "$td" lander "$root/data/scenarios/lander_case_$c.yaml" --out "$out/lander_case_$c"
done
# Model-gap workflow on the shipped SYNTHETIC air-vs-vacuum dataset (gas cushion hidden in the air drops).
"$td" diagnose "$root/data/datasets/air_vs_vacuum_synthetic" --out "$out/diagnose_air_vs_vacuum"
echo "main job done: see $out/"

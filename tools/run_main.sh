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
# Case B keeps its ParaView series (vtk/, the one docs/paraview.md opens); A and C leave theirs
# out (--no-vtk: 58 and 79 MB of text, about a second each to write).
"$td" lander "$root/data/scenarios/lander_case_A.yaml" --out "$out/lander_case_A" --no-vtk
"$td" lander "$root/data/scenarios/lander_case_B.yaml" --out "$out/lander_case_B"
"$td" lander "$root/data/scenarios/lander_case_C.yaml" --out "$out/lander_case_C" --no-vtk
# Model-gap workflow on the shipped SYNTHETIC air-vs-vacuum dataset (gas cushion hidden in the air drops).
"$td" diagnose "$root/data/datasets/air_vs_vacuum_synthetic" --out "$out/diagnose_air_vs_vacuum"
echo "main job done: see $out/"

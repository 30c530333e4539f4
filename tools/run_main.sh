#!/usr/bin/env bash
# The main job on the bundled data: install, build, and reproduce the paper's single-footpad
# drop campaign in vacuum. Results, traces and plots go to results/ (or the folder given).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-"$root/results"}
bash "$root/tools/build.sh"
td="$root/build/apps/touchdown"
mkdir -p "$out"
"$td" campaign "$root/data/scenarios/sutoh2017_single_footpad.yaml" --out "$out/single_footpad"
echo "main job done: see $out/"

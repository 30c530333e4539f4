#!/usr/bin/env bash
# Regenerates docs/figures/gallery/: one PNG of every figure touchdown draws, from the shipped
# examples at the size they are run (a campaign, the three lander cases, the shipped lunar
# stability study of 10,000 landings, the pad trade, a comparison, a diagnosis of the shipped 24
# drops and one of the same campaign with four trials of each condition, 96 drops, the validation
# set), shrunk to 800 pixels wide and to a 64-colour palette so the committed gallery stays under a
# few MB. docs/figures.md shows them. About 15 minutes on the project's 2-core machine, 7 of them
# the study's landings: its figures are drawn to read at that size, and are shown at it.
#
#   tools/make_figure_gallery.sh build/apps/touchdown
#
# The runs go to a temporary folder, removed at the end; only docs/figures/gallery/ is replaced.
set -euo pipefail
if [[ $# -ne 1 ]]; then
  echo "usage: $0 TOUCHDOWN_EXECUTABLE" >&2
  exit 2
fi
td=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
export TOUCHDOWN_DATA_DIR="$root/data"
gallery="$root/docs/figures/gallery"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$td" campaign "$root/data/scenarios/sutoh2017_single_footpad.yaml" --out campaign > /dev/null
for c in A B C; do
  "$td" lander "$root/data/scenarios/lander_case_$c.yaml" --out "lander_case_$c" > /dev/null
done
"$td" stability "$root/data/studies/lunar_paper_lander.yaml" --out stability --threads 2 --progress none > /dev/null
"$td" trade "$root/data/sweeps/pad_trade.yaml" --out trade > /dev/null
"$td" compare "$root/data/datasets/air_vs_vacuum_synthetic" --out compare > /dev/null
"$td" diagnose "$root/data/datasets/air_vs_vacuum_synthetic" --out diagnose --threads 2 > /dev/null
# The same campaign with four trials of each condition (96 drops): the diagnosis's figures as a
# replicated campaign draws them (conditions grouped, residuals as bands).
sed 's/^trials: 1$/trials: 4/' "$root/data/datasets/air_vs_vacuum_synthetic.synth.yaml" > replicated.synth.yaml
"$td" synth replicated.synth.yaml --out replicated_dataset > /dev/null
"$td" diagnose replicated_dataset --out diagnose_replicated --threads 2 > /dev/null
"$td" validate --out validation > /dev/null

# Every PNG a command drew, named <run>__<figure>.png; per-drop comparison plots: the first two.
staged="$work/gallery"
mkdir -p "$staged"
find . -path ./gallery -prune -o -name '*.png' -print | sort | while read -r png; do
  run=${png#./}
  run=${run%%/*}
  name=$(basename "$png" .png)
  case "$png" in
    */plots/drops/*) [[ $(find "$staged" -name "${run}__drop_*" | wc -l) -lt 2 ]] || continue; name="drop_$name" ;;
  esac
  cp "$png" "$staged/${run}__${name}.png"
done

# Shrink: Pillow when the system Python has it (Debian: python3-pil), else the PNGs as drawn.
if /usr/bin/python3 -c 'import PIL' 2> /dev/null; then
  /usr/bin/python3 - "$staged" << 'PY'
import pathlib, sys
from PIL import Image
for f in sorted(pathlib.Path(sys.argv[1]).glob("*.png")):
    im = Image.open(f).convert("RGB")
    w, h = im.size
    im = im.resize((800, round(h * 800 / w)), Image.LANCZOS)
    # Octree keeps a colour scale's hues (median cut turned the map's reds brown and merged the
    # pads' green and blue into one teal) and writes smaller files.
    im.quantize(colors=64, method=Image.Quantize.FASTOCTREE).save(f, optimize=True)
PY
fi
rm -rf "$gallery"
mkdir -p "$(dirname "$gallery")"
cp -r "$staged" "$gallery"
du -sh "$gallery"
ls "$gallery"

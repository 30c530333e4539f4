#!/usr/bin/env python3
"""Writes the example terrain raster `site.asc` (ESRI ASCII grid, docs/terrain.md): a 2.4 m x 2.4 m
patch at 4 cm (61 x 61 cell centres) in made-up map coordinates, tilted 3 deg down towards +x with a
degraded 0.8 m crater (d/D 0.1) under the lander's pad 1 side. Heights in metres, rows north to south.

  python3 examples/terrain/make_site.py [OUT.asc]     # default: site.asc beside this script

It never replaces a file that exists (delete it first)."""
import math
import os
import sys

N, CELL = 61, 0.04
X_LL, Y_LL = 350000.0, 4100000.0      # lower-left corner, map metres (made up)
BASE_M = -1742.0                      # a site elevation: touchdown shifts it to the scenario's height_m
TILT = math.tan(math.radians(3.0))
CRATER_X, CRATER_Y, CRATER_D = 1.50, 1.20, 0.8  # from the lower-left corner [m]


def height(x, y):
    z = BASE_M - TILT * x
    r = math.hypot(x - CRATER_X, y - CRATER_Y) / (0.5 * CRATER_D)
    depth, rim = 0.1 * CRATER_D, 0.018 * CRATER_D  # degraded: half of Pike's fresh 0.196 and 0.036
    z += rim - depth * (1.0 - r * r) if r <= 1.0 else rim * r ** -3.0
    return z


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "site.asc")
    if os.path.exists(out):
        sys.exit(f"{out}: exists; not replaced (delete it first)")
    lines = [f"ncols {N}", f"nrows {N}", f"xllcorner {X_LL}", f"yllcorner {Y_LL}", f"cellsize {CELL}",
             "NODATA_value -9999"]
    for row in range(N):  # north first
        y = (N - 1 - row + 0.5) * CELL
        lines.append(" ".join(f"{height((c + 0.5) * CELL, y):.4f}" for c in range(N)))
    with open(out, "x") as f:
        f.write("\n".join(lines) + "\n")
    print(out)


if __name__ == "__main__":
    main()

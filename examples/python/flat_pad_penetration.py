#!/usr/bin/env python3
"""Penetration against time of the paper's flat pad on loosely (LP) and closely (CP) packed FJS-1 at
its three impact speeds (Sutoh et al. 2017, vacuum drops; the simulated counterpart of its Fig. 3).

    PYTHONPATH=build/python python3 examples/python/flat_pad_penetration.py --out figures

writes figures/flat_pad_penetration.png and .svg (new files: an existing one is never replaced)
and prints each drop's final penetration. Runs headless (matplotlib's Agg backend).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import touchdown  # noqa: E402

SOILS = {"fjs1_lp": ("FJS-1 LP", "tab:blue"), "fjs1_cp": ("FJS-1 CP", "tab:orange")}
SPEEDS_M_S = {0.7: ":", 1.0: "-", 1.5: "--"}  # the paper's impact speeds


def simulate():
    """{(soil, speed): (summary, trace)} for the flat pad, from touchdown.drop."""
    return {(soil, speed): touchdown.drop(pad="flat", soil=soil, speed=speed, trace=True)
            for soil in SOILS for speed in SPEEDS_M_S}


def plot(drops):
    fig, ax = plt.subplots(figsize=(7.2, 4.0), dpi=150, layout="constrained")
    end_ms = 0.0
    for (soil, speed), (summary, trace) in drops.items():
        label, colour = SOILS[soil]
        ax.plot(trace["t_s"] * 1e3, trace["penetration_m"] * 1e3, color=colour, linestyle=SPEEDS_M_S[speed],
                label=f"{label}, {speed:.1f} m/s")
        end_ms = max(end_ms, summary["time_to_rest_s"] * 1e3)
    ax.set_xlim(0.0, 1.2 * end_ms)  # touchdown to rest, not the quiet tail
    ax.set_ylim(bottom=0.0)
    ax.invert_yaxis()  # penetration downward, as the pad moves
    ax.set_xlabel("time since touchdown [ms]")
    ax.set_ylabel("penetration [mm]")
    ax.set_title("Flat pad, 1.6 kg, vacuum: simulated (granular RFT)")
    ax.grid(True, alpha=0.3)
    ax.legend(title="soil, impact speed", fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0))  # off the curves
    return fig


def save_new(fig, path):
    """Writes a new file only (mode 'x'): a user's file of that name is left as it is."""
    with open(path, "xb") as f:
        fig.savefig(f, format=os.path.splitext(path)[1][1:])


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="directory for the figure (created if missing)")
    args = parser.parse_args(argv)
    paths = [os.path.join(args.out, "flat_pad_penetration." + ext) for ext in ("png", "svg")]
    for path in paths:  # before simulating: say at once that a file is in the way
        if os.path.lexists(path):
            print(f"{path}: exists; not replaced (give another --out)", file=sys.stderr)
            return 2
    drops = simulate()
    for (soil, speed), (summary, _) in drops.items():
        print(f"{soil} {speed:.1f} m/s: final penetration {summary['final_penetration_m'] * 1e3:.2f} mm")
    os.makedirs(args.out, exist_ok=True)
    fig = plot(drops)
    for path in paths:
        try:
            save_new(fig, path)
        except FileExistsError:  # appeared meanwhile
            print(f"{path}: exists; not replaced (give another --out)", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

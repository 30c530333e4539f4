#!/usr/bin/python3
"""A drop dataset (drops.csv + traces/) from Katsuragi & Durian's measured force law, for `touchdown
diagnose` (docs/model_gap.md, "The workflow on a measured law"): the 1-inch steel sphere into glass
beads at the drop heights of the paper's trajectory figure, each drop's penetration and the force
the medium exerts on the sphere, F = m v^2 / d1 + k z while it moves (the law as the paper reports
it, data/validation/katsuragi_durian_2007.yaml), then m g at rest.

What it is and is not: the paper's fitted law, integrated, not its raw trajectories (not available
as text); so a "gap" diagnose finds is between RFT and that law. Sensor noise is an ASSUMPTION
(the law has none): Gaussian, 1 % of the weight on the force and 1 um on the penetration, fixed
seed, so the noise floor diagnose reads at rest is defined.

    tools/kd_law_dataset.py OUT_DIR
"""
import csv
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

G = 9.81
MASS_KG = 0.0692          # the sphere (data/validation/pads/kd2007_steel_sphere.yaml)
D1_M = 0.087              # inertial drag length, quoted (katsuragi_durian_2007.yaml)
K_OVER_M = 1040.0         # friction k/m [s^-2], quoted
HEIGHTS_MM = [830, 500, 300, 150, 70, 38, 22, 16, 11, 5.2, 2.8, 1.8]  # the figure's legend (h = 0 left out: no impact)
RATE_HZ = 10000.0         # samples a second: the stops take 20-60 ms
REST_S = 0.01             # samples at rest after the stop, for the noise floor
FORCE_SIGMA_N = 0.01 * MASS_KG * G
PEN_SIGMA_M = 1e-6
SEED = 2007
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


def trajectory(v0):
    """Depth z(t) and speed v(t) (both down) until v = 0, by the law m dv/dt = m g - m v^2/d1 - k z."""
    def rhs(_t, y):
        z, v = y
        return [v, G - v * v / D1_M - K_OVER_M * z]

    def stopped(_t, y):
        return y[1]
    stopped.terminal = True
    stopped.direction = -1
    # From rest (v0 = 0) the first step moves it: start at a tiny speed in that case.
    sol = solve_ivp(rhs, (0.0, 1.0), [0.0, max(v0, 1e-9)], events=stopped, rtol=1e-11, atol=1e-13,
                    dense_output=True, max_step=1e-4)
    return sol.sol, sol.t_events[0][0]


def main(out):
    os.makedirs(os.path.join(out, "traces"), exist_ok=False)
    rng = np.random.default_rng(SEED)
    rows = []
    for h_mm in HEIGHTS_MM:
        v0 = math.sqrt(2 * G * h_mm / 1000.0)
        sol, t_stop = trajectory(v0)
        n = int(math.floor((t_stop + REST_S) * RATE_HZ)) + 1
        t = np.arange(n) / RATE_HZ
        z = np.empty(n)
        f = np.empty(n)
        for i, ti in enumerate(t):
            if ti < t_stop:
                zi, vi = sol(ti)
                f[i] = MASS_KG * (vi * vi / D1_M + K_OVER_M * zi)
            else:
                zi = sol(t_stop)[0]
                f[i] = MASS_KG * G  # at rest the medium holds the weight
            z[i] = zi
        z += rng.normal(0.0, PEN_SIGMA_M, n)
        f += rng.normal(0.0, FORCE_SIGMA_N, n)
        drop_id = "kd_h%g" % h_mm
        trace = "traces/%s.csv" % drop_id
        with open(os.path.join(out, trace), "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["t_s", "penetration_m", "force_N"])
            for ti, zi, fi in zip(t, z, f):
                w.writerow(["%.6g" % ti, "%.6g" % zi, "%.6g" % fi])
        rows.append([drop_id, os.path.relpath(os.path.join(DATA, "validation/pads/kd2007_steel_sphere.yaml"), out),
                     os.path.relpath(os.path.join(DATA, "validation/soils/kd2007_glass_beads.yaml"), out), "air", "%.6g" % v0, MASS_KG, G, trace, 0, "published_fitted_law"])
    with open(os.path.join(out, "drops.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["drop_id", "pad", "soil", "atmosphere", "impact_speed_m_s", "pad_mass_kg", "gravity_m_s2", "trace",
                    "trial", "data_origin"])
        w.writerows(rows)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])

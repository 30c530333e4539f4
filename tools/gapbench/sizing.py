#!/usr/bin/python3
"""Size the hidden effects: the force gap a base model (quasi-static RFT + the soil's dynamic term,
lambda 1.1, zeta refitted per soil) leaves on CLEAN traces of a hidden effect or control.

Used to choose the out-of-library controls' sizes (a held-out force gap of several per cent) and to
compare them with the library effects at 1x/3x/10x. Our own approximation of the workflow's gap
metric: per drop sqrt(mean (F_base - F_true)^2) / max F_true over samples at 2 kHz from touchdown to
20 ms after the later stop, averaged over drops; zeta fitted by least squares on all drops.

  /usr/bin/python3 sizing.py [--quick]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _deps  # noqa: F401,E402

import numpy as np  # noqa: E402
from scipy.optimize import minimize_scalar  # noqa: E402

import physics as ph  # noqa: E402


def force_trace(res, t):
    d, v = ph.state_at(res, np.minimum(t, res.t_stop))
    F, _ = ph.loadcell_force(res, d, v)
    return np.where(t < res.t_stop, F, res.m * res.g)


def gap_for(hidden, pads=("flat", "c4", "curved"), speeds=(0.8, 1.2, 1.6), soil="fjs1_lp", zeta=3.5,
            atmospheres=("vacuum",), m=1.6, g=9.81, fs=2000.0):
    spec = ph.load_soil(soil)
    rho, lam = spec["bulk_density_kg_m3"], spec["dynamic_lambda"]
    truths = []
    tabs = {}

    def run(prof, z, hid, atm, v0, key):
        r = ph.SoilResponse(prof, z, rho, lam, hid, atm)
        if key not in tabs:
            tabs[key] = ph.ResponseTable(r)
        return ph.simulate_drop(r.use_table(tabs[key]), m, g, v0)

    for pad in pads:
        prof, _ = ph.load_pad(pad)
        for atm in atmospheres:
            for v0 in speeds:
                sim_h = None if hidden.get("id") in ("none", "sensor_offset") else hidden
                truths.append((prof, atm, v0, run(prof, zeta, sim_h, atm, v0, ("t", pad, atm))))
    tmax = max(r.t_stop for *_, r in truths) + 0.02
    t = np.arange(0, tmax, 1 / fs)
    Ftrue = [force_trace(r, t) for *_, r in truths]
    if hidden.get("id") == "sensor_offset":
        dt = hidden["dt_ms"] * 1e-3
        Ftrue = [np.interp(t + dt, t, F, left=0.0) for F in Ftrue]

    def cost(z, ret=False):
        out = []
        for (prof, atm, v0, _), Ft in zip(truths, Ftrue):
            rb = run(prof, z, None, atm, v0, ("b", prof.name, atm))
            out.append(np.sqrt(np.mean((force_trace(rb, t) - Ft) ** 2)) / Ft.max())
        return out if ret else float(np.sum(np.square(out)))

    best = minimize_scalar(cost, bounds=(zeta * 0.5, zeta * 2.0), method="bounded", options={"xatol": 1e-3})
    per = cost(best.x, ret=True)
    return float(np.mean(per)), float(best.x), [r.d_stop for *_, r in truths]


def main():
    quick = "--quick" in sys.argv
    cases = [("none", {"id": "none"})]
    lib = {
        "inertial_drag": lambda s: {"id": "inertial_drag", "lambda": 1.1 + 0.147 * s},
        "rate_damping": lambda s: {"id": "rate_damping", "c_N_s_m3": 450.0 * s},
        "added_mass": lambda s: {"id": "added_mass", "c_a": 0.15 * s},
        "added_mass_plug": lambda s: {"id": "added_mass_plug", "c_p": 0.05 * s},
        "compaction_peak": lambda s: {"id": "compaction_peak", "k_c_kg_m3": 900.0 * s, "d_c_mm": 3.0},
        "depth_exponent": lambda s: {"id": "depth_exponent", "p": 1 + 0.03 * s},
        "sensor_offset": lambda s: {"id": "sensor_offset", "dz_mm": 0.03 * s, "dt_ms": 0.09 * s},
    }
    for k, f in lib.items():
        for s in ((3,) if quick else (1, 3, 10)):
            cases.append(("%s x%d" % (k, s), f(s)))
    # the controls at the ends of generate.py's ranges (draw_control); the floor's clearance and the
    # layer's depth are set from the base strokes of this design, as the generator does
    base = gap_for({"id": "none"})[2]
    deepest, median = 1e3 * max(base), 1e3 * float(np.median(base))
    import generate
    n_f = generate.soil_n_f()
    for gap0 in (12.0, 30.0):
        cases.append(("floor, clearance %g mm" % gap0, {"id": "floor", "bed_depth_mm": deepest + gap0, "c_f": 0.05,
                                                      "length_mm": 50.0, "n": 3.0}))
    for D, f1 in ((0.05, 0.3), (0.05, 0.6), (0.08, 0.3), (0.08, 0.6)):
        cases.append(("density layered D %.2f z1 %.1f x median" % (D, f1),
                      {"id": "density", "variant": "layered", "n_f": n_f, "D": D, "z1_mm": f1 * median,
                       "width_mm": 2.0}))
    for L in (150, 300):
        cases.append(("density self_weight L %d mm" % L, {"id": "density", "variant": "self_weight",
                                                          "n_f": n_f, "L_mm": L}))
    for q in (0.5, 1.5):
        for c in (3000, 6000):
            cases.append(("rate_exponent q %.1f c %d" % (q, c), {"id": "rate_exponent", "q": q, "c_q": c}))
    for name, h in cases:
        g, z, ds = gap_for(h)
        print("%-36s gap %.4f  zeta_fit %.3f  strokes_mm %s" % (name, g, z,
                                                                 " ".join("%.1f" % (1e3 * x) for x in ds)),
              flush=True)


if __name__ == "__main__":
    main()

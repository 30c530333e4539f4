#!/usr/bin/python3
"""gapbench: an independent generator of hidden-effect drop-test sets for `touchdown diagnose`.

  /usr/bin/python3 tools/gapbench/generate.py OUT_DIR [--seed N] [--sets N] [--only PATTERN]

Writes OUT_DIR/sets/<set>/ with either dataset/ (touchdown's dataset format) or raw/ + import.yaml
(DAQ files for `touchdown import`), and truth.yaml beside them; OUT_DIR/manifest.csv lists every set
with its hidden effect and realism draws. Deterministic from the seed: set i is drawn from its own
random stream (seed, i), so a subset (--sets, --only) is identical to the same sets of a full run.
See README.md in this folder.
"""
import argparse
import csv
import fnmatch
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _deps  # noqa: F401,E402

import numpy as np  # noqa: E402
import yaml  # noqa: E402

import physics as ph  # noqa: E402
import sensors as sn  # noqa: E402

G = 9.81
PADS = ["flat", "c4", "curved"]
SOIL_NOMINAL_ZETA = {"fjs1_lp": 3.5, "fjs1_cp": 9.0}      # the brief's centres (N/cm^3)
SOIL_SHORT = {"fjs1_lp": "lp", "fjs1_cp": "cp"}

# docs/model_gap.md, "Power": the smallest size named on clean data (departure from neutral).
SMALLEST = {
    "inertial_drag": {"lambda": 1.247 - 1.1},
    "rate_damping": {"c_N_s_m3": 450.0},
    "added_mass": {"c_a": 0.15},
    "added_mass_plug": {"c_p": 0.05},
    "compaction_peak": {"k_c_kg_m3": 900.0},
    "depth_exponent": {"p": 0.03},
    "gas_cushion": {"chi": 0.009, "c_g_N_s_m3": 240.0},
    "sensor_offset": {"dz_mm": 0.03, "dt_ms": 0.09},
}
NEUTRAL = {"lambda": 1.1, "p": 1.0}
FIXED = {"compaction_peak": {"d_c_mm": 3.0}}              # the Power table's d_c, not scaled
LIBRARY = list(SMALLEST)
CONTROLS = ["none", "floor", "density", "rate_exponent"]
SETS_PER_SIZE = {1: 6, 3: 7, 10: 6}
SETS_PER_CONTROL = 13
N_CFC = 5                                                  # raw sets that ask for a CFC force filter


def library_params(effect, size):
    out = {}
    for k, dep in SMALLEST[effect].items():
        out[k] = round(NEUTRAL.get(k, 0.0) + size * dep, 10)
    out.update(FIXED.get(effect, {}))
    return out


# ---------------------------------------------------------------------------------------------
# The plan: which sets exist, in which form. Deterministic from the seed.

def make_plan(seed):
    rng = np.random.default_rng([seed, 0xC0FFEE])
    groups = []
    for eff in LIBRARY:
        for size, n in SETS_PER_SIZE.items():
            groups.append(("library", eff, size, n))
    for c in CONTROLS:
        groups.append(("control", c, None, SETS_PER_CONTROL))
    plan = []
    for kind, eff, size, n in groups:
        if eff == "sensor_offset":
            n_raw = 0       # the offset is defined on the recorded dataset (see README)
        else:
            n_raw = int(round(0.37 * n))    # about a third of all sets (sensor_offset sets have none)
        forms = ["raw"] * n_raw + ["dataset"] * (n - n_raw)
        rng.shuffle(forms)
        for j, form in enumerate(forms):
            plan.append({"kind": kind, "hidden": eff, "size": size, "form": form, "replica": j})
    raw_idx = [i for i, p in enumerate(plan) if p["form"] == "raw"]
    chan = ["acceleration"] * int(round(len(raw_idx) / 3))
    chan += ["displacement"] * (len(raw_idx) - len(chan))
    rng.shuffle(chan)
    for i, c in zip(raw_idx, chan):
        plan[i]["raw_channel"] = c
    for i in rng.choice(raw_idx, size=N_CFC, replace=False):
        plan[int(i)]["cfc"] = True
    order = rng.permutation(len(plan))
    plan = [plan[int(i)] for i in order]
    for k, p in enumerate(plan):
        p["index"] = k
        p["name"] = "gb%03d" % (k + 1)
        p["label"] = (p["hidden"] + "_x%d" % p["size"]) if p["kind"] == "library" else "control_" + p["hidden"]
    return plan


# ---------------------------------------------------------------------------------------------
# Realism and design draws for one set.

def log_uniform(rng, lo, hi):
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def draw_design(rng, need_air):
    for _ in range(1000):
        n_pads = 2 if rng.random() < 0.5 else 3
        pads = sorted(rng.choice(PADS, size=n_pads, replace=False).tolist(), key=PADS.index)
        cp = rng.random() < 0.4
        cp_pads = []
        if cp:
            cp_pads = ["flat"] if rng.random() < 0.5 else list(pads)
        both = need_air or rng.random() < 0.5
        atms = ["vacuum", "air"] if both else ["vacuum"]
        n_cond = (len(pads) + len(cp_pads)) * len(atms) * 3
        reps = [r for r in range(2, 7) if 12 <= n_cond * r <= 36]
        if reps:
            R = int(rng.choice(reps))
            return {"pads_lp": pads, "pads_cp": cp_pads, "atmospheres": atms, "replicates": R}
    raise RuntimeError("no feasible design")


def draw_speeds(rng):
    lo = round(rng.uniform(0.6, 0.9), 2)
    hi = round(rng.uniform(1.3, 1.8), 2)
    mid = round(0.5 * (lo + hi) + rng.uniform(-0.08, 0.08), 2)
    return [lo, mid, hi]


def draw_realism(rng, spec):
    raw = spec["form"] == "raw"
    cfc = spec.get("cfc", False)
    r = {}
    r["sample_rate_hz"] = 10000 if cfc else int(rng.choice([1000, 2000, 5000, 10000]))
    r["sampling_kind"] = str(rng.choice(["instantaneous", "period_mean", "antialias"]))
    if r["sampling_kind"] == "antialias":
        r["antialias"] = {"type": "butterworth", "order": int(rng.integers(2, 9)),
                          "cutoff_fraction_of_fs": float(rng.uniform(0.2, 0.45))}
        r["antialias"]["cutoff_hz"] = r["antialias"]["cutoff_fraction_of_fs"] * r["sample_rate_hz"]
    lc = cfc or rng.random() < 0.5
    if lc:
        if cfc:
            r["load_cell"] = {"natural_frequency_hz": float(rng.uniform(800, 2000)),
                              "damping_ratio": float(rng.uniform(0.02, 0.1))}
        else:
            r["load_cell"] = {"natural_frequency_hz": log_uniform(rng, 200, 2000),
                              "damping_ratio": float(rng.uniform(0.02, 0.3))}
    else:
        r["load_cell"] = None
    r["zeta_scatter_sd"] = float(rng.uniform(0.0, 0.05))
    r["speed_scatter_sd"] = float(rng.uniform(0.0, 0.02))
    r["force_noise_sd_N"] = log_uniform(rng, 0.2, 2.0)
    r["penetration_noise_sd_m"] = log_uniform(rng, 1e-6, 30e-6)
    r["force_drift_sd_N_s"] = float(rng.uniform(0.5, 5.0))
    r["penetration_drift_sd_m_s"] = float(rng.uniform(0.005e-3, 0.1e-3))
    r["adc_bits"] = int(rng.integers(12, 17))
    r["detector"] = None if raw else str(rng.choice(["onset_fit", "interp_back", "first_above", "last_below"],
                                                    p=[0.8, 0.1, 0.05, 0.05]))
    if raw:
        r["pretrigger_s"] = float(rng.uniform(0.010, 0.050))
    else:
        r["pretrigger_s"] = float(rng.uniform(0.005, 0.030)) if rng.random() < 0.5 else 0.0
    r["rest_s"] = float(rng.uniform(0.020, 0.100))
    r["pad_mass_kg"] = 1.6 if rng.random() < 0.8 else float(rng.choice([1.2, 2.0, 2.4]))
    return r


def draw_control(rng, control, ctx):
    """Out-of-library controls (README): sizes chosen with sizing.py for a gap of several per cent."""
    if control == "none":
        return {"id": "none"}
    if control == "floor":
        gap0 = float(rng.uniform(12.0, 30.0))
        return {"id": "floor", "bed_depth_mm": round(ctx["deepest_mm"] + gap0, 3), "c_f": 0.05,
                "length_mm": 50.0, "n": 3.0, "clearance_below_deepest_base_stop_mm": gap0}
    if control == "density":
        if rng.random() < 0.5:
            return {"id": "density", "variant": "layered", "n_f": ctx["n_f"],
                    "D": float(rng.uniform(0.05, 0.08)),
                    "z1_mm": float(rng.uniform(0.3, 0.6) * ctx["median_mm"]),
                    "width_mm": float(rng.uniform(1.5, 3.0))}
        return {"id": "density", "variant": "self_weight", "n_f": ctx["n_f"],
                "L_mm": float(rng.uniform(150.0, 300.0))}
    if control == "rate_exponent":
        q = float(rng.choice([0.5, 1.5]))
        return {"id": "rate_exponent", "q": q, "c_q": float(rng.uniform(3000.0, 6000.0))}
    raise ValueError(control)


def draw_raw_format(rng, spec, real):
    f = {}
    f["channel"] = spec["raw_channel"]
    f["units"] = str(rng.choice(["volts", "counts"]))
    f["delimiter"] = str(rng.choice([",", ";", "\t"]))
    f["time"] = str(rng.choice(["s", "ms", "us", "none"]))
    f["time_origin_s"] = float(rng.uniform(0.5, 120.0))
    names = [("time", "Fz", "disp", "acc"), ("t", "force", "lvdt", "accel"), ("Time", "LoadCell", "Position", "Accel_z"),
             ("timestamp", "ch1", "ch2", "ch3")]
    nm = names[int(rng.integers(len(names)))]
    f["columns"] = {"time": nm[0], "force": nm[1], "displacement": nm[2], "acceleration": nm[3]}
    f["force_bias_N"] = float(rng.choice([-1, 1]) * rng.uniform(1.0, 15.0))
    if f["units"] == "volts":
        f["force_offset_raw"] = round(float(rng.uniform(-0.02, 0.02)), 5)
    else:
        f["force_offset_raw"] = 0 if rng.random() < 0.5 else 2 ** (real["adc_bits"] - 1)
    if f["channel"] == "displacement":
        f["displacement_sign"] = -1 if rng.random() < 0.35 else 1          # -1: the sensor reads up
        f["surface_zeroed"] = bool(rng.random() < 0.5)
        f["sensor_zero_below_surface_m"] = 0.0 if f["surface_zeroed"] else float(rng.uniform(-0.03, 0.03))
        if f["units"] == "volts":
            f["displacement_offset_raw"] = round(float(rng.uniform(-0.01, 0.01)), 5)
        else:
            f["displacement_offset_raw"] = 0 if rng.random() < 0.5 else 2 ** (real["adc_bits"] - 1)
    else:
        f["accel_bias_m_s2"] = float(rng.uniform(-0.2, 0.2))
        f["accel_noise_sd_m_s2"] = log_uniform(rng, 0.05, 0.5)
        if f["units"] == "volts":
            f["acceleration_offset_raw"] = round(float(rng.uniform(-0.01, 0.01)), 5)
        else:
            f["acceleration_offset_raw"] = 0 if rng.random() < 0.5 else 2 ** (real["adc_bits"] - 1)
    if spec.get("cfc"):
        fn = real["load_cell"]["natural_frequency_hz"]
        f["force_filter"] = "cfc600" if fn > 1700 else "cfc180"
    else:
        f["force_filter"] = "none"
    return f


# ---------------------------------------------------------------------------------------------
# One drop: simulate, build the continuous channels, sample.

def build_channels(res, real, want_accel):
    """Continuous force, displacement (and acceleration) channels of a simulated drop."""
    m, g, v0 = res.m, res.g, res.v0
    fs = real["sample_rate_hz"]
    T = 1.0 / fs
    aa = []
    if real["sampling_kind"] == "antialias":
        aa = sn.butterworth_sections(real["antialias"]["order"], real["antialias"]["cutoff_hz"])
    lc = []
    if real["load_cell"]:
        lc = sn.loadcell_sections(real["load_cell"]["natural_frequency_hz"], real["load_cell"]["damping_ratio"])
    n_s = max(int(math.ceil(res.t_stop / sn.fine_dt(aa + lc))), 200)
    dt = res.t_stop / n_s
    ts = np.arange(n_s + 1) * dt
    ts[-1] = res.t_stop
    d, v = ph.state_at(res, ts)
    v[-1] = 0.0
    F, acc = ph.loadcell_force(res, d, v)
    t_end = res.t_stop + real["rest_s"] + 4 * T
    n_rest = int(math.ceil((t_end - res.t_stop) / dt)) + 2
    t_rest = res.t_stop + dt * np.arange(1, n_rest + 1)

    ch = {}
    # force: 0 before touchdown, m (g - dv/dt) in the stroke, m g at rest
    fsec = lc + aa
    if fsec:
        y = np.concatenate([F, np.full(n_rest, m * g)])
        y[0] = 0.5 * F[0]                         # the touchdown jump centred on t = 0
        y[n_s] = 0.5 * (F[-1] + m * g)            # the stop's jump centred on t_stop
        ch["force"] = sn.Channel(dt, sn.apply_filter(fsec, y, dt))
    else:
        ch["force"] = sn.Channel(dt, F, t_stop=res.t_stop, rest=m * g)
    # displacement: free-fall parabola before touchdown, d(t) in the stroke, d_stop at rest
    p = [0.0, v0, 0.5 * g]
    if aa:
        pv = lambda t: v0 * t + 0.5 * g * t * t  # noqa: E731
        q = np.concatenate([d - pv(ts), res.d_stop - pv(t_rest)])
        ch["displacement"] = sn.Channel(dt, sn.apply_filter(aa, q, dt), poly_all=sn.filtered_poly(p, aa))
    else:
        ch["displacement"] = sn.Channel(dt, d, poly_pre=p, t_stop=res.t_stop, rest=res.d_stop)
    if want_accel:
        if aa:
            y = np.concatenate([acc - g, np.full(n_rest, -g)])
            y[0] = 0.5 * (acc[0] - g)
            y[n_s] = 0.5 * (acc[-1] - g - g)
            ch["acceleration"] = sn.Channel(dt, sn.apply_filter(aa, y, dt), poly_all=sn.filtered_poly([g], aa))
        else:
            ch["acceleration"] = sn.Channel(dt, acc, poly_pre=[g], t_stop=res.t_stop, rest=0.0)
    peak = float(np.max(ch["force"].y))
    return ch, peak


def sample_channels(ch, real, t):
    kind = "period_mean" if real["sampling_kind"] == "period_mean" else "instantaneous"
    T = 1.0 / real["sample_rate_hz"]
    return {k: c.sample(t, kind, T) for k, c in ch.items()}


def choose_fs(need, options):
    for o in options:
        if o >= need:
            return o
    return options[-1]


# ---------------------------------------------------------------------------------------------

def fmt(x):
    return repr(float(x) + 0.0)          # + 0.0: no "-0.0"


def write_csv_rows(path, header, cols, delimiter=",", pre_lines=(), formatters=None):
    n = len(cols[0])
    formatters = formatters or [fmt] * len(cols)
    with open(path, "w", newline="") as f:
        for line in pre_lines:
            f.write(line + "\n")
        f.write(delimiter.join(header) + "\n")
        cols_s = [[fm(x) for x in c] for fm, c in zip(formatters, cols)]
        for i in range(n):
            f.write(delimiter.join(c[i] for c in cols_s) + "\n")


def to_builtin(x):
    if isinstance(x, dict):
        return {str(k): to_builtin(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [to_builtin(v) for v in x]
    if isinstance(x, (np.floating,)):
        return float(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    return x


def soil_n_f():
    """Exponent of the friction factor f(mu) against density from the catalogue's LP/CP pair."""
    lp, cp = ph.load_soil("fjs1_lp"), ph.load_soil("fjs1_cp")
    z_ratio = ph.agarwal_zeta(cp) / ph.agarwal_zeta(lp)
    r_ratio = cp["bulk_density_kg_m3"] / lp["bulk_density_kg_m3"]
    return math.log(z_ratio / r_ratio) / math.log(r_ratio)


def make_clean(real, spec):
    """--clean: the same set without the rig's realism (a check of the generator against the workflow):
    period-mean samples, no load cell, no scatter, 0.05 N / 0.1 um noise, no drift, 24 bits, t = 0 at the
    true touchdown, dataset form."""
    real.update({"sampling_kind": "period_mean", "load_cell": None, "zeta_scatter_sd": 0.0,
                 "speed_scatter_sd": 0.0, "force_noise_sd_N": 0.05, "penetration_noise_sd_m": 1e-7,
                 "force_drift_sd_N_s": 0.0, "penetration_drift_sd_m_s": 0.0, "adc_bits": 24, "detector": "truth",
                 "clean": True})
    real.pop("antialias", None)
    if spec["form"] == "raw":
        real["pretrigger_s"] = 0.0
    spec["form"] = "dataset"


def generate_set(spec, out_root, seed, soils, pads_cache, clean=False):
    rng = np.random.default_rng([seed, 1000 + spec["index"]])
    spec = dict(spec)
    name = spec["name"]
    set_dir = os.path.join(out_root, "sets", name)
    if os.path.exists(set_dir):
        import shutil
        shutil.rmtree(set_dir)
    os.makedirs(set_dir)
    real = draw_realism(rng, spec)
    if clean:
        make_clean(real, spec)
    is_raw = spec["form"] == "raw"
    hidden_id = spec["hidden"]
    design = draw_design(rng, need_air=(hidden_id == "gas_cushion"))
    speeds = draw_speeds(rng)
    zeta_true = {"fjs1_lp": SOIL_NOMINAL_ZETA["fjs1_lp"] * float(rng.uniform(0.7, 1.3))}
    if design["pads_cp"]:
        zeta_true["fjs1_cp"] = SOIL_NOMINAL_ZETA["fjs1_cp"] * float(rng.uniform(0.7, 1.3))
    m = real["pad_mass_kg"]

    # base strokes (no hidden effect) of this set's design, to place the controls' depths
    ctx = {"n_f": soil_n_f()}
    if spec["kind"] == "control" and hidden_id in ("floor", "density"):
        base_d = []
        for pad in design["pads_lp"]:
            for v in speeds:
                r0 = ph.simulate_drop(ph.SoilResponse(pads_cache[pad], zeta_true["fjs1_lp"],
                                                      soils["fjs1_lp"]["rho"], soils["fjs1_lp"]["lam"]),
                                      m, G, v, rtol=1e-8)
                base_d.append(r0.d_stop)
        ctx["deepest_mm"] = 1e3 * max(base_d)
        ctx["median_mm"] = 1e3 * float(np.median(base_d))
    if spec["kind"] == "library":
        hidden = dict({"id": hidden_id}, **library_params(hidden_id, spec["size"]))
    else:
        hidden = draw_control(rng, hidden_id, ctx)
    sim_hidden = None if hidden["id"] in ("sensor_offset", "none") else hidden
    so_dz = hidden.get("dz_mm", 0.0) * 1e-3 if hidden["id"] == "sensor_offset" else 0.0
    so_dt = hidden.get("dt_ms", 0.0) * 1e-3 if hidden["id"] == "sensor_offset" else 0.0
    rawfmt = draw_raw_format(rng, spec, real) if is_raw else None

    # drops, in a shuffled test order
    conds = []
    for soil, plist in (("fjs1_lp", design["pads_lp"]), ("fjs1_cp", design["pads_cp"])):
        for pad in plist:
            for atm in design["atmospheres"]:
                for v in speeds:
                    for rep in range(1, design["replicates"] + 1):
                        conds.append((pad, soil, atm, v, rep))
    order = rng.permutation(len(conds))
    conds = [conds[int(i)] for i in order]

    T = 1.0 / real["sample_rate_hz"]
    sims = []
    tables = {}
    for (pad, soil, atm, v_nom, rep) in conds:
        e = float(rng.normal(0, real["zeta_scatter_sd"]))
        u = float(rng.normal(0, real["speed_scatter_sd"]))
        z_drop = zeta_true[soil] * (1 + e)
        v_true = v_nom * (1 + u)
        resp = ph.SoilResponse(pads_cache[pad], z_drop, soils[soil]["rho"], soils[soil]["lam"], sim_hidden, atm)
        if (pad, soil, atm) not in tables:
            tables[(pad, soil, atm)] = ph.ResponseTable(resp)
        res = ph.simulate_drop(resp.use_table(tables[(pad, soil, atm)]), m, G, v_true)
        ch, peak = build_channels(res, real, want_accel=(is_raw and rawfmt["channel"] == "acceleration"))
        did = "%s_%s_%s_v%.2f_r%d" % (pad, SOIL_SHORT[soil], "vac" if atm == "vacuum" else "air", v_nom, rep)
        sims.append({"drop_id": did, "pad": pad, "soil": soil, "atm": atm, "v_nom": v_nom, "rep": rep,
                     "zeta": z_drop, "v_true": v_true, "res": res, "ch": ch, "peak": peak,
                     "phase": float(rng.uniform(0, T)),
                     "f_drift": float(rng.normal(0, real["force_drift_sd_N_s"])),
                     "x_drift": float(rng.normal(0, real["penetration_drift_sd_m_s"])),
                     "noise_seed": int(rng.integers(2 ** 31))})

    # full scales (the lab picks ranges for its largest signals)
    peak_all = max(s["peak"] for s in sims)
    force_fs = choose_fs(1.5 * peak_all, [500.0, 1000.0, 2000.0, 5000.0, 10000.0])
    max_pre = real["pretrigger_s"] if is_raw else max(real["pretrigger_s"], 0.02)
    deep = max(s["res"].d_stop for s in sims)
    vmax = max(s["v_true"] for s in sims)
    x_need = 1.3 * max(deep, vmax * max_pre + 0.005) + (abs(rawfmt.get("sensor_zero_below_surface_m", 0.0))
                                                      if rawfmt else 0.0)
    x_fs = choose_fs(x_need, [0.025, 0.05, 0.1, 0.2])
    bits = real["adc_bits"]
    f_step = 2 * force_fs / 2 ** bits
    x_step = 2 * x_fs / 2 ** bits
    real["force_full_scale_N"] = force_fs
    real["penetration_full_scale_m"] = x_fs
    real["force_quantum_N"] = f_step
    real["penetration_quantum_m"] = x_step
    if is_raw and rawfmt["channel"] == "acceleration":
        amax = max(float(np.max(np.abs(s["ch"]["acceleration"].y))) for s in sims) + G
        a_fs = choose_fs(1.5 * amax, [98.1, 196.2, 490.5, 981.0, 1962.0])
        rawfmt["acceleration_full_scale_m_s2"] = a_fs
        real["acceleration_quantum_m_s2"] = 2 * a_fs / 2 ** bits

    drop_truth = []
    if is_raw:
        os.makedirs(os.path.join(set_dir, "raw"))
    else:
        os.makedirs(os.path.join(set_dir, "dataset", "traces"))
    drops_rows = []
    for s in sims:
        res = s["res"]
        nrng = np.random.default_rng(s["noise_seed"])
        P = real["pretrigger_s"] if is_raw else max(real["pretrigger_s"], 0.02)
        t_end = res.t_stop + real["rest_s"]
        t = -P + s["phase"] + T * np.arange(int(math.floor((t_end + P - s["phase"]) / T)) + 1)
        smp = sample_channels(s["ch"], real, t)
        tr = t - t[0]
        f_meas = smp["force"] + nrng.normal(0, real["force_noise_sd_N"], len(t)) + s["f_drift"] * tr
        x_meas = smp["displacement"] + so_dz + nrng.normal(0, real["penetration_noise_sd_m"], len(t)) \
            + s["x_drift"] * tr
        info = {"drop_id": s["drop_id"], "pad": s["pad"], "soil": s["soil"], "atmosphere": s["atm"],
                "impact_speed_nominal_m_s": s["v_nom"], "impact_speed_true_m_s": s["v_true"],
                "zeta_true_N_cm3": s["zeta"], "replicate": s["rep"],
                "stop_time_s": res.t_stop, "final_penetration_true_m": res.d_stop,
                "peak_force_continuous_N": s["peak"], "energy_balance_rel_error": res.energy_rel_error,
                "sample_phase_s": s["phase"], "force_drift_N_s": s["f_drift"],
                "penetration_drift_m_s": s["x_drift"]}
        if not is_raw:
            f_q = sn.quantise(f_meas, f_step)
            x_q = sn.quantise(x_meas, x_step)
            n_base = max(int(0.010 / T), 5)
            if real["detector"] == "truth":
                t_det, thr = 0.0, float("nan")
            else:
                t_det, thr = sn.detect_touchdown(t, f_q, real["detector"], n_base, step=f_step)
            tw = t - t_det - so_dt
            keep = tw >= -real["pretrigger_s"] - 1e-12
            tw, f_q, x_q = tw[keep], f_q[keep], x_q[keep]
            info["detected_touchdown_error_s"] = t_det
            info["detector_threshold_N"] = thr
            info["recorded_t0_after_true_touchdown_s"] = t_det + so_dt
            rel = "traces/%s.csv" % s["drop_id"]
            write_csv_rows(os.path.join(set_dir, "dataset", rel), ["t_s", "penetration_m", "force_N"],
                           [tw, x_q, f_q])
            drops_rows.append([s["drop_id"], s["pad"], s["soil"], s["atm"], fmt(s["v_nom"]), fmt(m), fmt(G), rel,
                               str(s["rep"])])
        else:
            write_raw_drop(set_dir, s, t, f_meas, x_meas, smp, real, rawfmt, nrng, info)
        drop_truth.append(info)

    if not is_raw:
        with open(os.path.join(set_dir, "dataset", "drops.csv"), "w", newline="") as f:
            f.write("drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace,replicate\n")
            for row in drops_rows:
                f.write(",".join(row) + "\n")
        with open(os.path.join(set_dir, "dataset", "README.md"), "w") as f:
            f.write("# %s: SYNTHETIC drop tests (gapbench)\n\nNot measurements. Generated by "
                    "tools/gapbench/generate.py for a blind test of `touchdown diagnose`; what is hidden in "
                    "these drops is recorded outside this folder.\n" % name)
    else:
        write_import_yaml(set_dir, name, sims, real, rawfmt, m)

    truth = {
        "set": name, "label": spec["label"], "form": spec["form"], "kind": spec["kind"],
        "hidden_effect": hidden, "size_factor": spec["size"],
        "zeta_true_N_cm3": zeta_true,
        "soils": {k: {"bulk_density_kg_m3": soils[k]["rho"], "dynamic_lambda": soils[k]["lam"]} for k in soils},
        "design": dict(design, speeds_nominal_m_s=speeds, n_drops=len(sims), gravity_m_s2=G, pad_mass_kg=m),
        "realism": real, "raw_format": rawfmt, "seed": seed,
        "drops": drop_truth,
        "generator": "tools/gapbench/generate.py (independent of touchdown's code)",
    }
    with open(os.path.join(set_dir, "truth.yaml"), "w") as f:
        yaml.safe_dump(to_builtin(truth), f, sort_keys=False, default_flow_style=None, width=120)
    return manifest_row(spec, hidden, real, design, speeds, len(sims), zeta_true, rawfmt)


def write_raw_drop(set_dir, s, t, f_meas, x_meas, smp, real, rf, nrng, info):
    bits = real["adc_bits"]
    t_file = rf["time_origin_s"] + (t - t[0])
    info["touchdown_time_in_file_s"] = rf["time_origin_s"] - t[0]
    info["force_bias_N"] = rf["force_bias_N"]
    cols, header, fmts = [], [], []
    if rf["time"] != "none":
        scale = {"s": 1.0, "ms": 1e3, "us": 1e6}[rf["time"]]
        dec = {"s": 7, "ms": 4, "us": 1}[rf["time"]]
        cols.append(t_file * scale)
        header.append(rf["columns"]["time"])
        fmts.append(lambda x, dec=dec: "%.*f" % (dec, x))
    vstep = 20.0 / 2 ** bits

    def to_raw(phys, gain, offset):
        r = phys / gain + offset
        if rf["units"] == "counts":
            return np.round(r), (lambda x: "%d" % x)
        return np.round(r / vstep) * vstep, (lambda x: "%.7f" % x)

    fgain = real["force_full_scale_N"] / 10.0 if rf["units"] == "volts" else real["force_quantum_N"]
    rf["force_gain"] = fgain
    vals, fm = to_raw(f_meas + rf["force_bias_N"], fgain, rf["force_offset_raw"])
    cols.append(vals)
    header.append(rf["columns"]["force"])
    fmts.append(fm)
    if rf["channel"] == "displacement":
        sign = rf["displacement_sign"]
        xg = (real["penetration_full_scale_m"] / 10.0 if rf["units"] == "volts"
              else real["penetration_quantum_m"]) * sign
        rf["displacement_gain"] = xg
        vals, fm = to_raw(x_meas + rf["sensor_zero_below_surface_m"], xg, rf["displacement_offset_raw"])
        cols.append(vals)
        header.append(rf["columns"]["displacement"])
        fmts.append(fm)
    else:
        a = smp["acceleration"] + rf["accel_bias_m_s2"] + nrng.normal(0, rf["accel_noise_sd_m_s2"], len(t))
        ag = rf["acceleration_full_scale_m_s2"] / 10.0 if rf["units"] == "volts" \
            else 2 * rf["acceleration_full_scale_m_s2"] / 2 ** bits
        rf["acceleration_gain"] = ag
        vals, fm = to_raw(a, ag, rf["acceleration_offset_raw"])
        cols.append(vals)
        header.append(rf["columns"]["acceleration"])
        fmts.append(fm)
    pre = ["# gapbench synthetic DAQ export (SYNTHETIC, not a measurement)",
           "# drop: %s" % s["drop_id"],
           "# sample rate: %d Hz; units: %s" % (real["sample_rate_hz"], rf["units"])]
    write_csv_rows(os.path.join(set_dir, "raw", s["drop_id"] + ".csv"), header, cols,
                   delimiter=rf["delimiter"], pre_lines=pre, formatters=fmts)


def yaml_num(x):
    return repr(float(x))


def write_import_yaml(set_dir, name, sims, real, rf, m):
    delim = {",": '","', ";": '";"', "\t": '"\\t"'}[rf["delimiter"]]
    lines = ["schema_version: 1", "type: import", "name: %s" % name, "daq:",
             "  delimiter: %s" % delim, '  comment: "#"']
    if rf["time"] == "none":
        lines.append("  time: {sample_rate_hz: %d}" % real["sample_rate_hz"])
    else:
        lines.append("  time: {column: %s, unit: %s}" % (rf["columns"]["time"], rf["time"]))
    lines.append("channels:")
    lines.append("  force: {column: %s, gain: %s, offset: %s, filter: %s, zero: pre_trigger}"
                 % (rf["columns"]["force"], yaml_num(rf["force_gain"]), repr(rf["force_offset_raw"]),
                    rf["force_filter"]))
    if rf["channel"] == "displacement":
        lines.append("  displacement: {column: %s, gain: %s, offset: %s, filter: none}"
                     % (rf["columns"]["displacement"], yaml_num(rf["displacement_gain"]),
                        repr(rf["displacement_offset_raw"])))
    else:
        lines.append("  acceleration: {column: %s, gain: %s, offset: %s, filter: none, zero: none}"
                     % (rf["columns"]["acceleration"], yaml_num(rf["acceleration_gain"]),
                        repr(rf["acceleration_offset_raw"])))
    lines.append("drops:")
    for s in sims:
        lines.append("  - {file: raw/%s.csv, drop_id: %s, pad: %s, soil: %s, atmosphere: %s, impact_speed_m_s: %s, "
                     "pad_mass_kg: %s, gravity_m_s2: %s, replicate: %d}"
                     % (s["drop_id"], s["drop_id"], s["pad"], s["soil"], s["atm"], yaml_num(s["v_nom"]),
                        yaml_num(m), yaml_num(G), s["rep"]))
    with open(os.path.join(set_dir, "import.yaml"), "w") as f:
        f.write("\n".join(lines) + "\n")


MANIFEST_COLS = ["name", "form", "kind", "hidden", "size", "label", "params", "sample_rate_hz", "sampling_kind",
                 "antialias_order", "antialias_cutoff_fraction", "load_cell", "load_cell_fn_hz",
                 "load_cell_damping", "zeta_scatter_sd", "speed_scatter_sd", "replicates", "n_drops", "pads",
                 "soils", "atmospheres", "speeds_m_s", "pad_mass_kg", "force_noise_sd_N",
                 "penetration_noise_sd_um", "force_drift_sd_N_s", "penetration_drift_sd_mm_s", "adc_bits",
                 "force_full_scale_N", "detector", "pretrigger_ms", "rest_ms", "zeta_lp", "zeta_cp",
                 "raw_channel", "raw_units", "raw_time", "raw_delimiter", "raw_force_filter",
                 "raw_surface_zeroed"]


def manifest_row(spec, hidden, real, design, speeds, n, zeta_true, rf):
    params = ";".join("%s=%s" % (k, (round(v, 6) if isinstance(v, float) else v))
                      for k, v in hidden.items() if k != "id")
    aa = real.get("antialias") or {}
    lc = real["load_cell"] or {}
    soils = ["fjs1_lp"] + (["fjs1_cp"] if design["pads_cp"] else [])
    pads = design["pads_lp"] + ["cp:" + p for p in design["pads_cp"]]
    return {
        "name": spec["name"], "form": spec["form"], "kind": spec["kind"], "hidden": spec["hidden"],
        "size": spec["size"] if spec["size"] is not None else "", "label": spec["label"], "params": params,
        "sample_rate_hz": real["sample_rate_hz"], "sampling_kind": real["sampling_kind"],
        "antialias_order": aa.get("order", ""), "antialias_cutoff_fraction": round(aa["cutoff_fraction_of_fs"], 4)
        if aa else "", "load_cell": int(bool(lc)), "load_cell_fn_hz": round(lc["natural_frequency_hz"], 1) if lc else "",
        "load_cell_damping": round(lc["damping_ratio"], 4) if lc else "",
        "zeta_scatter_sd": round(real["zeta_scatter_sd"], 5), "speed_scatter_sd": round(real["speed_scatter_sd"], 5),
        "replicates": design["replicates"], "n_drops": n, "pads": " ".join(pads), "soils": " ".join(soils),
        "atmospheres": " ".join(design["atmospheres"]), "speeds_m_s": " ".join("%.2f" % v for v in speeds),
        "pad_mass_kg": real["pad_mass_kg"], "force_noise_sd_N": round(real["force_noise_sd_N"], 4),
        "penetration_noise_sd_um": round(real["penetration_noise_sd_m"] * 1e6, 3),
        "force_drift_sd_N_s": round(real["force_drift_sd_N_s"], 3),
        "penetration_drift_sd_mm_s": round(real["penetration_drift_sd_m_s"] * 1e3, 4),
        "adc_bits": real["adc_bits"], "force_full_scale_N": real["force_full_scale_N"],
        "detector": real["detector"] or "", "pretrigger_ms": round(real["pretrigger_s"] * 1e3, 2),
        "rest_ms": round(real["rest_s"] * 1e3, 2), "zeta_lp": round(zeta_true["fjs1_lp"], 4),
        "zeta_cp": round(zeta_true["fjs1_cp"], 4) if "fjs1_cp" in zeta_true else "",
        "raw_channel": rf["channel"] if rf else "", "raw_units": rf["units"] if rf else "",
        "raw_time": rf["time"] if rf else "", "raw_delimiter": {",": "comma", ";": "semicolon", "\t": "tab"}[
            rf["delimiter"]] if rf else "", "raw_force_filter": rf["force_filter"] if rf else "",
        "raw_surface_zeroed": (int(rf["surface_zeroed"]) if rf and "surface_zeroed" in rf else ""),
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out_dir")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--sets", type=int, default=None, help="generate only the first N sets of the plan")
    ap.add_argument("--clean", action="store_true",
                    help="write the same sets without the rig's realism (see make_clean): a consistency check")
    ap.add_argument("--only", default=None,
                    help="glob on the set name or its label (e.g. 'gb01*', 'rate_damping_x3', 'control_*', '*x10')")
    args = ap.parse_args(argv)
    plan = make_plan(args.seed)
    if args.sets is not None:
        plan = plan[:args.sets]
    if args.only:
        plan = [p for p in plan if fnmatch.fnmatch(p["name"], args.only) or fnmatch.fnmatch(p["label"], args.only)]
    os.makedirs(os.path.join(args.out_dir, "sets"), exist_ok=True)
    soils = {}
    for k in ("fjs1_lp", "fjs1_cp"):
        sp = ph.load_soil(k)
        soils[k] = {"rho": float(sp["bulk_density_kg_m3"]),
                    "lam": float(sp.get("dynamic_lambda", 1.1)) if sp.get("dynamic_term", False) else 0.0}
    pads_cache = {p: ph.load_pad(p)[0] for p in PADS}
    rows = []
    t0 = time.time()
    for i, spec in enumerate(plan):
        ts = time.time()
        rows.append(generate_set(spec, args.out_dir, args.seed, soils, pads_cache, clean=args.clean))
        print("[%d/%d] %s %s %s (%.1f s)" % (i + 1, len(plan), spec["name"], spec["form"], spec["label"],
                                             time.time() - ts), flush=True)
    with open(os.path.join(args.out_dir, "manifest.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=MANIFEST_COLS)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    print("wrote %d sets to %s in %.0f s" % (len(rows), args.out_dir, time.time() - t0))


if __name__ == "__main__":
    main()

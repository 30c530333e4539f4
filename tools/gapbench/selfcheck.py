#!/usr/bin/python3
"""gapbench self-check: our physics and sensors against closed forms and independent quadrature.

  /usr/bin/python3 tools/gapbench/selfcheck.py        (about a minute; exit 0 when every check passes)

Prints one line per check and closes with 'N passed, N failed'.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _deps  # noqa: F401,E402

import numpy as np  # noqa: E402
from scipy import integrate, optimize, signal  # noqa: E402

import physics as ph  # noqa: E402
import sensors as sn  # noqa: E402

RESULTS = []


def check(name, ok, detail=""):
    RESULTS.append(bool(ok))
    print("%s  %s  %s" % ("PASS" if ok else "FAIL", name, detail), flush=True)


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def disc_only(R=0.05):
    return ph.Profile("disc", [ph.Disc(R)], R, 0.0)


def check_raw_files():
    """Generate one raw displacement set and one raw acceleration set and decode them with the mapping
    (physical = gain * (raw - offset)): the pre-trigger reads the force bias and gravity, the
    displacement at the true touchdown reads the sensor's zero offset, and the dataset-form trace of a
    generated set starts near penetration 0."""
    import shutil
    import tempfile
    import yaml
    import generate as gen
    plan = gen.make_plan(1)
    picks = {}
    for p in plan:
        if p["form"] == "raw" and p.get("raw_channel") not in picks:
            picks[p["raw_channel"]] = p
    soils = {}
    for k in ("fjs1_lp", "fjs1_cp"):
        sp = ph.load_soil(k)
        soils[k] = {"rho": float(sp["bulk_density_kg_m3"]), "lam": float(sp["dynamic_lambda"])}
    pads = {p: ph.load_pad(p)[0] for p in gen.PADS}
    tmp = tempfile.mkdtemp(prefix="gapbench_selfcheck_")
    try:
        for chan, spec in sorted(picks.items()):
            gen.generate_set(spec, tmp, 1, soils, pads)
            sdir = os.path.join(tmp, "sets", spec["name"])
            with open(os.path.join(sdir, "import.yaml")) as f:
                imp = yaml.safe_load(f)
            with open(os.path.join(sdir, "truth.yaml")) as f:
                truth = yaml.safe_load(f)
            daq, chans = imp["daq"], imp["channels"]
            ok = imp["schema_version"] == 1 and imp["type"] == "import" and len(imp["drops"]) == \
                truth["design"]["n_drops"]
            worst_f = worst_x = worst_a = 0.0
            rf = truth["raw_format"]
            fs = truth["realism"]["sample_rate_hz"]
            for dr, dt_ in zip(imp["drops"][:4], truth["drops"][:4]):
                with open(os.path.join(sdir, dr["file"])) as f:
                    lines = [ln.rstrip("\n") for ln in f if not ln.startswith(daq["comment"])]
                head = lines[0].split(daq["delimiter"])
                rows = np.array([[float(x) for x in ln.split(daq["delimiter"])] for ln in lines[1:]])
                col = {h: rows[:, i] for i, h in enumerate(head)}
                if "column" in daq["time"]:
                    scale = {"s": 1.0, "ms": 1e-3, "us": 1e-6}[daq["time"]["unit"]]
                    t = col[daq["time"]["column"]] * scale
                else:
                    t = np.arange(len(rows)) / daq["time"]["sample_rate_hz"]
                    t = t + rf["time_origin_s"]
                td = dt_["touchdown_time_in_file_s"]
                pre = t < td - 3.0 / fs
                fc = chans["force"]
                F = fc["gain"] * (col[fc["column"]] - fc["offset"])
                worst_f = max(worst_f, abs(np.mean(F[pre]) - dt_["force_bias_N"]))
                if "displacement" in chans:
                    xc = chans["displacement"]
                    x = xc["gain"] * (col[xc["column"]] - xc["offset"])
                    x_td = np.interp(td, t, x)
                    worst_x = max(worst_x, abs(x_td - rf["sensor_zero_below_surface_m"]))
                else:
                    ac = chans["acceleration"]
                    a = ac["gain"] * (col[ac["column"]] - ac["offset"])
                    worst_a = max(worst_a, abs(np.mean(a[pre]) - 9.81 - rf["accel_bias_m_s2"]))
            check("raw %s set %s: mapping decodes the channels (force bias %.2f N, displacement at touchdown "
                  "%.3f mm, free-fall acceleration %.3f m/s^2 off)" % (chan, spec["name"], worst_f, worst_x * 1e3,
                                                                     worst_a),
                  ok and worst_f < 1.5 and worst_x < 2e-4 and worst_a < 0.3)
        # a dataset-form set: the trace near t = 0 reads penetration near 0 and force near 0 before it
        spec = next(p for p in plan if p["form"] == "dataset" and p["hidden"] == "none")
        gen.generate_set(spec, tmp, 1, soils, pads)
        ddir = os.path.join(tmp, "sets", spec["name"], "dataset")
        with open(os.path.join(ddir, "drops.csv")) as f:
            hdr = f.readline().strip()
            first = f.readline().strip().split(",")
        ok = hdr == "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace,replicate"
        tr = np.loadtxt(os.path.join(ddir, first[7]), delimiter=",", skiprows=1)
        ok = ok and np.all(np.diff(tr[:, 0]) > 0)
        with open(os.path.join(tmp, "sets", spec["name"], "truth.yaml")) as f:
            truth = yaml.safe_load(f)
        dt_ = next(d for d in truth["drops"] if d["drop_id"] == first[0])
        if tr[0, 0] <= 0:
            x0 = np.interp(0.0, tr[:, 0], tr[:, 1])
        else:   # no pre-trigger: extrapolate the first two samples back to t = 0
            x0 = tr[0, 1] - tr[0, 0] * (tr[1, 1] - tr[0, 1]) / (tr[1, 0] - tr[0, 0])
        expect = dt_["impact_speed_true_m_s"] * dt_["detected_touchdown_error_s"]   # the detector's error
        check("dataset form: header, increasing times, penetration at t = 0 = v x detector error "
              "(%.3f vs %.3f mm)" % (x0 * 1e3, expect * 1e3), ok and abs(x0 - expect) < 3e-4)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main():
    # --- RFT coefficients (physics.md section 1 checks) ---------------------------------------
    check("alpha_z(0, pi/2) = 1", abs(ph.alpha_z(0.0) - 1.0) < 1e-12)
    check("alpha_z(pi/4, pi/2) = 0.564", abs(ph.alpha_z(math.pi / 4) - 0.564) < 1e-12)
    check("alpha_z(pi/2, pi/2) = 0.128", abs(ph.alpha_z(math.pi / 2) - 0.128) < 1e-12)
    check("alpha_z(0, -pi/2) = -0.25", abs(ph.alpha_z(0.0, -math.pi / 2) + 0.25) < 1e-12)

    # --- flat pad closed form: zeta pi r^2 d + zeta 0.128 pi r (d^2 - max(d - h, 0)^2) -----------
    flat, _ = ph.load_pad("flat")
    c4, _ = ph.load_pad("c4")
    cur, _ = ph.load_pad("curved")
    zeta = 3.5
    d = np.array([1e-4, 0.002, 0.008, 0.016, 0.021, 0.04])
    r, h = 0.05, 0.016
    closed = zeta * 1e6 * (math.pi * r * r * d + 0.128 * math.pi * r * (d ** 2 - np.maximum(d - h, 0) ** 2))
    got = ph.SoilResponse(flat, zeta, 1540, 0.0).static_capacity(d)
    check("flat pad F(d) = closed form (bottom + side wall)", np.max(np.abs(got / closed - 1)) < 1e-12,
          "max rel %.1e" % np.max(np.abs(got / closed - 1)))

    # --- c4 and curved against independent adaptive quadrature of the arc-length integral ------
    def quad_profile(u, du, x_end, dd, S=lambda z: z):
        """zeta * int alpha(beta) S(d - u) 2 pi x sqrt(1 + u'^2) dx over the submerged x (scipy.quad)."""
        def integrand(x):
            z = dd - u(x)
            if z <= 0:
                return 0.0
            b = math.atan(du(x))
            return float(ph.alpha_z(b)) * float(S(z)) * 2 * math.pi * x * math.sqrt(1 + du(x) ** 2)
        return integrate.quad(integrand, 0, x_end, limit=400, points=None, epsabs=0, epsrel=1e-12)[0]

    c = 0.004
    worst = 0.0
    for dd in [0.001, 0.004, 0.01, 0.02]:
        # split at the chamfer's start so quad sees smooth pieces
        disc = math.pi * (r - c) ** 2 * dd
        cone = integrate.quad(lambda x: 0.564 * max(dd - (x - (r - c)), 0) * 2 * math.pi * x * math.sqrt(2),
                              r - c, r, epsrel=1e-13, points=[min(max(r - c + dd, r - c), r)])[0]
        wall = 0.128 * 2 * math.pi * r * integrate.quad(lambda u: max(dd - u, 0), c, h, epsrel=1e-13,
                                                        points=[min(max(dd, c), h)])[0]
        ref = zeta * 1e6 * (disc + cone + wall)
        gotc = float(ph.SoilResponse(c4, zeta, 1540, 0.0).static_capacity(np.array([dd]))[0])
        worst = max(worst, rel(gotc, ref))
    check("c4 pad F(d) = quadrature", worst < 1e-10, "max rel %.1e" % worst)

    ec = cur.pieces[0]
    u = lambda x: ec.a0 * (math.exp(ec.a1 * x) - 1)  # noqa: E731
    du = lambda x: ec.a0 * ec.a1 * math.exp(ec.a1 * x)  # noqa: E731
    worst = 0.0
    worst_p = 0.0
    for dd in [0.0005, 0.003, 0.01, 0.0159, 0.02]:
        xe = min(r, math.log1p(dd / ec.a0) / ec.a1)
        ref = zeta * 1e6 * quad_profile(u, du, xe, dd)
        gotc = float(ph.SoilResponse(cur, zeta, 1540, 0.0).static_capacity(np.array([dd]))[0])
        worst = max(worst, rel(gotc, ref))
        S = lambda z: ph.Z_REF * (z / ph.Z_REF) ** 1.3  # noqa: E731
        refp = zeta * 1e6 * quad_profile(u, du, xe, dd, S)
        gotp = float(ph.SoilResponse(cur, zeta, 1540, 0.0, {"id": "depth_exponent", "p": 1.3})
                     .static_capacity(np.array([dd]))[0])
        worst_p = max(worst_p, rel(gotp, refp))
    check("curved pad F(d) = quadrature", worst < 1e-9, "max rel %.1e" % worst)
    check("curved pad, depth exponent 1.3, F(d) = quadrature", worst_p < 1e-6, "max rel %.1e" % worst_p)
    wp = float(ph.SoilResponse(flat, zeta, 1540, 0.0, {"id": "depth_exponent", "p": 1.3})
               .static_capacity(np.array([0.008]))[0])
    cf = zeta * 1e6 * (math.pi * r * r * ph.Z_REF * 0.8 ** 1.3
                       + 0.128 * 2 * math.pi * r * ph.Z_REF * 0.8 ** 2.3 * ph.Z_REF / 2.3)
    check("flat pad, depth exponent 1.3, F = closed form", rel(wp, cf) < 1e-5, "rel %.1e" % rel(wp, cf))

    # --- I_k: flat I_k = pi r^2; curved I_1 = projected area pi a(d)^2; c4 I_3 ------------------
    s = ph.SoilResponse(flat, zeta, 1540, 1.1)
    _, I2, I3, _ = s.terms(np.array([0.003, 0.03]))
    check("flat I_2 = I_3 = pi r^2", np.allclose(I2, math.pi * r * r, rtol=1e-13) and
          np.allclose(I3, math.pi * r * r, rtol=1e-13))
    z, w, cb, _ = cur.nodes(np.array([0.006]))
    a, _ = cur.footprint(np.array([0.006]))
    I1 = float(np.sum(cb * w))
    check("curved I_1 = pi a(d)^2 (projection)", rel(I1, math.pi * a[0] ** 2) < 1e-12,
          "rel %.1e" % rel(I1, math.pi * a[0] ** 2))
    _, _, I3c, _ = ph.SoilResponse(c4, zeta, 1540, 1.1).terms(np.array([0.002]))
    ref = math.pi * (r - c) ** 2 + 0.5 * math.pi * ((r - c + 0.002) ** 2 - (r - c) ** 2)
    check("c4 I_3 = disc + cos^2(45 deg) x chamfer ring", rel(I3c[0], ref) < 1e-12)

    # --- energy balance: impact energy + m g d = dissipated work, every effect ------------------
    effects = [None, {"id": "inertial_drag", "lambda": 6.0}, {"id": "rate_damping", "c_N_s_m3": 15000.0},
               {"id": "added_mass", "c_a": 3.0}, {"id": "added_mass_plug", "c_p": 1.0},
               {"id": "compaction_peak", "k_c_kg_m3": 30000.0, "d_c_mm": 3.0},
               {"id": "depth_exponent", "p": 1.3}, {"id": "gas_cushion", "chi": 0.3, "c_g_N_s_m3": 8000.0},
               {"id": "floor", "bed_depth_mm": 30.0, "c_f": 0.05, "length_mm": 50.0, "n": 3.0},
               {"id": "density", "variant": "layered", "n_f": 6.0, "D": 0.06, "z1_mm": 5.0, "width_mm": 2.0},
               {"id": "density", "variant": "self_weight", "n_f": 6.0, "L_mm": 200.0},
               {"id": "rate_exponent", "q": 0.5, "c_q": 4000.0}, {"id": "rate_exponent", "q": 1.5, "c_q": 4000.0}]
    worst = 0.0
    for prof in (flat, c4, cur):
        for e in effects:
            for v0 in (0.6, 1.8):
                res = ph.simulate_drop(ph.SoilResponse(prof, zeta, 1540, 1.1, e, "air"), 1.6, 9.81, v0)
                worst = max(worst, abs(res.energy_rel_error))
                # independent: trapezoid of F v + accretion over a fine grid of the dense output
    check("energy balance at the stop, 3 pads x 13 effects x 2 speeds", worst < 1e-6, "max rel %.1e" % worst)

    res = ph.simulate_drop(ph.SoilResponse(cur, zeta, 1540, 1.1, {"id": "added_mass", "c_a": 3.0}), 1.6, 9.81, 1.2)
    t = np.linspace(0, res.t_stop, 200001)
    dd, vv = ph.state_at(res, t)
    F = res.resp.force(dd, vv)
    _, dM = res.resp.mass(dd)
    W = integrate.trapezoid(F * vv + 0.5 * dM * vv ** 3, t)
    check("energy balance by independent quadrature of the dense output (curved, added mass)",
          rel(W, res.energy_in) < 1e-6, "rel %.1e" % rel(W, res.energy_in))

    # --- the spline tables (the generator's speed-up) against the exact quadrature -------------
    worst_d = worst_t = 0.0
    for prof in (flat, c4, cur):
        for e in effects:
            for v0 in (0.6, 1.8):
                ex = ph.simulate_drop(ph.SoilResponse(prof, zeta, 1540, 1.1, e, "air"), 1.6, 9.81, v0)
                r_ = ph.SoilResponse(prof, zeta, 1540, 1.1, e, "air")
                tb = ph.simulate_drop(r_.use_table(ph.ResponseTable(r_)), 1.6, 9.81, v0)
                worst_d = max(worst_d, rel(tb.d_stop, ex.d_stop))
                worst_t = max(worst_t, rel(tb.t_stop, ex.t_stop))
                if tb.energy_rel_error > 1e-6:
                    worst_d = 1.0
    check("tabulated response = exact quadrature (stop depth and time, 3 pads x 13 effects x 2 speeds)",
          worst_d < 1e-7 and worst_t < 1e-6, "max rel depth %.1e, time %.1e" % (worst_d, worst_t))

    # --- pure quasi-static flat drop: stop depth from 1/2 m v0^2 + m g d = k d^2 / 2 + c_w d^3 / 3
    m, g = 1.6, 9.81
    k = zeta * 1e6 * math.pi * r * r
    cw = zeta * 1e6 * 0.128 * math.pi * r
    for v0 in (0.6, 1.0, 1.8):
        res = ph.simulate_drop(ph.SoilResponse(flat, zeta, 1540, 0.0), m, g, v0)
        ref = optimize.brentq(lambda x: 0.5 * m * v0 ** 2 + m * g * x - 0.5 * k * x * x - cw * x ** 3 / 3, 1e-9, h)
        check("quasi-static flat stop depth (v0 %.1f) = energy root" % v0, rel(res.d_stop, ref) < 1e-8,
              "%.9f vs %.9f mm" % (res.d_stop * 1e3, ref * 1e3))
    # its stop time against the quadrature t = int dd / v(d), v(d)^2 = v0^2 + 2 g d - (k d^2 + 2 c_w d^3 / 3) / m
    v0 = 1.0
    res = ph.simulate_drop(ph.SoilResponse(flat, zeta, 1540, 0.0), m, g, v0)
    vd = lambda x: math.sqrt(max(v0 ** 2 + 2 * g * x - (k * x * x + 2 * cw * x ** 3 / 3) / m, 0.0))  # noqa: E731
    tq = integrate.quad(lambda x: 1 / vd(x), 0, res.d_stop, limit=500, epsrel=1e-10)[0]
    check("quasi-static flat stop time = quadrature of dd/v", rel(res.t_stop, tq) < 1e-5,
          "%.7f vs %.7f ms" % (res.t_stop * 1e3, tq * 1e3))

    # --- inertial drag against Katsuragi-Durian: disc-only pad, m dv/dt = m g - m v^2/d1 - k z ----
    disc = disc_only()
    lam, rho = 6.0, 1540.0
    d1 = m / (lam * rho * math.pi * r * r)
    A = g * d1 + k * d1 * d1 / (2 * m)
    B = -k * d1 / m
    for v0 in (0.7, 1.6):
        res = ph.simulate_drop(ph.SoilResponse(disc, zeta, rho, lam), m, g, v0)
        sfun = lambda z: A + B * z + (v0 ** 2 - A) * math.exp(-2 * z / d1)  # noqa: E731
        zs = optimize.brentq(sfun, 1e-9, 1.0)
        check("inertial drag stop depth (v0 %.1f) = Katsuragi-Durian root" % v0, rel(res.d_stop, zs) < 1e-8,
              "%.9f vs %.9f mm" % (res.d_stop * 1e3, zs * 1e3))
        tt = np.linspace(0, res.t_stop, 50)
        dd, vv = ph.state_at(res, tt)
        err = np.max(np.abs(vv ** 2 - np.array([sfun(x) for x in dd])))
        check("inertial drag v^2(d) = s(d) along the stroke (v0 %.1f)" % v0, err < 1e-8, "max %.1e" % err)

    # --- rate damping against the damped oscillator: m d'' + c A d' + k d = m g -----------------
    cdamp = 15000.0
    res = ph.simulate_drop(ph.SoilResponse(disc, zeta, rho, 0.0, {"id": "rate_damping", "c_N_s_m3": cdamp}),
                           m, g, 1.0)
    gam = cdamp * math.pi * r * r / (2 * m)
    w0 = math.sqrt(k / m)
    wd = math.sqrt(w0 * w0 - gam * gam)
    xs = m * g / k
    # d(t) = xs + e^{-gam t} (C1 cos wd t + C2 sin wd t), d(0) = 0, v(0) = 1
    C1 = -xs
    C2 = (1.0 + gam * C1) / wd
    vfun = lambda tt: math.exp(-gam * tt) * ((-gam * C1 + wd * C2) * math.cos(wd * tt)  # noqa: E731
                                            + (-gam * C2 - wd * C1) * math.sin(wd * tt))
    ts = optimize.brentq(vfun, 1e-6, math.pi / wd)
    dts = xs + math.exp(-gam * ts) * (C1 * math.cos(wd * ts) + C2 * math.sin(wd * ts))
    check("rate damping stop time = damped oscillator", rel(res.t_stop, ts) < 1e-8,
          "%.9f vs %.9f ms" % (res.t_stop * 1e3, ts * 1e3))
    check("rate damping stop depth = damped oscillator", rel(res.d_stop, dts) < 1e-8)

    # --- added mass: momentum (m + m_a) v = m v0 with no other force, energy lost = accretion ---
    for prof, eff in ((cur, {"id": "added_mass", "c_a": 3.0}), (flat, {"id": "added_mass", "c_a": 3.0}),
                      (c4, {"id": "added_mass_plug", "c_p": 1.0}), (flat, {"id": "added_mass_plug", "c_p": 1.0})):
        sr = ph.SoilResponse(prof, 0.0, rho, 0.0, eff)
        rhs = ph.rig_rhs(sr, m, 0.0)
        v0 = 1.0
        sol = integrate.solve_ivp(rhs, (0, 0.03), [0.0, v0, 0.0], method="DOP853", rtol=1e-11,
                                  atol=[1e-14, 1e-12, 1e-14], dense_output=True, max_step=1e-4)
        dE, vE = sol.y[0, -1], sol.y[1, -1]
        M, _ = sr.mass(np.array([dE]))
        mom = (m + M[0]) * vE
        lost = 0.5 * m * v0 ** 2 - 0.5 * (m + M[0]) * vE ** 2
        check("%s on %s: (m + m_a) v = m v0" % (eff["id"], prof.name), rel(mom, m * v0) < 1e-8,
              "rel %.1e" % rel(mom, m * v0))
        check("%s on %s: kinetic energy lost = accretion loss" % (eff["id"], prof.name),
              rel(lost, sol.y[2, -1]) < 1e-7, "rel %.1e" % rel(lost, sol.y[2, -1]))
    # plug past d_f: v = m v0 / (m + m_p), the instant inelastic impact
    sr = ph.SoilResponse(flat, 0.0, rho, 0.0, {"id": "added_mass_plug", "c_p": 1.0})
    mp = rho * math.pi / 3 * r ** 3
    sol = integrate.solve_ivp(ph.rig_rhs(sr, m, 0.0), (0, 0.01), [0.0, 1.0, 0.0], method="DOP853", rtol=1e-11,
                              atol=[1e-14, 1e-12, 1e-14], max_step=1e-5)
    check("plug past d_f: v = m v0 / (m + m_p)", rel(sol.y[1, -1], m / (m + mp)) < 1e-8)
    check("plug past d_f: energy lost = m m_p v0^2 / (2 (m + m_p))",
          rel(sol.y[2, -1], m * mp / (2 * (m + mp))) < 1e-7)

    # --- gas cushion in vacuum is inert; static capacity includes (1 - chi) in air -------------
    gv = ph.SoilResponse(flat, zeta, rho, 1.1, {"id": "gas_cushion", "chi": 0.3, "c_g_N_s_m3": 8000.0}, "vacuum")
    ga = ph.SoilResponse(flat, zeta, rho, 1.1, {"id": "gas_cushion", "chi": 0.3, "c_g_N_s_m3": 8000.0}, "air")
    base = ph.SoilResponse(flat, zeta, rho, 1.1)
    dd = np.array([0.005])
    check("gas cushion inert in vacuum", gv.force(dd, np.array([1.0]))[0] == base.force(dd, np.array([1.0]))[0])
    check("gas cushion in air: capacity x (1 - chi), damping c_g v I_2",
          rel(ga.static_capacity(dd)[0], 0.7 * base.static_capacity(dd)[0]) < 1e-13 and
          rel(ga.force(dd, np.array([1.0]))[0] - ga.static_capacity(dd)[0] - 1.1 * rho * math.pi * r * r,
              8000.0 * math.pi * r * r) < 1e-12)

    # --- filters: step responses -----------------------------------------------------------------
    dt = sn.FINE_DT
    tt = np.arange(0, 0.02, dt)
    fn, zl = 500.0, 0.05
    wn = 2 * math.pi * fn
    y = sn.apply_filter(sn.loadcell_sections(fn, zl), np.ones_like(tt), dt)
    wdl = wn * math.sqrt(1 - zl * zl)
    # FOH with zero state starts the step as a ramp over [-dt, 0]: compare with the step at -dt/2
    te = tt + dt / 2
    ya = 1 - np.exp(-zl * wn * te) * (np.cos(wdl * te) + zl / math.sqrt(1 - zl * zl) * np.sin(wdl * te))
    err = np.max(np.abs(y - ya))
    check("load cell (500 Hz, zeta 0.05) step response = analytic", err < 1e-5, "max abs %.1e" % err)
    for order, fc in ((2, 200.0), (5, 900.0), (8, 4500.0)):
        secs = sn.butterworth_sections(order, fc)
        dtb = sn.fine_dt(secs)
        tt = np.arange(0, 0.02, dtb)
        te = tt + dtb / 2
        y = sn.apply_filter(secs, np.ones_like(tt), dtb)
        zb, pb, kb = signal.butter(order, 2 * math.pi * fc, analog=True, output="zpk")
        # reference: the analytic step response by residues, y = 1 + sum_i Res(H(s)/s, p_i) e^{p_i t}
        yr = np.ones_like(te, dtype=complex)
        for i, pi_ in enumerate(pb):
            others = np.prod([pi_ - pj for j, pj in enumerate(pb) if j != i])
            yr += kb / (pi_ * others) * np.exp(pi_ * te)
        err = np.max(np.abs(y - yr.real))
        check("Butterworth order %d at %g Hz step = analytic (residues)" % (order, fc), err < 1e-4,
              "max abs %.1e" % err)
        wgrid = np.logspace(1, 5, 50)
        _, hr = signal.freqs_zpk(zb, pb, kb, worN=2 * math.pi * wgrid)
        hm = np.ones_like(wgrid, dtype=complex)
        for sec in secs:
            num, den = sn.section_tf(sec)
            hm *= np.polyval(num, 2j * math.pi * wgrid) / np.polyval(den, 2j * math.pi * wgrid)
        check("Butterworth order %d sections = scipy's analog design" % order, np.max(np.abs(hm - hr)) < 1e-9)
    # steady-state polynomial response: a parabola fed from far back equals p + h1 p' + h2 p''
    secs = sn.butterworth_sections(6, 600.0) + sn.loadcell_sections(900.0, 0.2)
    t2 = np.arange(-0.2, 0.01, dt)
    p = [0.0, 1.2, 4.905]
    y = sn.apply_filter(secs, p[0] + p[1] * (t2 + 0.2) + p[2] * (t2 + 0.2) ** 2, dt)
    fp = sn.filtered_poly(p, secs)
    tail = t2 >= 0
    ya = fp[0] + fp[1] * (t2[tail] + 0.2) + fp[2] * (t2[tail] + 0.2) ** 2
    err = np.max(np.abs(y[tail] - ya))
    check("filtered parabola = p + h1 p' + h2 p'' (steady state)", err < 1e-8, "max abs %.1e" % err)

    # --- sampling: period mean against brute-force averaging of the continuous channel -----------
    res = ph.simulate_drop(ph.SoilResponse(c4, zeta, rho, 1.1), m, g, 1.0)
    import generate as gen  # noqa: E402
    for kind, lc in (("period_mean", None), ("period_mean", {"natural_frequency_hz": 700.0, "damping_ratio": 0.1})):
        real = {"sample_rate_hz": 2000, "sampling_kind": kind, "load_cell": lc, "rest_s": 0.02}
        ch, _ = gen.build_channels(res, real, want_accel=True)
        T = 1 / 2000.0
        tk = np.array([-0.0031, -0.0002, 0.0001, 0.004, res.t_stop - 1e-4, res.t_stop + 2e-5, res.t_stop + 0.01])
        worst = 0.0
        for name, c_ in ch.items():
            pm = c_.period_mean(tk, T)
            bf = np.array([np.mean(c_.instantaneous(np.linspace(x - T / 2, x + T / 2, 400001))) for x in tk])
            scale = max(1.0, float(np.max(np.abs(bf))))
            worst = max(worst, float(np.max(np.abs(pm - bf))) / scale)
        check("period mean = brute-force mean (%s)" % ("load cell" if lc else "no filter"), worst < 1e-5,
              "max rel %.1e" % worst)
    real = {"sample_rate_hz": 2000, "sampling_kind": "instantaneous", "load_cell": None, "rest_s": 0.02}
    ch, _ = gen.build_channels(res, real, want_accel=True)
    tk = np.array([-0.004, 0.003, res.t_stop / 2, res.t_stop + 0.005])
    dd, vv = ph.state_at(res, np.clip(tk, 0, res.t_stop))
    Fref, aref = ph.loadcell_force(res, dd, vv)
    xref = np.where(tk < 0, 1.0 * tk + 0.5 * g * tk * tk, np.where(tk > res.t_stop, res.d_stop, dd))
    Fref = np.where(tk < 0, 0.0, np.where(tk > res.t_stop, m * g, Fref))
    aref = np.where(tk < 0, g, np.where(tk > res.t_stop, 0.0, aref))
    ok = (np.max(np.abs(ch["force"].instantaneous(tk) - Fref)) < 1e-6 and
          np.max(np.abs(ch["displacement"].instantaneous(tk) - xref)) < 1e-9 and
          np.max(np.abs(ch["acceleration"].instantaneous(tk) - aref)) < 1e-6)
    check("instantaneous samples = the trajectory (free fall, stroke, rest)", ok)
    # the load cell reads the weight at rest once its ringing has decayed
    real = {"sample_rate_hz": 2000, "sampling_kind": "instantaneous",
            "load_cell": {"natural_frequency_hz": 1500.0, "damping_ratio": 0.3}, "rest_s": 0.05}
    ch, _ = gen.build_channels(res, real, want_accel=False)
    check("load cell settles to m g at rest", abs(ch["force"].instantaneous(np.array([res.t_stop + 0.045]))[0] - m * g)
          < 1e-6)

    # --- detector: on a clean step + ramp with a known onset ------------------------------------
    T = 1e-3
    tk = -0.02 + 0.3e-3 + T * np.arange(60)
    f = np.where(tk > 0, 20.0 + 30000.0 * tk, 0.0)
    for kind in ("onset_fit", "interp_back", "first_above", "last_below"):
        t0, _ = sn.detect_touchdown(tk, f, kind, 10)
        check("detector %s on a clean jump: |error| <= 1 sample" % kind, abs(t0) <= T + 1e-12, "%.3f ms" % (t0 * 1e3))
    f = np.where(tk > 0, 2e8 * np.maximum(tk, 0) ** 3, 0.0)
    t0, _ = sn.detect_touchdown(tk, f, "onset_fit", 10)
    check("detector onset_fit on a clean cubic onset: |error| < 0.2 sample", abs(t0) < 0.2 * T, "%.3f ms" % (t0 * 1e3))

    check_raw_files()

    n_ok = sum(RESULTS)
    n_bad = len(RESULTS) - n_ok
    print("%d passed, %d failed" % (n_ok, n_bad))
    return 0 if n_bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main())

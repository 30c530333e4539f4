"""gapbench physics: RFT on an axisymmetric footpad profile and the 1-DOF drop rig.

Written from the project's physics reference (physics.md, sections 1, 2, 4) and docs/model_gap.md
("The effect library", "Rig dynamics with added mass"), independently of touchdown's source code.

Units: SI everywhere inside (m, s, kg, N); zeta is given in N/cm^3 and multiplied by 1e6.
d = penetration of the pad's lowest point (positive down), v = dd/dt (positive down).
"""
import bisect
import math
import os

import numpy as np
import yaml
from scipy.integrate import solve_ivp
from scipy.interpolate import CubicSpline

# ---------------------------------------------------------------------------------------------
# Li, Zhang & Goldman 2013 generic fit (physics.md section 1), per N/cm^3 of zeta.
A00, A10, B11, B01, BM11 = 0.206, 0.169, 0.212, 0.358, 0.055


def alpha_z(beta, gamma=math.pi / 2):
    """Vertical RFT coefficient for attack angle beta and intrusion angle gamma (full generic fit)."""
    return (A00 + A10 * np.cos(2 * beta) + B11 * np.sin(2 * beta + gamma) + B01 * np.sin(gamma)
            + BM11 * np.sin(-2 * beta + gamma))


ALPHA_FLAT = float(alpha_z(0.0))          # 1.000
ALPHA_WALL = float(alpha_z(math.pi / 2))  # 0.128

Z_REF = 0.010      # depth_exponent reference depth (docs/model_gap.md: z_ref = 10 mm)
D_F = 0.001        # added_mass_plug formation depth (docs/model_gap.md: d_f = 1 mm)

_GL_CACHE = {}


def gauss_legendre(n):
    if n not in _GL_CACHE:
        _GL_CACHE[n] = np.polynomial.legendre.leggauss(n)
    return _GL_CACHE[n]


# ---------------------------------------------------------------------------------------------
# Profile pieces. Each returns quadrature nodes over its SUBMERGED part for an array of depths d:
# z (depth of each node below the undisturbed surface), w (surface area weight 2 pi x ds),
# cosb (cos of the attack angle beta = atan(du/dx); the wall has beta = pi/2), alpha (alpha_z).
# Arrays have shape (len(d), n). u(x) = height of the surface above the pad's lowest point.

class Disc:
    """Flat bottom u = 0 for x < R0 (beta = 0)."""

    def __init__(self, R0):
        self.R0 = R0
        self.u_top = 0.0

    def nodes(self, d, n):
        d = d[:, None]
        wet = (d >= 0).astype(float)     # wet from first contact on: F(0) is the right-hand limit
        z = np.maximum(d, 0.0)
        w = wet * math.pi * self.R0 ** 2
        return z, w, np.ones_like(z), np.full_like(z, ALPHA_FLAT)

    def breakpoints(self):
        return []


class Cone:
    """Straight generator from (x0, u0) to (x1, u1), u1 > u0, x1 > x0 (a chamfer)."""

    def __init__(self, x0, u0, x1, u1):
        self.x0, self.u0, self.x1, self.u1 = x0, u0, x1, u1
        self.m = (u1 - u0) / (x1 - x0)
        self.beta = math.atan(self.m)
        self.u_top = u1

    def nodes(self, d, n):
        xi, wg = gauss_legendre(n)
        xs = np.clip(self.x0 + (d - self.u0) / self.m, self.x0, self.x1)[:, None]
        half = (xs - self.x0) / 2
        x = self.x0 + half * (xi[None, :] + 1)
        sec = math.sqrt(1 + self.m ** 2)
        w = half * wg[None, :] * 2 * math.pi * x * sec
        z = np.maximum(d[:, None] - self.u0 - self.m * (x - self.x0), 0.0)
        return z, w, np.full_like(z, 1 / sec), np.full_like(z, float(alpha_z(self.beta)))

    def breakpoints(self):
        return [self.u0, self.u1]

    def footprint_radius(self, d):
        """x where u = d on this piece (for d within [u0, u1])."""
        return self.x0 + (d - self.u0) / self.m


class Wall:
    """Vertical side wall at radius R from u0 to u1 (beta = pi/2: alpha 0.128, cos beta = 0)."""

    def __init__(self, R, u0, u1):
        self.R, self.u0, self.u1 = R, u0, u1
        self.u_top = u1

    def nodes(self, d, n):
        xi, wg = gauss_legendre(n)
        us = np.clip(d, self.u0, self.u1)[:, None]
        half = (us - self.u0) / 2
        u = self.u0 + half * (xi[None, :] + 1)
        w = half * wg[None, :] * 2 * math.pi * self.R
        z = np.maximum(d[:, None] - u, 0.0)
        return z, w, np.zeros_like(z), np.full_like(z, ALPHA_WALL)

    def breakpoints(self):
        return [self.u0, self.u1]


class ExpCurve:
    """Curved bottom u = a0 (exp(a1 x) - 1) for 0 <= x <= R (paper's form, physics.md section 2)."""

    def __init__(self, a0, a1, R):
        self.a0, self.a1, self.R = a0, a1, R
        self.u_top = a0 * (math.exp(a1 * R) - 1)

    def x_of_u(self, u):
        return np.log1p(np.maximum(u, 0.0) / self.a0) / self.a1

    def nodes(self, d, n):
        xi, wg = gauss_legendre(n)
        xs = np.clip(self.x_of_u(d), 0.0, self.R)[:, None]
        half = xs / 2
        x = half * (xi[None, :] + 1)
        e = np.exp(self.a1 * x)
        u = self.a0 * (e - 1)
        s = self.a0 * self.a1 * e              # du/dx = tan(beta)
        sec = np.sqrt(1 + s * s)
        w = half * wg[None, :] * 2 * math.pi * x * sec
        z = np.maximum(d[:, None] - u, 0.0)
        return z, w, 1 / sec, alpha_z(np.arctan(s))

    def breakpoints(self):
        return [self.u_top]


class Profile:
    """An axisymmetric pad: pieces plus the footprint a(d) of its downward-facing surface."""

    def __init__(self, name, pieces, radius, thickness, nodes_per_piece=48):
        self.name = name
        self.pieces = pieces
        self.R = radius
        self.h = thickness
        self.n = nodes_per_piece

    def nodes(self, d):
        d = np.atleast_1d(np.asarray(d, dtype=float))
        parts = [p.nodes(d, self.n) for p in self.pieces]
        return tuple(np.concatenate([q[i] for q in parts], axis=1) for i in range(4))

    def breakpoints(self):
        b = sorted({round(x, 12) for p in self.pieces for x in p.breakpoints() if x > 0})
        return b

    def footprint(self, d):
        """(a, da/dd): radius of the horizontal projection of the submerged downward-facing surface."""
        d = np.atleast_1d(np.asarray(d, dtype=float))
        a = np.zeros_like(d)
        da = np.zeros_like(d)
        for p in self.pieces:
            if isinstance(p, Disc):
                a = np.where(d >= 0, np.maximum(a, p.R0), a)
            elif isinstance(p, Cone):
                inside = (d > p.u0) & (d < p.u1)
                full = d >= p.u1
                a = np.where(inside, np.maximum(a, p.footprint_radius(d)), a)
                da = np.where(inside, 1 / p.m, da)
                a = np.where(full, np.maximum(a, p.x1), a)
            elif isinstance(p, ExpCurve):
                inside = (d > 0) & (d < p.u_top)
                a = np.where(inside, np.maximum(a, p.x_of_u(d)), a)
                da = np.where(inside, 1 / (p.a1 * (p.a0 + np.maximum(d, 0))), da)
                a = np.where(d >= p.u_top, np.maximum(a, p.R), a)
        return a, da


def data_dir():
    env = os.environ.get("TOUCHDOWN_DATA_DIR")
    if env:
        return env
    return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data"))


def load_pad(name, nodes_per_piece=48):
    with open(os.path.join(data_dir(), "pads", name + ".yaml")) as f:
        spec = yaml.safe_load(f)
    prof = spec["profile"]
    R = prof["radius_mm"] * 1e-3
    h = prof["thickness_mm"] * 1e-3
    shape = prof["shape"]
    if shape == "flat":
        pieces = [Disc(R), Wall(R, 0.0, h)]
    elif shape == "chamfer":
        c = prof["chamfer_mm"] * 1e-3            # 45 deg chamfer: c radial by c vertical
        pieces = [Disc(R - c), Cone(R - c, 0.0, R, c), Wall(R, c, h)]
    elif shape == "exponential":
        a1 = prof["a1_per_mm"] * 1e3
        rim = prof.get("rim_height_mm", prof["thickness_mm"]) * 1e-3
        a0 = rim / (math.exp(a1 * R) - 1)
        pieces = [ExpCurve(a0, a1, R)]
        if rim < h - 1e-12:
            pieces.append(Wall(R, rim, h))
    else:
        raise ValueError("unsupported pad shape " + shape)
    return Profile(name, pieces, R, h, nodes_per_piece), float(spec.get("mass_kg", 1.6))


def load_soil(name):
    with open(os.path.join(data_dir(), "soils", name + ".yaml")) as f:
        spec = yaml.safe_load(f)
    return spec


def agarwal_zeta(spec):
    """zeta [N/cm^3] from the Agarwal 2023 scaling named in the soil files: rho g (894 mu^3 - 386 mu^2 + 89 mu)."""
    mu = math.tan(math.radians(spec["internal_friction_angle_deg"]))
    return spec["bulk_density_kg_m3"] * spec.get("reference_gravity_m_s2", 9.81) * (
        894 * mu ** 3 - 386 * mu ** 2 + 89 * mu) / 1e6


# ---------------------------------------------------------------------------------------------
# Depth laws S(z): the factor replacing z in the RFT stress zeta alpha z.

def depth_law(kind, **kw):
    if kind == "linear":
        return lambda z: z
    if kind == "power":                      # depth_exponent: z_ref (z/z_ref)^p
        p = kw["p"]
        return lambda z: Z_REF * np.power(np.maximum(z, 0.0) / Z_REF, p)
    raise ValueError(kind)


class DensityProfile:
    """Out-of-library control (b): a bed whose bulk density grows with depth.

    rho(z)/rho0 = 1 + D s(z), s a logistic step at z1 of width wd ("layered") or the linear z/L
    ("self_weight"). Stress per element: alpha zeta0 k_mu(z) P(z), with P(z) = int_0^z rho/rho0 dz'
    (the lithostatic pressure, Agarwal 2023: zeta proportional to rho g) and k_mu = (rho/rho0)^n_f,
    the friction factor f(mu) of the same scaling, its exponent n_f taken from the catalogue's LP/CP
    pair (both soil files). The dynamic (inertial) term uses rho(z) too.
    """

    def __init__(self, variant, n_f, D=None, z1=None, wd=None, L=None):
        self.variant, self.n_f, self.D, self.z1, self.wd, self.L = variant, n_f, D, z1, wd, L

    def ratio(self, z):
        z = np.maximum(z, 0.0)
        if self.variant == "layered":
            return 1 + self.D / (1 + np.exp(-(z - self.z1) / self.wd))
        return 1 + z / self.L

    def pressure(self, z):
        z = np.maximum(z, 0.0)
        if self.variant == "layered":
            w = self.wd
            return z + self.D * w * (np.logaddexp(0, (z - self.z1) / w) - np.logaddexp(0, -self.z1 / w))
        return z + z * z / (2 * self.L)

    def S(self, z):
        return np.power(self.ratio(z), self.n_f) * self.pressure(z)


# ---------------------------------------------------------------------------------------------

class SoilResponse:
    """Vertical soil response on a level bed for one drop: force, added mass, static capacity.

    hidden: dict with 'id' and parameters in the docs' names (or None); controls use ids
    'floor', 'density', 'rate_exponent'. atmosphere: 'vacuum' or 'air'.
    """

    def __init__(self, profile, zeta_N_cm3, rho, lam=1.1, hidden=None, atmosphere="vacuum"):
        self.prof = profile
        self.zeta = zeta_N_cm3 * 1e6
        self.rho = rho
        self.lam = lam
        h = dict(hidden or {})
        hid = h.get("id", "none")
        self.hid = hid
        self.air = atmosphere == "air"
        self.S = depth_law("linear")
        self.c_lin = 0.0          # rate_damping c [N s/m^3]
        self.k_c = 0.0            # compaction_peak
        self.d_c = 1.0
        self.c_a = 0.0
        self.c_p = 0.0
        self.zeta_factor = 1.0
        self.floor = None
        self.density = None
        self.q = None
        self.c_q = 0.0
        if hid == "inertial_drag":
            self.lam = h["lambda"]
        elif hid == "rate_damping":
            self.c_lin = h["c_N_s_m3"]
        elif hid == "added_mass":
            self.c_a = h["c_a"]
        elif hid == "added_mass_plug":
            self.c_p = h["c_p"]
        elif hid == "compaction_peak":
            self.k_c = h["k_c_kg_m3"]
            self.d_c = h["d_c_mm"] * 1e-3
        elif hid == "depth_exponent":
            self.S = depth_law("power", p=h["p"])
        elif hid == "gas_cushion":
            if self.air:
                self.zeta_factor = 1 - h["chi"]
                self.c_lin = h["c_g_N_s_m3"]
        elif hid == "sensor_offset" or hid == "none":
            pass
        elif hid == "floor":
            self.floor = (h["bed_depth_mm"] * 1e-3, h["c_f"], h["length_mm"] * 1e-3, h.get("n", 3.0))
        elif hid == "density":
            self.density = DensityProfile(h["variant"], h["n_f"], D=h.get("D"),
                                          z1=(h["z1_mm"] * 1e-3 if "z1_mm" in h else None),
                                          wd=(h["width_mm"] * 1e-3 if "width_mm" in h else None),
                                          L=(h["L_mm"] * 1e-3 if "L_mm" in h else None))
            self.S = self.density.S
        elif hid == "rate_exponent":
            self.q = h["q"]
            self.c_q = h["c_q"]
        else:
            raise ValueError("unknown hidden effect " + hid)
        self.any_mass = self.c_a > 0 or self.c_p > 0

        self.table = None

    # -- quantities ------------------------------------------------------------------------
    def use_table(self, table):
        """Evaluate through a ResponseTable (built for this pad, effect, atmosphere and density)."""
        self.table = table
        return self

    def floor_factor(self, d):
        if self.floor is None:
            return 1.0
        H, c_f, ell, n = self.floor
        gap = np.maximum(H - d, 1e-6)
        return 1 + c_f * (ell / gap) ** n

    def terms(self, d):
        """Per-depth pieces: static (zeta included), I2, I3 (density-weighted), Iq."""
        if self.table is not None:
            Y = self.table.eval(d)
            if Y is not None:
                return self.zeta * Y[:, 0], Y[:, 1], Y[:, 2], Y[:, 3]
        return self.terms_exact(d)

    def terms_exact(self, d):
        z, w, cb, al = self.prof.nodes(d)
        static = self.zeta * self.zeta_factor * np.sum(al * self.S(z) * w, axis=1) * self.floor_factor(
            np.atleast_1d(d))
        I2 = np.sum(cb ** 2 * w, axis=1)
        if self.density is not None:
            I3 = np.sum(cb ** 3 * w * self.density.ratio(z), axis=1)
        else:
            I3 = np.sum(cb ** 3 * w, axis=1)
        Iq = np.sum(cb ** (self.q + 1) * w, axis=1) if self.q is not None else 0.0 * I2
        return static, I2, I3, Iq

    def static_capacity(self, d):
        return self.terms(d)[0]

    def force(self, d, v):
        """Soil force on the pad (up), velocity terms only while sinking (v > 0)."""
        static, I2, I3, Iq = self.terms(d)
        v = np.maximum(np.asarray(v, dtype=float), 0.0)
        F = static + (self.lam * self.rho + self.k_c * np.exp(-np.atleast_1d(d) / self.d_c)) * v * v * I3 \
            + self.c_lin * v * I2
        if self.q is not None:
            F = F + self.c_q * np.power(v, self.q) * Iq
        return F

    def mass(self, d):
        """(m_a, dm_a/dd): entrained grains, the cone (c_a) plus the plug (c_p), docs/model_gap.md."""
        d = np.atleast_1d(np.asarray(d, dtype=float))
        if self.any_mass and self.table is not None:
            Y = self.table.eval(d)
            if Y is not None:
                return Y[:, 4], Y[:, 5]
        return self.mass_exact(d)

    def mass_exact(self, d):
        d = np.atleast_1d(np.asarray(d, dtype=float))
        if not self.any_mass:
            z = np.zeros_like(d)
            return z, z
        a, da = self.prof.footprint(d)
        k = self.rho * math.pi / 3
        dd = np.maximum(d, 0.0)
        mn = np.minimum(dd, a)
        dmn = np.where(dd < a, 1.0, da)
        Ma = self.c_a * k * a * a * mn
        dMa = self.c_a * k * (2 * a * da * mn + a * a * dmn)
        fr = np.minimum(1.0, dd / D_F)
        dfr = np.where(dd < D_F, 1 / D_F, 0.0)
        Mp = self.c_p * k * a ** 3 * fr
        dMp = self.c_p * k * (3 * a * a * da * fr + a ** 3 * dfr)
        return Ma + Mp, dMa + dMp

    def breakpoints(self):
        b = list(self.prof.breakpoints())
        if self.c_p > 0:
            b.append(D_F)
        if self.c_a > 0:
            b.append(self.prof.R)          # min(d, a) switches where d reaches the full footprint
        return sorted(set(b))


class ResponseTable:
    """C2 cubic splines of a response's depth functions, one per stretch between the profile's kinks
    (breakpoints), on [0, d_cap] with knots every h: static force per unit zeta, I_2, I_3, I_q, m_a,
    dm_a/dd. A speed-up only (the ODE's right-hand side is evaluated thousands of times per drop):
    selfcheck.py compares drops run through it with the exact quadrature. Depths past d_cap fall back
    to the exact quadrature."""

    def __init__(self, resp, d_cap=0.1, h=1e-5):
        self.d_cap = d_cap
        edges = sorted({0.0, d_cap} | {b for b in resp.breakpoints() if 0 < b < d_cap})
        self.edges = np.array(edges)
        self.edges_list = list(edges)
        self.splines = []
        z_save, resp.zeta = resp.zeta, 1.0
        try:
            for a, b in zip(edges[:-1], edges[1:]):
                n = max(8, int(math.ceil((b - a) / h)) + 1)
                x = np.linspace(a, b, n)
                xe = x.copy()
                xe[0] = a + 1e-12 * (b - a)          # one-sided limits inside the stretch
                xe[-1] = b - 1e-12 * (b - a)
                st, I2, I3, Iq = resp.terms_exact(xe)
                M, dM = resp.mass_exact(xe)
                Y = np.column_stack([st, I2, I3, Iq * np.ones_like(I2), M, dM])
                self.splines.append(CubicSpline(x, Y, axis=0))
        finally:
            resp.zeta = z_save
        self.nseg = len(self.splines)

    def eval(self, d):
        d = np.atleast_1d(np.asarray(d, dtype=float))
        if d.size == 0 or d.max() > self.d_cap or d.min() < 0:
            return None
        if d.size == 1:
            i = min(bisect.bisect_right(self.edges_list, float(d[0])) - 1, self.nseg - 1)
            return self.splines[i](d)
        out = np.empty((d.size, 6))
        idx = np.clip(np.searchsorted(self.edges, d, side="right") - 1, 0, self.nseg - 1)
        for i in np.unique(idx):
            sel = idx == i
            out[sel] = self.splines[int(i)](d[sel])
        return out


# ---------------------------------------------------------------------------------------------

class DropResult:
    pass


def rig_rhs(resp, m, g):
    """Right-hand side of the rig for state [d, v, W]:
    (m + m_a) dv/dt = m g - F(d, v) - v^2 dm_a/dd; dW/dt = F v + v^3 m_a' / 2."""

    def rhs(t, y):
        d, v = y[0], y[1]
        F = resp.force(np.array([d]), np.array([v]))[0]
        if resp.any_mass:
            M, dM = resp.mass(np.array([d]))
            M, dM = M[0], dM[0]
        else:
            M = dM = 0.0
        a = (m * g - F - v * v * dM) / (m + M)
        return [v, a, F * v + 0.5 * dM * v ** 3]
    return rhs


def simulate_drop(resp, m, g, v0, rtol=1e-10, atol_d=1e-15, atol_v=1e-13, d_max=0.2, method="DOP853"):
    """Integrate the rig from touchdown (t = 0, d = 0, v = v0) to the stop (v = 0 with static
    capacity >= m g). State [d, v, W], W = dissipated work (int F v dt + accretion loss v^3 m_a'/2).

    (m + m_a) dv/dt = m g - F(d, v) - v^2 dm_a/dd     (docs/model_gap.md, rig dynamics)
    """

    rhs = rig_rhs(resp, m, g)

    def ev_stop(t, y):
        return y[1]
    ev_stop.terminal = True
    ev_stop.direction = -1

    bps = [b for b in resp.breakpoints() if b > 0]
    segs = []
    t0, y0 = 0.0, [0.0, v0, 0.0]
    n_resume = 0
    while True:
        nxt = [b for b in bps if b > y0[0] + 1e-15]
        target = nxt[0] if nxt else d_max

        def ev_bp(t, y, target=target):
            return y[0] - target
        ev_bp.terminal = True
        ev_bp.direction = 1
        sol = solve_ivp(rhs, (t0, t0 + 5.0), y0, method=method, rtol=rtol,
                        atol=[atol_d, atol_v, 1e-12], events=[ev_stop, ev_bp], dense_output=True)
        if sol.status == -1:
            raise RuntimeError("integration failed: " + sol.message)
        segs.append((t0, sol.t[-1], sol.sol))
        t0 = float(sol.t[-1])
        y0 = [float(x) for x in sol.y[:, -1]]
        if len(sol.t_events[0]):
            y0[1] = 0.0
            cap = float(resp.static_capacity(np.array([y0[0]]))[0])
            if cap >= m * g * (1 - 1e-12):
                break
            n_resume += 1                    # the bed cannot hold the pad: it sinks on
            if n_resume > 50:
                raise RuntimeError("pad never comes to rest")
            continue
        if len(sol.t_events[1]):
            if target >= d_max:
                raise RuntimeError("pad reached d_max without stopping")
            y0[0] = target
            continue
        raise RuntimeError("integration ended without an event")
    r = DropResult()
    r.segments = segs
    r.t_stop = t0
    r.d_stop = y0[0]
    r.W = y0[2]
    r.m, r.g, r.v0 = m, g, v0
    r.resp = resp
    r.energy_in = 0.5 * m * v0 ** 2 + m * g * r.d_stop
    r.energy_rel_error = (r.W - r.energy_in) / r.energy_in
    return r


def state_at(r, t):
    """d(t), v(t) for t in [0, t_stop] (vectorised) from the dense outputs."""
    t = np.asarray(t, dtype=float)
    d = np.zeros_like(t)
    v = np.zeros_like(t)
    for (a, b, sol) in r.segments:
        sel = (t >= a) & (t <= b)
        if np.any(sel):
            y = sol(t[sel])
            d[sel] = y[0]
            v[sel] = y[1]
    return d, v


def loadcell_force(r, d, v):
    """Load-cell force m (g - dv/dt) = F + m_a dv/dt + v^2 m_a' during the stroke (vectorised)."""
    resp = r.resp
    F = resp.force(d, v)
    M, dM = resp.mass(d)
    a = (r.m * r.g - F - v * v * dM) / (r.m + M)
    return r.m * (r.g - a), a

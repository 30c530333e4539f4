"""gapbench sensors: continuous (analogue) filters, the three sampling kinds, noise and touchdown detection.

Signals are continuous-time. A channel is built from
  * an analytic part valid for all t (the free fall's parabola, or gravity), passed through the
    analogue filters exactly (steady-state response to a polynomial: y = p + h1 p' + h2 p''), and
  * a numeric part that is zero before touchdown (t < 0), tabulated on a fine uniform grid from
    t = 0, with the analogue filters applied by first-order-hold (exact for piecewise-linear input)
    discretisations of each second-order section (scipy.signal.cont2discrete, method 'foh').
Unfiltered numeric parts keep the stop's jump exact (a stroke grid plus a constant rest value).
"""
import math

import numpy as np
from scipy import signal


# ---------------------------------------------------------------------------------------------
# Analogue filters as cascades of unity-DC-gain sections: ('2', w, zeta) or ('1', w).

def loadcell_sections(fn_hz, zeta):
    return [("2", 2 * math.pi * fn_hz, zeta)]


def butterworth_sections(order, fc_hz):
    wc = 2 * math.pi * fc_hz
    secs = []
    for k in range(1, order // 2 + 1):
        theta = math.pi * (2 * k + order - 1) / (2 * order)   # pole angle
        zeta = -math.cos(theta)                                # damping of the conjugate pair
        secs.append(("2", wc, zeta))
    if order % 2:
        secs.append(("1", wc))
    return secs


def section_tf(sec):
    if sec[0] == "2":
        w, z = sec[1], sec[2]
        return [w * w], [1.0, 2 * z * w, w * w]
    w = sec[1]
    return [w], [1.0, w]


def taylor_h(sections):
    """H(s) = 1 + h1 s + h2 s^2 + O(s^3) for the cascade (each section has H(0) = 1)."""
    b1 = b2 = 0.0
    for sec in sections:
        if sec[0] == "2":
            c1, c2 = 2 * sec[2] / sec[1], 1 / sec[1] ** 2
        else:
            c1, c2 = 1 / sec[1], 0.0
        # multiply (1 + b1 s + b2 s^2) by (1 + c1 s + c2 s^2)
        b1, b2 = b1 + c1, b2 + c2 + b1 * c1
    return -b1, b1 * b1 - b2


def discrete_sos(sections, dt):
    rows = []
    for sec in sections:
        num, den = section_tf(sec)
        nd, dd, _ = signal.cont2discrete((num, den), dt, method="foh")
        nd = np.atleast_1d(np.squeeze(nd)).astype(float)
        dd = np.atleast_1d(np.squeeze(dd)).astype(float)
        nd = np.concatenate([nd, np.zeros(3 - len(nd))])
        dd = np.concatenate([dd, np.zeros(3 - len(dd))])
        rows.append(np.concatenate([nd / dd[0], dd / dd[0]]))
    return np.array(rows)


FINE_DT = 2e-6          # the continuous signals' grid step (s), at most


def fine_dt(sections):
    """Grid step for filtering: at most FINE_DT and omega dt <= 0.025 for the fastest section, which keeps
    the cascade's first-order-hold error (about (omega dt)^2 / 12 of a step) near 5e-5."""
    w = max([sec[1] for sec in sections] + [1.0])
    return min(FINE_DT, 0.025 / w)


def apply_filter(sections, x, dt):
    """Filter a signal tabulated on a uniform grid starting at t = 0 from rest (zero state)."""
    if not sections:
        return x
    return signal.sosfilt(discrete_sos(sections, dt), x)


# ---------------------------------------------------------------------------------------------

class Channel:
    """One continuous channel: value(t) = P_all(t) + [t < 0] P_pre(t) + [t >= 0] numeric(t).

    P_all and P_pre are polynomials in t (coefficients c0, c1, c2). The numeric part, zero before
    touchdown, is either 'grid' (values y on t = i*dt, i = 0..N-1, linear between nodes; filtered
    channels) or 'piecewise' (a stroke grid whose last node is t_stop, then the constant rest value:
    the stop's jump stays exact for unfiltered channels).
    """

    def __init__(self, dt, y, poly_all=(0.0,), poly_pre=(0.0,), t_stop=None, rest=None):
        self.pa = (list(poly_all) + [0.0] * 3)[:3]
        self.pp = (list(poly_pre) + [0.0] * 3)[:3]
        self.dt = dt
        self.y = np.asarray(y, dtype=float)
        self.t_stop = t_stop
        self.rest = rest
        self._C = np.concatenate([[0.0], np.cumsum(0.5 * (self.y[1:] + self.y[:-1]) * dt)])

    @staticmethod
    def _pv(c, t):
        return c[0] + c[1] * t + c[2] * t * t

    @staticmethod
    def _pint(c, t):
        return c[0] * t + c[1] * t * t / 2 + c[2] * t ** 3 / 3

    def _grid_value(self, t):
        y = self.y
        n = len(y)
        s = np.maximum(t, 0.0) / self.dt
        i = np.clip(np.floor(s).astype(int), 0, n - 2)
        f = np.clip(s - i, 0.0, 1.0)
        val = y[i] * (1 - f) + y[i + 1] * f
        if self.t_stop is not None:
            val = np.where(t >= self.t_stop, self.rest, val)
        return np.where(t < 0, 0.0, val)

    def _grid_cumint(self, t):
        y, dt, C = self.y, self.dt, self._C
        n = len(y)
        tt = np.maximum(t, 0.0)
        if self.t_stop is not None:
            tt = np.minimum(tt, self.t_stop)
        s = tt / dt
        i = np.clip(np.floor(s).astype(int), 0, n - 2)
        tau = np.clip(tt - i * dt, 0.0, dt)
        out = C[i] + y[i] * tau + (y[i + 1] - y[i]) * tau * tau / (2 * dt)
        if self.t_stop is not None:
            out = out + self.rest * np.maximum(t - self.t_stop, 0.0)
        return out

    def instantaneous(self, t):
        t = np.asarray(t, dtype=float)
        return self._pv(self.pa, t) + np.where(t < 0, self._pv(self.pp, t), 0.0) + self._grid_value(t)

    def period_mean(self, t, T):
        t = np.asarray(t, dtype=float)
        a, b = t - T / 2, t + T / 2
        tot = self._pint(self.pa, b) - self._pint(self.pa, a)
        tot = tot + self._pint(self.pp, np.minimum(b, 0.0)) - self._pint(self.pp, np.minimum(a, 0.0))
        tot = tot + self._grid_cumint(b) - self._grid_cumint(a)
        return tot / T

    def sample(self, t, kind, T):
        if kind == "period_mean":
            return self.period_mean(t, T)
        return self.instantaneous(t)


def filtered_poly(poly, sections):
    """Steady-state response of the cascade to the polynomial input c0 + c1 t + c2 t^2 (valid for all t)."""
    c0, c1, c2 = (list(poly) + [0.0] * 3)[:3]
    if not sections:
        return [c0, c1, c2]
    h1, h2 = taylor_h(sections)
    return [c0 + h1 * c1 + 2 * h2 * c2, c1 + 2 * h1 * c2, c2]


# ---------------------------------------------------------------------------------------------

def quantise(x, step):
    return np.round(x / step) * step


# onset_fit: the rise fitted runs to 30 % of the largest force within 30 ms of the trigger (chosen on
# clean and noisy flat and curved drops: later tops bias a curved pad late, earlier ones scatter it)
ONSET_PEAK_WINDOW_S = 0.03
ONSET_TOP_FRACTION = 0.3


def detect_touchdown(t, f, kind, n_base, step=0.0):
    """Threshold detector on a sampled noisy force (our own; it sets each trace's t = 0).

    Baseline and noise from the first n_base samples (free fall); trigger threshold = baseline +
    max(6 sigma, 2 quantisation steps, 2 N). Kinds (per set):
      onset_fit  : the trigger, then the onset refined on the force alone: F - baseline = A (t - t0)^k
                   (k in [0.2, 4]) fitted by least squares to the rise from the last sample in the noise
                   band before the trigger to the first sample past 30 % of the largest force within 30 ms (a curved pad's
                   force grows like (t - t0)^3 from a point contact, a flat pad's jumps: one form fits both);
      interp_back: the threshold crossing interpolated between the samples around it, then
                   extrapolated back to the baseline along the steeper of the two neighbouring slopes
                   (clamped to at most one sample before the last sample below);
      first_above: t = 0 at the first sample above the threshold (crude);
      last_below : t = 0 at the sample before it (crude).
    Returns (t0, threshold).
    """
    base = float(np.mean(f[:n_base]))
    sd = float(np.std(f[:n_base]))
    thr = base + max(6 * sd, 2 * step, 2.0)
    above = np.nonzero(f[n_base:] > thr)[0]
    if len(above) == 0:
        raise RuntimeError("touchdown not detected")
    k = n_base + int(above[0])
    if kind == "first_above":
        return float(t[k]), thr
    if kind == "last_below":
        return float(t[k - 1]), thr
    T = float(np.median(np.diff(t[:n_base + 1])))
    tc = t[k - 1] + (thr - f[k - 1]) / (f[k] - f[k - 1]) * (t[k] - t[k - 1])
    slope = (f[k + 1] - f[k]) / (t[k + 1] - t[k]) if k + 1 < len(f) else 0.0
    slope = max(slope, (f[k] - f[k - 1]) / (t[k] - t[k - 1]))
    t_ib = tc - (thr - base) / slope if slope > 0 else tc
    t_ib = float(min(max(t_ib, t[k - 1] - T), tc))
    if kind == "interp_back":
        return t_ib, thr
    if kind != "onset_fit":
        raise ValueError(kind)
    band = base + max(3 * sd, step, 0.5)
    lo = k - 1
    while lo > n_base and f[lo] > band:
        lo -= 1
    n_pk = max(3, int(round(ONSET_PEAK_WINDOW_S / T)))
    pk = k + int(np.argmax(f[k:k + n_pk]))
    top = base + ONSET_TOP_FRACTION * (f[pk] - base)
    hi = k
    while hi < pk and f[hi] < top:
        hi += 1
    hi = max(hi, min(k + 1, len(f) - 1))
    i0 = max(n_base // 2, lo - max(3, int(round(0.008 / T))))
    tt = t[i0:hi + 1]
    yy = f[i0:hi + 1] - base
    if len(tt) < 4:
        return t_ib, thr
    from scipy.optimize import least_squares
    scale = max(float(yy.max()), 1e-9)
    t_lo, t_hi = float(t[i0]), float(t[k])

    def res(p):
        t0, a, kk = p
        x = np.maximum(tt - t0, 0.0) / T
        return (a * np.power(x, kk) - yy) / scale

    best = None
    for kk0 in (0.5, 1.0, 2.0, 3.0):
        x0 = [min(max(t_ib, t_lo + 1e-9), t_hi - 1e-9), scale / max((t[hi] - t_ib) / T, 0.5) ** kk0, kk0]
        try:
            r = least_squares(res, x0, bounds=([t_lo, 0.0, 0.2], [t_hi, np.inf, 4.0]))
        except ValueError:
            continue
        if best is None or r.cost < best.cost:
            best = r
    if best is None:
        return t_ib, thr
    return float(best.x[0]), thr

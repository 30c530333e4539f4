#!/usr/bin/python3
"""Reference implementation of the impact-test channel filter classes (SAE J211-1 / ISO 6487 CFC
60, 180, 600, 1000) for touchdown's C++ filter (drop_tests/dataset/channel_filter.h), and the
fixture its test compares against (tests/fixtures/cfc_reference_*.csv, to 1e-9 absolute).

Independent of the C++ code in how it gets there: the 2-pole section comes from scipy.signal.butter
(a 2nd-order digital Butterworth low-pass at the standard's design frequency 2.0775 CFC, which
scipy pre-warps and maps by the bilinear transform itself), and the phaseless run from
scipy.signal.filtfilt with padtype=None: a forward then a backward pass, each started in the
steady state of its first input sample (lfilter_zi), the start-up touchdown documents. The script
also checks that butter's coefficients are the standard's Appendix C formulas.

    /usr/bin/python3 tools/cfc_reference.py            # rewrites the fixtures
    /usr/bin/python3 tools/cfc_reference.py --check    # compares with the stored fixtures only
"""
import argparse
import math
import os
import sys

import numpy as np
from scipy import signal

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
FIXTURES = os.path.join(ROOT, "tests", "fixtures")
CLASSES = [60, 180, 600, 1000]


def j211_coefficients(cfc, period_s):
    """SAE J211-1 Appendix C, as the standard writes them: (b, a) in scipy's sign convention."""
    wd = 2.0 * math.pi * cfc * 2.0775
    wa = math.sin(wd * period_s / 2.0) / math.cos(wd * period_s / 2.0)
    d = 1.0 + math.sqrt(2.0) * wa + wa * wa
    a0 = wa * wa / d
    b1 = -2.0 * (wa * wa - 1.0) / d
    b2 = (-1.0 + math.sqrt(2.0) * wa - wa * wa) / d
    return np.array([a0, 2.0 * a0, a0]), np.array([1.0, -b1, -b2])


def reference_filter(x, cfc, fs):
    """The phaseless CFC filter by scipy alone."""
    b, a = signal.butter(2, 2.0775 * cfc, btype="low", fs=fs)
    jb, ja = j211_coefficients(cfc, 1.0 / fs)
    assert np.allclose(b, jb, rtol=1e-12, atol=0) and np.allclose(a, ja, rtol=1e-12, atol=0), (cfc, fs, b, jb, a, ja)
    return signal.filtfilt(b, a, x, padtype=None)


def test_signal(fs, duration_s, seed):
    """Unit scale: a free-fall baseline, a 12 ms half-sine impact with a jump at contact, a ringing
    load-cell mode, tones across the classes' corners and white noise, then rest at 0.6."""
    t = np.arange(int(round(duration_s * fs))) / fs
    x = np.zeros_like(t)
    contact, stroke = 0.030, 0.012
    inside = (t >= contact) & (t < contact + stroke)
    x[inside] = 0.25 + 0.75 * np.sin(math.pi * (t[inside] - contact) / stroke)
    x[t >= contact + stroke] = 0.6
    after = t >= contact
    x[after] += 0.2 * np.exp(-(t[after] - contact) / 0.004) * np.sin(2 * math.pi * 1400.0 * (t[after] - contact))
    for f, amplitude in [(45.0, 0.05), (260.0, 0.04), (900.0, 0.03), (2100.0, 0.02)]:
        if f < fs / 2:
            x += amplitude * np.sin(2 * math.pi * f * t + 0.3)
    x += 0.02 * np.random.default_rng(seed).standard_normal(t.size)
    return t, x


def fixture_rows(fs, classes, seed):
    t, x = test_signal(fs, 0.1, seed)
    columns = {"t_s": t, "x": x}
    for cfc in classes:
        columns[f"cfc{cfc}"] = reference_filter(x, cfc, fs)
    return columns


def write(path, columns):
    names = list(columns)
    with open(path, "w", encoding="utf-8") as out:
        out.write("# tools/cfc_reference.py: scipy.signal.butter(2, 2.0775 CFC) + filtfilt(padtype=None)\n")
        out.write(",".join(names) + "\n")
        for i in range(len(columns["x"])):
            out.write(",".join(repr(float(columns[n][i])) for n in names) + "\n")


FIXTURE_SETS = [("cfc_reference_10khz.csv", 10000.0, CLASSES, 1), ("cfc_reference_2khz.csv", 2000.0, [60, 180], 2)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="compare with the stored fixtures, write nothing")
    args = parser.parse_args()
    worst = 0.0
    for name, fs, classes, seed in FIXTURE_SETS:
        columns = fixture_rows(fs, classes, seed)
        path = os.path.join(FIXTURES, name)
        if args.check:
            stored = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
            for key, values in columns.items():
                worst = max(worst, float(np.max(np.abs(stored[key] - values))))
        else:
            os.makedirs(FIXTURES, exist_ok=True)
            write(path, columns)
            print(f"wrote {path}: {len(columns['x'])} samples at {fs:g} Hz, classes {classes}")
    if args.check:
        print(f"largest difference from the stored fixtures: {worst:.3g}")
        return 0 if worst <= 1e-12 else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""examples/python/flat_pad_penetration.py runs headless and writes its figure (PNG and SVG) into
a new directory, with the drops' final penetrations as touchdown.drop gives them."""
import os
import subprocess
import sys

import touchdown
from conftest import ROOT

SCRIPT = os.path.join(ROOT, "examples", "python", "flat_pad_penetration.py")


def test_example_writes_the_figure(tmp_path):
    env = {**os.environ, "MPLBACKEND": "Agg"}
    done = subprocess.run([sys.executable, SCRIPT, "--out", str(tmp_path / "fig")], capture_output=True, text=True,
                          env=env, check=False)
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "fig" / "flat_pad_penetration.png", "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    with open(tmp_path / "fig" / "flat_pad_penetration.svg", encoding="utf-8") as f:
        assert "<svg" in f.read()
    lines = done.stdout.splitlines()
    assert len(lines) == 6  # two soils, three speeds
    final_mm = touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0)["final_penetration_m"] * 1e3
    assert f"fjs1_lp 1.0 m/s: final penetration {final_mm:.2f} mm" in lines
    # A second run leaves the first figure as it is and says so.
    png = (tmp_path / "fig" / "flat_pad_penetration.png").read_bytes()
    again = subprocess.run([sys.executable, SCRIPT, "--out", str(tmp_path / "fig")], capture_output=True, text=True,
                           env=env, check=False)
    assert again.returncode == 2 and "exists; not replaced" in again.stderr
    assert (tmp_path / "fig" / "flat_pad_penetration.png").read_bytes() == png

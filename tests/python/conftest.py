"""Shared fixtures of the Python module's tests: the touchdown executable (to compare with the
command line) and the bundled data. CTest sets TOUCHDOWN_BINARY, TOUCHDOWN_DATA_DIR and
PYTHONPATH (tests/CMakeLists.txt); run by hand from the repository root:

    PYTHONPATH=build/python python3 -m pytest tests/python
"""
import json
import os
import subprocess
import sys

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
if not any(os.path.isdir(os.path.join(p, "touchdown")) for p in sys.path if p):
    sys.path.insert(0, os.path.join(ROOT, "build", "python"))
os.environ.setdefault("TOUCHDOWN_DATA_DIR", os.path.join(ROOT, "data"))
DATA = os.environ["TOUCHDOWN_DATA_DIR"]
BINARY = os.environ.get("TOUCHDOWN_BINARY", os.path.join(ROOT, "build", "apps", "touchdown"))


def run_touchdown(*args, cwd=None):
    """Runs the command line (no shell) and returns its stdout; fails the test on a non-zero exit."""
    done = subprocess.run([BINARY, *map(str, args)], cwd=cwd, capture_output=True, text=True, check=False)
    assert done.returncode == 0, f"touchdown {' '.join(map(str, args))}: {done.stderr}"
    return done.stdout


def touchdown_json(*args, cwd=None):
    return json.loads(run_touchdown(*args, cwd=cwd))


def data_file(*parts):
    return os.path.join(DATA, *parts)


@pytest.fixture(scope="session")
def tiny_sweep(tmp_path_factory):
    """A sweep of four rig drops (flat pad, both beds, two speeds) with traces, and its export as
    a dataset: (sweep directory, dataset directory)."""
    root = tmp_path_factory.mktemp("sweep")
    plan = root / "tiny.yaml"
    plan.write_text("schema_version: 1\ntype: sweep\nname: tiny\ntraces: decimated\ntrace_max_samples: 16\n"
                    "fixed: {gravity_m_s2: 9.81}\n"
                    "grid: {pad: [flat], soil: [fjs1_lp, fjs1_cp], impact_speed_m_s: [0.7, 1.0]}\n")
    run_touchdown("sweep", plan, "--out", root / "out", "--threads", 1)
    run_touchdown("export", root / "out", "--to", root / "dataset")
    return root / "out", root / "dataset"

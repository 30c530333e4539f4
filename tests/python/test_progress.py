"""The long calls' progress and Ctrl-C: sweep, stability, trade, diagnose and calibrate_targets
report (done, total) to a callable (or a tqdm bar) from the calling thread, and a SIGINT stops each
of them within about a second with KeyboardInterrupt, the drops already committed kept for a rerun
to resume, with the results an uninterrupted run gives."""
import json
import os
import subprocess
import sys

import pytest

import touchdown
from conftest import data_file

# Tilted pads: free 6-DOF drops, a tenth of a second each (rig drops take a millisecond).
PLAN = ("schema_version: 1\ntype: sweep\nname: many\nfixed: {gravity_m_s2: 9.81, tilt_deg: 5}\n"
        "grid: {pad: [flat, c4], soil: [fjs1_lp, fjs1_cp], impact_speed_m_s: {from: 0.5, to: 1.5, count: %d}}\n"
        "trade: {allowable_final_penetration_mm: 15, allowable_peak_force_N: 400}\n")

# Runs one call in a process of its own; a thread sends it SIGINT (as Ctrl-C does) `delay_s` after
# the call started, and the process prints what came of it as JSON: the exception's type and how
# long after the signal it came, and the last counts the progress callable was given.
INTERRUPTED_CALL = r"""
import json, os, signal, sys, threading, time
import touchdown
function, args, kwargs, delay_s = json.loads(sys.argv[1])
counts, sent = [], []
def send():
    sent.append(time.monotonic())
    os.kill(os.getpid(), signal.SIGINT)
timer = threading.Timer(delay_s, send)
timer.start()
outcome = {"raised": None}
try:
    getattr(touchdown, function)(*args, progress=lambda done, total: counts.append([done, total]), **kwargs)
except BaseException as e:
    outcome = {"raised": type(e).__name__, "message": str(e), "latency_s": time.monotonic() - sent[0] if sent else None}
timer.cancel()
outcome["counts"] = counts[-1] if counts else None
print(json.dumps(outcome))
"""

# Within a second, with room for a machine busy with other work.
LATENCY_BOUND_S = 1.5


def _interrupt(function, *args, delay_s=1.0, **kwargs):
    env = dict(os.environ)
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(touchdown.__file__)))
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [package_parent, env.get("PYTHONPATH")]))
    env["TOUCHDOWN_DATA_DIR"] = touchdown.data_dir()
    request = json.dumps([function, [str(a) for a in args], kwargs, delay_s])
    done = subprocess.run([sys.executable, "-c", INTERRUPTED_CALL, request], capture_output=True, text=True,
                          env=env, timeout=600, check=False)
    assert done.returncode == 0, done.stderr
    outcome = json.loads(done.stdout.strip().splitlines()[-1])
    assert outcome["raised"] == "KeyboardInterrupt", outcome
    assert outcome["latency_s"] < LATENCY_BOUND_S, outcome
    return outcome


def _plan(tmp_path, speeds):
    plan = tmp_path / "plan.yaml"
    plan.write_text(PLAN % speeds)
    return plan


def test_a_callable_is_given_the_counts_up_to_the_total(tmp_path):
    plan = _plan(tmp_path, 3)  # 12 drops
    seen = []
    drops = touchdown.sweep(plan, tmp_path / "out", threads=1, progress=lambda done, total: seen.append((done, total)))
    assert len(drops) == 12
    assert seen[-1] == (12, 12)
    assert all(total == 12 for _, total in seen)
    assert [done for done, _ in seen] == sorted({done for done, _ in seen})  # each change once, rising
    again = []
    touchdown.sweep(plan, tmp_path / "out", threads=1, progress=lambda done, total: again.append((done, total)))
    assert again == [(12, 12)]  # resumed: all done before


# Speeds enough to run for seconds on one thread: 60 drops.
MANY = 15


def test_a_callable_that_raises_stops_the_call_keeping_the_committed_drops(tmp_path):
    plan = _plan(tmp_path, MANY)

    def enough(done, total):
        if done > 0:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="^enough$"):
        touchdown.sweep(plan, tmp_path / "out", threads=1, progress=enough)
    kept = touchdown.read_sweep(tmp_path / "out")
    assert 0 < len(kept) < 4 * MANY and (kept["status"] == "ok").all()


def test_progress_must_be_a_bool_or_a_callable(tmp_path):
    with pytest.raises(ValueError, match=r"^touchdown\.sweep: progress: must be True, False or a callable, got 'yes'$"):
        touchdown.sweep(_plan(tmp_path, 2), tmp_path / "out", progress="yes")
    assert not (tmp_path / "out").exists()


def test_the_bar_is_tqdm_on_stderr_and_nothing_without_tqdm(tmp_path, capsys, monkeypatch):
    pytest.importorskip("tqdm")
    # 60 drops: several seconds even on an idle machine (20 took under the one second after which the
    # bar shows).
    plan = _plan(tmp_path, 15)
    touchdown.sweep(plan, tmp_path / "bar", threads=1, progress=True)
    err = capsys.readouterr().err
    assert "sweep: 100%" in err and "60/60" in err, err
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)  # as if tqdm were not installed
    touchdown.sweep(plan, tmp_path / "none", threads=1, progress=True)
    assert capsys.readouterr().err == ""


def test_ctrl_c_stops_a_sweep_within_a_second_and_a_rerun_resumes_it_bit_identical(tmp_path):
    plan = _plan(tmp_path, MANY)
    outcome = _interrupt("sweep", plan, tmp_path / "stopped", threads=1)
    kept = touchdown.read_sweep(tmp_path / "stopped")
    assert 0 < len(kept) < 4 * MANY and (kept["status"] == "ok").all()
    assert outcome["counts"][0] <= len(kept) and outcome["counts"][1] == 4 * MANY  # then the drops in flight
    resumed = touchdown.sweep(plan, tmp_path / "stopped", threads=2, progress=False)
    assert resumed.attrs["run"]["already_done"] == len(kept)
    assert resumed.attrs["run"]["computed"] == 4 * MANY - len(kept)
    whole = touchdown.sweep(plan, tmp_path / "whole", threads=2, progress=False)
    assert resumed.drop(columns=["seconds"], errors="ignore").equals(whole.drop(columns=["seconds"], errors="ignore"))


def test_ctrl_c_stops_a_trade_writing_no_table(tmp_path):
    _interrupt("trade", _plan(tmp_path, MANY), tmp_path / "trade", threads=1)
    assert 0 < len(touchdown.read_sweep(tmp_path / "trade")) < 4 * MANY
    assert not (tmp_path / "trade" / "trade.csv").exists()


def test_ctrl_c_stops_a_stability_study_before_its_analysis(tmp_path):
    _interrupt("stability", "lab_paper_lander", tmp_path / "study", samples=40, threads=1, delay_s=2.0)
    assert (tmp_path / "study" / "results.sqlite").exists()
    assert not (tmp_path / "study" / "summary.json").exists()


def test_ctrl_c_stops_a_diagnosis_within_a_fit(tmp_path):
    _interrupt("diagnose", data_file("datasets", "air_vs_vacuum_synthetic"), tmp_path / "diagnosis", threads=1,
               pairs=False)
    assert not (tmp_path / "diagnosis").exists()  # nothing written, not even the directory


def test_ctrl_c_stops_a_targets_calibration_within_a_fit(tmp_path):
    outcome = _interrupt("calibrate_targets", data_file("targets", "sutoh2017.yaml"), tmp_path / "model.yaml",
                         threads=1)
    assert outcome["counts"][0] > 0 and outcome["counts"][1] == 0  # evaluations counted, their number not known
    assert not (tmp_path / "model.yaml").exists()

"""touchdown.calibrate, diagnose, trade, synth and export write what the commands write, byte for
byte, and return what the commands print (the same doubles, or the same file's content)."""
import csv
import json
import re

import pytest
import yaml

import touchdown
from conftest import data_file, run_touchdown

MEASURED = data_file("datasets", "air_vs_vacuum_synthetic")


def _json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def test_calibrate_equals_the_command_line(tmp_path):
    printed = run_touchdown("calibrate", MEASURED, "--out", tmp_path / "cli.yaml", "--atmosphere", "vacuum")
    fit = touchdown.calibrate(MEASURED, tmp_path / "py.yaml", atmosphere="vacuum")
    # The model files are the same but for their name (the file's stem).
    cli = (tmp_path / "cli.yaml").read_text().replace("cli", "NAME")
    assert (tmp_path / "py.yaml").read_text().replace("py", "NAME") == cli
    assert fit["law"] == "rft"
    assert [f["group"] for f in fit["fits"]] == ["fjs1_cp", "fjs1_lp"]
    for f in fit["fits"]:
        # The command prints each fit rounded: "fjs1_lp: zeta = 2.1234 N/cm^3, 95 % interval [a, b] from N drops".
        line = re.search(re.escape(f["group"]) + r": zeta = (\S+) N/cm\^3, 95 % interval \[(\S+), (\S+)\] from (\d+) drops, "
                         r"(\d+) samples", printed)
        assert line, printed
        assert float(line.group(1)) == pytest.approx(f["zeta_N_cm3"], abs=5e-5)
        assert float(line.group(2)) == pytest.approx(f["low_N_cm3"], abs=5e-5)
        assert float(line.group(3)) == pytest.approx(f["high_N_cm3"], abs=5e-5)
        assert (int(line.group(4)), int(line.group(5))) == (f["drops"], f["samples"])
        assert f["low_N_cm3"] < f["zeta_N_cm3"] < f["high_N_cm3"]
    # The model file holds the returned doubles, as it writes them (10 significant digits).
    model = yaml.safe_load((tmp_path / "py.yaml").read_text())
    for f in fit["fits"]:
        assert model["soils"][f["group"]]["zeta_N_cm3"] == float(f"{f['zeta_N_cm3']:.10g}")


def test_calibrate_report_equals_the_command_line(tmp_path):
    # The report of a dataset calibration: each soil's zeta with its variance, as a study draws it.
    run_touchdown("calibrate", MEASURED, "--out", tmp_path / "cli.yaml", "--report", tmp_path / "cli.json")
    report = touchdown.calibrate(MEASURED, tmp_path / "py.yaml", report=tmp_path / "py.json")
    assert json.loads((tmp_path / "py.json").read_text().replace("py.", "X.")) == \
        json.loads((tmp_path / "cli.json").read_text().replace("cli.", "X."))
    assert report["command"] == json.loads((tmp_path / "py.json").read_text())["command"]
    covariance = report["covariance"]
    assert [p["soil"] for p in covariance["parameters"]] == [f["group"] for f in report["fits"]]
    for k, f in enumerate(report["fits"]):
        assert covariance["parameters"][k]["value"] == f["zeta_N_cm3"]
        assert covariance["matrix"][k][k] == f["standard_error_N_cm3"] ** 2
    with pytest.raises(ValueError, match="per soil"):
        touchdown.calibrate(MEASURED, tmp_path / "all.yaml", per="all", report=tmp_path / "all.json")


def test_calibrate_bekker_equals_the_command_line(tmp_path):
    args = ("--law", "bekker", "--soil", "fjs1_lp", "--atmosphere", "vacuum", "--shear-from", "fjs1_lp_bekker")
    printed = run_touchdown("calibrate", MEASURED, "--out", tmp_path / "soil.yaml", *args)
    (tmp_path / "cli").mkdir()
    (tmp_path / "soil.yaml").rename(tmp_path / "cli" / "soil.yaml")
    fit = touchdown.calibrate(MEASURED, tmp_path / "soil.yaml", law="bekker", soil="fjs1_lp", atmosphere="vacuum",
                              shear_from="fjs1_lp_bekker")
    assert (tmp_path / "soil.yaml").read_bytes() == (tmp_path / "cli" / "soil.yaml").read_bytes()
    assert fit["law"] == "bekker" and fit["soils"] == ["fjs1_lp"] and fit["k_c_kN_m_n1"] == 0.0
    line = re.search(r"n = (\S+), k_c = \S+ kN/m\^\(n\+1\), k_phi = (\S+) kN/m\^\(n\+2\) from (\d+) drops, (\d+) samples",
                     printed)
    assert line, printed
    assert float(line.group(1)) == pytest.approx(fit["n"], rel=5e-4)
    assert float(line.group(2)) == pytest.approx(fit["k_phi_kN_m_n2"], rel=5e-4)
    assert (int(line.group(3)), int(line.group(4))) == (fit["drops"], fit["samples"])
    soil = yaml.safe_load((tmp_path / "soil.yaml").read_text())
    assert soil["bekker"]["n"] == pytest.approx(fit["n"], rel=1e-9)


def test_calibrate_refuses_bad_arguments(tmp_path):
    with pytest.raises(ValueError, match="touchdown.calibrate: law: must be rft or bekker, got 'rtf'"):
        touchdown.calibrate(MEASURED, tmp_path / "m.yaml", law="rtf")
    with pytest.raises(ValueError, match="atmosphere"):
        touchdown.calibrate(MEASURED, tmp_path / "m.yaml", atmosphere="argon")
    (tmp_path / "mine.yaml").write_text("a file of the user's\n")
    with pytest.raises(ValueError, match="mine.yaml"):
        touchdown.calibrate(MEASURED, tmp_path / "mine.yaml")
    assert (tmp_path / "mine.yaml").read_text() == "a file of the user's\n"


def _without_seconds(summary):
    return {k: v for k, v in summary.items() if k != "seconds"}


SYNTH_SPEC = ("schema_version: 1\ntype: synth\nname: tiny_synth\ndescription: two drops\nseed: 7\n"
              "sample_rate_hz: 1000\nrest_duration_s: 0.01\ntrials: 1\n"
              "drops:\n  - {pads: [flat], soils: [fjs1_lp], atmospheres: [air, vacuum], impact_speeds_m_s: [1.0]}\n"
              "noise: {force_sigma_N: 1.5, penetration_sigma_mm: 0.03}\n"
              "hidden_effect: {id: gas_cushion, chi: 0.3, c_g_N_s_m3: 3000}\n"
              "provenance: {all: 'assumption: a test'}\n")


@pytest.mark.parametrize("sampling", ["instantaneous", "period_mean"])
def test_diagnose_equals_the_command_line(tmp_path, sampling):
    # Six synthetic drops with a gas cushion in air: a second each (the bundled 24 take five),
    # recorded and compared through either sensor.
    spec = tmp_path / "synth.yaml"
    spec.write_text(SYNTH_SPEC.replace("impact_speeds_m_s: [1.0]", "impact_speeds_m_s: [0.7, 1.0, 1.5]")
                    + f"sensor_sampling: {sampling}\n")
    run_touchdown("synth", spec, "--out", tmp_path / "measured")
    args = ("--no-pairs", "--threads", "2", "--sensor-sampling", sampling)
    run_touchdown("diagnose", tmp_path / "measured", "--out", tmp_path / "cli", *args)
    py = touchdown.diagnose(tmp_path / "measured", tmp_path / "py", pairs=False, threads=2, sensor_sampling=sampling)
    assert _without_seconds(py) == _without_seconds(_json(tmp_path / "cli" / "diagnosis.json"))
    assert py == _json(tmp_path / "py" / "diagnosis.json")
    assert py["named_effect"] == "gas_cushion"
    assert (tmp_path / "py" / "model.yaml").read_bytes() == (tmp_path / "cli" / "model.yaml").read_bytes()


def test_diagnose_base_bekker_equals_the_command_line(tmp_path):
    # Python's `base` is the command line's --base, parsed by the same function.
    spec = tmp_path / "synth.yaml"
    spec.write_text(SYNTH_SPEC.replace("impact_speeds_m_s: [1.0]", "impact_speeds_m_s: [0.7, 1.0, 1.5]"))
    run_touchdown("synth", spec, "--out", tmp_path / "measured")
    run_touchdown("diagnose", tmp_path / "measured", "--out", tmp_path / "cli", "--no-pairs", "--threads", "2",
                  "--base", "bekker")
    py = touchdown.diagnose(tmp_path / "measured", tmp_path / "py", pairs=False, threads=2, base="bekker")
    assert _without_seconds(py) == _without_seconds(_json(tmp_path / "cli" / "diagnosis.json"))
    rft = touchdown.diagnose(tmp_path / "measured", tmp_path / "rft", pairs=False, threads=2)
    assert _without_seconds(py) != _without_seconds(rft)  # the base changed the fit
    assert (tmp_path / "py" / "model.yaml").read_bytes() == (tmp_path / "cli" / "model.yaml").read_bytes()


def test_diagnose_fit_on_equals_the_command_line(tmp_path):
    # Python's `fit_on` is the command line's --fit-on: fitted on the two drops at 1.0 m/s, the other
    # four are held out and predicted.
    spec = tmp_path / "synth.yaml"
    spec.write_text(SYNTH_SPEC.replace("impact_speeds_m_s: [1.0]", "impact_speeds_m_s: [0.7, 1.0, 1.5]"))
    run_touchdown("synth", spec, "--out", tmp_path / "measured")
    with open(tmp_path / "measured" / "drops.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    fit_on = [r["drop_id"] for r in rows if float(r["impact_speed_m_s"]) == 1.0]
    assert len(fit_on) == 2
    run_touchdown("diagnose", tmp_path / "measured", "--out", tmp_path / "cli", "--no-pairs", "--threads", "2",
                  "--fit-on", ",".join(fit_on))
    py = touchdown.diagnose(tmp_path / "measured", tmp_path / "py", pairs=False, threads=2, fit_on=fit_on)
    assert _without_seconds(py) == _without_seconds(_json(tmp_path / "cli" / "diagnosis.json"))
    assert sorted(py["split"]["train"]) == sorted(fit_on)
    assert sorted(py["split"]["held_out"]) == sorted(r["drop_id"] for r in rows if r["drop_id"] not in fit_on)
    assert py["split"]["rule"].startswith("--fit-on")


def test_diagnose_floor_from_base_equals_the_command_line(tmp_path):
    # Two trials of six conditions: a floor from the replicates (6 degrees of freedom). Python's
    # `floor_from_base` is --floor-from-base: the floor read from the base's residuals alone; and
    # `count_stop_samples` is --count-stop-samples: every sample in the force residual; and
    # `search_within_floor` is --search-within-floor (accepted by both; one term here, so no search);
    # `rig_offsets="candidate"` is --rig-offsets candidate: the common offsets leave the base and
    # are a candidate of their own; `refit_drops=False` is --no-refit-drops: the training drops'
    # nuisances as the joint fit left them.
    spec = tmp_path / "synth.yaml"
    spec.write_text(SYNTH_SPEC.replace("impact_speeds_m_s: [1.0]", "impact_speeds_m_s: [0.7, 1.0, 1.5]")
                    .replace("trials: 1", "trials: 2"))
    run_touchdown("synth", spec, "--out", tmp_path / "measured")
    run_touchdown("diagnose", tmp_path / "measured", "--out", tmp_path / "cli", "--no-pairs", "--threads", "2",
                  "--floor-from-base", "--count-stop-samples", "--search-within-floor", "--rig-offsets", "candidate",
                  "--no-refit-drops")
    py = touchdown.diagnose(tmp_path / "measured", tmp_path / "py", pairs=False, threads=2, floor_from_base=True,
                            count_stop_samples=True, search_within_floor=True, rig_offsets="candidate",
                            refit_drops=False)
    assert _without_seconds(py) == _without_seconds(_json(tmp_path / "cli" / "diagnosis.json"))
    assert py["floor"]["source"] == "replicates (pure error)"
    assert py["floor"]["read_from_model"] == "base"
    assert py["floor"]["force_nrmse_upper_95"] >= py["floor"]["force_nrmse"]
    assert py["stop_samples_skipped"] is False
    assert not any(k.startswith("sensor_offset.") for k in py["rig_parameters"])
    assert any(c["effect"] == "sensor_offset" for c in py["candidates"])


TRADE_PLAN = ("schema_version: 1\ntype: sweep\nname: tiny_trade\nfixed: {gravity_m_s2: 9.81}\n"
              "grid: {pad: [flat, c4], soil: [fjs1_lp], impact_speed_m_s: [1.0]}\n"
              "trade: {allowable_final_penetration_mm: 15, allowable_peak_force_N: 400}\n")


def test_trade_equals_the_command_line(tmp_path):
    plan = tmp_path / "trade.yaml"
    plan.write_text(TRADE_PLAN)
    run_touchdown("trade", plan, "--out", tmp_path / "cli", "--threads", 1)
    py = touchdown.trade(plan, tmp_path / "py", threads=1)
    run = py.pop("run")
    assert (run["total"], run["computed"], run["failed"]) == (2, 2, 0)
    assert py == _json(tmp_path / "cli" / "summary.json") == _json(tmp_path / "py" / "summary.json")
    assert (tmp_path / "py" / "trade.csv").read_bytes() == (tmp_path / "cli" / "trade.csv").read_bytes()
    again = touchdown.trade(plan, tmp_path / "py", threads=1)  # resumes: nothing left to run
    assert again.pop("run")["already_done"] == 2 and again == py


def test_synth_equals_the_command_line(tmp_path):
    spec = tmp_path / "synth.yaml"
    spec.write_text(SYNTH_SPEC)
    printed = run_touchdown("synth", spec, "--out", tmp_path / "cli")
    drops = touchdown.synth(spec, tmp_path / "py")
    assert "(2 drops, hidden effect gas_cushion)" in printed
    assert drops.attrs["synth"] == {"drops": 2, "hidden_effect": "gas_cushion"}
    assert len(drops) == 2 and set(drops["atmosphere"]) == {"air", "vacuum"}
    for name in ["drops.csv", *drops["trace"]]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name


def test_export_equals_the_command_line(tiny_sweep, tmp_path):
    out, dataset = tiny_sweep  # the fixture exported it with the command line
    counts = touchdown.export(out, tmp_path / "py")
    assert counts == {"exported": 4, "failed": 0, "resimulated": 0, "lander": False}
    assert (tmp_path / "py" / "drops.csv").read_bytes() == (dataset / "drops.csv").read_bytes()
    for trace in touchdown.read_dataset(tmp_path / "py")["trace"]:
        assert (tmp_path / "py" / trace).read_bytes() == (dataset / trace).read_bytes()
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("the user's\n")
    with pytest.raises(ValueError, match="mine"):
        touchdown.export(out, tmp_path / "mine")  # a directory of the user's is never written into
    assert sorted(p.name for p in (tmp_path / "mine").iterdir()) == ["notes.txt"]


TINY_TARGETS = ("schema_version: 1\ntype: targets\nname: tiny_targets\nparameters:\n"
                "  - {name: zeta_lp, soil: fjs1_lp, field: zeta_N_cm3, lower: 1.0, upper: 8.0, start: 2.0, source: test}\n"
                "targets:\n"
                "  - {name: depth, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_penetration_m,"
                " value: 0.009, uncertainty: 0.0005, use: fit, source: test}\n"
                "  - {name: force, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: peak_force_N,"
                " at_most: 1000, uncertainty: 10, use: predict, source: test}\n")


def test_calibrate_targets_equals_the_command_line(tmp_path):
    targets = tmp_path / "t.yaml"
    targets.write_text(TINY_TARGETS)
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    run_touchdown("calibrate", "--targets", targets, "--out", tmp_path / "cli" / "m.yaml",
                  "--report", tmp_path / "cli" / "r.json", "--threads", "1")
    report = touchdown.calibrate_targets(targets, tmp_path / "py" / "m.yaml", report=tmp_path / "py" / "r.json",
                                         threads=1)
    # The model files are the same but for the directory they name (how to apply the other parameters).
    cli = (tmp_path / "cli" / "m.yaml").read_text().replace(str(tmp_path / "cli"), "DIR")
    assert (tmp_path / "py" / "m.yaml").read_text().replace(str(tmp_path / "py"), "DIR") == cli
    # So are the reports (their "command" names the files it wrote).
    assert ((tmp_path / "py" / "r.json").read_text().replace(str(tmp_path / "py"), "DIR") ==
            (tmp_path / "cli" / "r.json").read_text().replace(str(tmp_path / "cli"), "DIR"))
    # The returned report is the written one (which opens with its "written_by" mark).
    written = _json(tmp_path / "py" / "r.json")
    assert {k: v for k, v in written.items() if k != "written_by"} == report
    fitted = [t for t in report["targets"] if t["use"] == "fit"]
    assert len(fitted) == 1 and abs(fitted[0]["residual"]) < 1e-6


def test_validate_equals_the_command_line(tmp_path):
    run_touchdown("validate", "--out", tmp_path / "cli")
    result = touchdown.validate(out=tmp_path / "py")
    assert result == _json(tmp_path / "cli" / "validation.json")
    assert (tmp_path / "py" / "validation.md").read_bytes() == (tmp_path / "cli" / "validation.md").read_bytes()
    assert touchdown.validate() == result  # without out: nothing written, the same numbers
    with pytest.raises(ValueError, match="not a directory of validation sources"):
        touchdown.validate(sources=tmp_path / "missing")


def test_version_is_the_projects():
    """touchdown.__version__ is the CMake project's version, the one `touchdown --version` prints."""
    assert re.fullmatch(r"\d+\.\d+\.\d+", touchdown.__version__)
    assert run_touchdown("--version").strip() == "touchdown " + touchdown.__version__


def test_bundled_inputs_run_by_name(tmp_path, monkeypatch):
    """A workflow's input given by a bundled name, as `touchdown lander lander_case_B` takes it."""
    monkeypatch.chdir(tmp_path)  # no file of that name here
    by_name = json.loads(json.dumps(touchdown.lander("lander_case_B", vtk=False)))
    by_path = json.loads(json.dumps(touchdown.lander(data_file("scenarios", "lander_case_B.yaml"), vtk=False)))
    assert by_name == by_path
    with pytest.raises(ValueError, match=r"lunar_paper_lander_scenario: no such file, nor a bundled name "
                                         r"\(did you mean 'lunar_paper_lander'\?\)"):
        touchdown.stability("lunar_paper_lander_scenario", tmp_path / "out")

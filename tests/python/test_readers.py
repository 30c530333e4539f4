"""The readers give pandas DataFrames of a sweep database, a dataset and a stability study, with
the formats' columns and one row per drop or landing, numbers as written."""
import json

import numpy as np
import pandas as pd
import pytest

import touchdown
from conftest import data_file, run_touchdown, touchdown_json

SWEEP_COLUMNS = ["drop_index", "drop_id", "status", "failure", "pad", "soil", "atmosphere", "impact_speed_m_s",
                 "pad_mass_kg", "gravity_m_s2", "tilt_deg", "horizontal_speed_m_s", "zeta_N_cm3",
                 "final_penetration_m", "peak_force_N", "time_to_rest_s", "drop_kind", "tipped_over"]


def test_read_sweep_gives_one_row_per_drop(tiny_sweep):
    out, _ = tiny_sweep
    drops = touchdown.read_sweep(out)
    assert isinstance(drops, pd.DataFrame)
    assert len(drops) == 4
    assert set(SWEEP_COLUMNS) <= set(drops.columns)
    assert list(drops["drop_index"]) == [0, 1, 2, 3]
    assert set(drops["status"]) == {"ok"} and set(drops["drop_kind"]) == {"rig"}
    assert drops.attrs["meta"]["sweep_name"] == "tiny"
    assert drops["tipped_over"].isna().all()  # a lander column: NULL for rig drops
    # The database's metric is the drop's own: the same doubles as touchdown.drop gives.
    row = drops[(drops["soil"] == "fjs1_lp") & (drops["impact_speed_m_s"] == 1.0)].iloc[0]
    summary = touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0)
    assert row["final_penetration_m"] == summary["final_penetration_m"]
    assert row["peak_force_N"] == summary["peak_force_N"]


def test_read_sweep_traces(tiny_sweep):
    out, _ = tiny_sweep
    drops, traces = touchdown.read_sweep(out / "results.sqlite", traces=True)
    assert sorted(traces) == list(drops["drop_index"])
    for index, trace in traces.items():
        assert list(trace.columns) == ["t_s", "penetration_m", "velocity_m_s", "force_N"]
        assert 2 <= len(trace) <= 16
        assert np.all(np.diff(trace["t_s"]) > 0)
        final = drops.loc[drops["drop_index"] == index, "final_penetration_m"].iloc[0]
        assert abs(trace["penetration_m"].iloc[-1] - final) < 1e-6 * final


def test_read_dataset_gives_the_exported_drops(tiny_sweep):
    out, dataset = tiny_sweep
    drops, traces = touchdown.read_dataset(dataset, traces=True)
    assert list(drops.columns[:8]) == ["drop_id", "pad", "soil", "atmosphere", "impact_speed_m_s", "pad_mass_kg",
                                       "gravity_m_s2", "trace"]
    assert len(drops) == 4 and len(traces) == 4
    # Written in shortest round-trip form, read back exactly: the database's doubles.
    sweep = touchdown.read_sweep(out)
    assert list(drops["final_penetration_m"]) == list(sweep["final_penetration_m"])
    for trace in traces.values():
        assert list(trace.columns[:3]) == ["t_s", "penetration_m", "force_N"]
    assert len(touchdown.read_dataset(dataset)) == 4


def test_read_stability_gives_summary_tables_and_landings(tmp_path):
    # Four slow, level landings of the paper's lander (case A) on a 2 x 2 map: none tips over.
    study = tmp_path / "study.yaml"
    study.write_text("schema_version: 1\ntype: stability\nname: tiny\n"
                     f"lander: {{scenario: {data_file('scenarios', 'lander_case_A.yaml')}}}\n"
                     "grid: {impact_speed_m_s: [0.6, 1.0], horizontal_speed_m_s: [0, 0.2]}\n"
                     "study: {map: {x: impact_speed_m_s, y: horizontal_speed_m_s, bins: [2, 2]}}\n")
    run_touchdown("stability", study, "--out", tmp_path / "out")
    result = touchdown.read_stability(tmp_path / "out")
    assert result.summary["landings"] == 4 and result.summary["tipped_over"] == 0
    assert list(result.percentiles.columns) == ["metric", "unit", "landings", "p50", "p95", "p99", "max"]
    assert "max_tilt_deg" in set(result.percentiles["metric"])
    assert list(result.tip_over_map.columns[:4]) == ["impact_speed_m_s_low", "impact_speed_m_s_high",
                                                     "horizontal_speed_m_s_low", "horizontal_speed_m_s_high"]
    assert len(result.tip_over_map) == 4 and list(result.tip_over_map["landings"]) == [1, 1, 1, 1]
    assert len(result.landings) == 4 and set(result.landings["drop_kind"]) == {"lander"}
    assert list(result.landings["tipped_over"]) == [0.0] * 4
    # The table's numbers are the database's, read back exactly.
    p_max = result.percentiles.set_index("metric").loc["max_tilt_deg", "max"]
    assert p_max == result.landings["max_tilt_deg"].max()


def test_sweep_from_python_equals_the_command_lines(tiny_sweep, tmp_path):
    out, _ = tiny_sweep
    drops = touchdown.sweep(out.parent / "tiny.yaml", tmp_path / "py", threads=2)
    assert drops.attrs["run"]["computed"] == 4 and drops.attrs["run"]["failed"] == 0
    pd.testing.assert_frame_equal(drops, touchdown.read_sweep(out), check_exact=True)
    # A rerun resumes: nothing left to compute.
    assert touchdown.sweep(out.parent / "tiny.yaml", tmp_path / "py").attrs["run"]["computed"] == 0


def test_stability_from_python_writes_the_study(tmp_path):
    study = tmp_path / "study.yaml"
    study.write_text("schema_version: 1\ntype: stability\nname: level\n"
                     f"lander: {{scenario: {data_file('scenarios', 'lander_case_A.yaml')}}}\n"
                     "grid: {impact_speed_m_s: [0.8]}\n")
    result = touchdown.stability(study, tmp_path / "out", threads=1)
    assert result.summary["landings"] == 1 and result.tip_over_map is None
    assert len(result.landings) == 1 and result.landings["tipped_over"].iloc[0] == 0.0


def test_read_sweep_types_missing_metrics_and_meta(tiny_sweep):
    out, _ = tiny_sweep
    drops = touchdown.read_sweep(out)
    # Lander metrics of a rig sweep are NULL in every row: float columns of NaN, not None objects.
    for column in ["tipped_over", "max_tilt_deg", "pad1_final_penetration_m", "final_roll_deg"]:
        assert drops[column].dtype == np.float64, column
        assert drops[column].isna().all(), column
    meta = drops.attrs["meta"]
    assert meta["format_version"] == 8 and isinstance(meta["format_version"], int)
    assert meta["total_drops"] == 4 and isinstance(meta["total_drops"], int)
    assert isinstance(meta["max_drop_wall_time_s"], float)
    assert meta["load_dependent_failures"] is False
    assert isinstance(meta["plan_digest"], str) and isinstance(meta["shard"], str)


def test_read_sweep_separates_rig_and_lander_columns(tiny_sweep, tmp_path):
    out, _ = tiny_sweep
    drops = touchdown.read_sweep(out)
    rig, lander = drops.attrs["rig_columns"], drops.attrs["lander_columns"]
    assert sorted(rig + lander) == sorted(drops.columns) and not set(rig) & set(lander)
    assert rig == [c for c in drops.columns if c in rig]  # in table order
    assert {"drop_index", "status", "impact_speed_m_s", "final_penetration_m", "peak_force_N"} <= set(rig)
    assert {"tipped_over", "max_tilt_deg", "pad1_final_penetration_m", "pad4_soil", "ground_case"} <= set(lander)
    assert set(touchdown.readers.LANDER_COLUMNS) == set(lander)  # the list names the table's columns
    # The split follows the data: a rig drop leaves every lander column empty and fills every rig
    # column but the failure's.
    empty = drops.isna() | (drops == "")
    assert empty[lander].all(axis=None)
    assert list(empty[rig].all()[lambda filled: filled].index) == ["failure", "failure_limit", "failure_limit_value"]
    # kind="rig": the rig drops without the lander columns (all NaN or "" in a rig drop's row).
    only_rig = touchdown.read_sweep(out, kind="rig")
    assert list(only_rig.columns) == rig and only_rig.attrs["lander_columns"] == []
    pd.testing.assert_frame_equal(only_rig, drops[rig], check_exact=True)
    assert len(touchdown.read_sweep(out, kind="lander")) == 0
    only_rig, traces = touchdown.read_sweep(out, traces=True, kind="rig")
    assert sorted(traces) == [0, 1, 2, 3]
    with pytest.raises(ValueError, match="kind: must be 'rig', 'lander' or None, got 'free'"):
        touchdown.read_sweep(out, kind="free")
    # A lander sweep (a stability study's landings): kind="lander" keeps every column, filled.
    study = tmp_path / "study.yaml"
    study.write_text("schema_version: 1\ntype: stability\nname: level\n"
                     f"lander: {{scenario: {data_file('scenarios', 'lander_case_A.yaml')}}}\n"
                     "grid: {impact_speed_m_s: [0.8]}\n")
    touchdown.stability(study, tmp_path / "out", threads=1)
    landings = touchdown.read_sweep(tmp_path / "out", kind="lander")
    assert len(landings) == 1 and list(landings.columns) == list(touchdown.read_sweep(tmp_path / "out").columns)
    assert landings[["tipped_over", "max_tilt_deg", "pad1_final_penetration_m"]].notna().all(axis=None)
    assert len(touchdown.read_sweep(tmp_path / "out", kind="rig")) == 0


# The paper's lander with 16-segment pads for 1 s.
COARSE_LANDER = data_file("studies", "lab_coarse_lander_scenario.yaml")


def test_stability_subset_method_from_python_is_the_cli_run(tmp_path):
    # The rare-event path of touchdown.stability(method=...) writes what `touchdown stability
    # --method subset` writes: the same estimate, interval and design points, to the bit.
    study = tmp_path / "study.yaml"
    study.write_text("schema_version: 1\ntype: stability\nname: rare\n"
                     f"lander: {{scenario: {COARSE_LANDER}}}\n"
                     "fixed: {downhill_azimuth_deg: -90, yaw_relative_to_slope_deg: 90, horizontal_azimuth_deg: -90}\n"
                     "random: {samples: 10, seed: 5, slope_deg: {uniform: [0, 20]},\n"
                     "         horizontal_speed_m_s: {uniform: [0, 1.5]}}\n")
    result = touchdown.stability(study, tmp_path / "py", samples=10, threads=2, progress=False, method="subset")
    run_touchdown("stability", str(study), "--out", str(tmp_path / "cli"), "--method", "subset", "--samples", "10",
                  "--threads", "2", "--progress", "none")
    cli = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert result.summary["method"] == "subset"
    for key in ["tip_over_probability", "tip_over_probability_interval_95", "interval_method"]:
        assert result.summary[key] == cli[key], key
    assert result.summary["rare_event"]["design_points"] == cli["rare_event"]["design_points"]
    assert result.summary["rare_event"]["landings_spent"] == cli["rare_event"]["landings_spent"] > 10
    assert len(result.landings) == cli["rare_event"]["landings_spent"]  # every level's, from py/subset/
    assert set(result.landings["run"]) == {"subset"}
    with pytest.raises(ValueError, match="method: "):
        touchdown.stability(study, tmp_path / "bad", method="subsets")

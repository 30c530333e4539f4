"""touchdown.lander gives the summary `touchdown lander` prints, and writes the same outputs."""
import json
import os

import pytest

import touchdown
from conftest import data_file, touchdown_json


def test_lander_summary_equals_the_command_line_json(tmp_path):
    scenario = data_file("scenarios", "lander_case_A.yaml")
    cli = touchdown_json("lander", scenario, "--out", tmp_path / "cli")
    assert touchdown.lander(scenario) == cli
    # With out=: the same files, the summary among them.
    assert touchdown.lander(scenario, out=tmp_path / "py") == cli
    assert sorted(os.listdir(tmp_path / "py")) == sorted(os.listdir(tmp_path / "cli"))
    with open(tmp_path / "py" / "summary.json", encoding="utf-8") as f:
        assert json.load(f) == cli


def test_lander_never_writes_into_an_existing_directory(tmp_path):
    (tmp_path / "mine.txt").write_text("a user's file")
    with pytest.raises(ValueError, match=str(tmp_path)):
        touchdown.lander(data_file("scenarios", "lander_case_A.yaml"), out=tmp_path)
    assert os.listdir(tmp_path) == ["mine.txt"]


def test_a_missing_scenario_raises_file_not_found_naming_it(tmp_path):
    missing = tmp_path / "nope.yaml"
    with pytest.raises(FileNotFoundError, match="nope.yaml"):
        touchdown.lander(missing)


def test_lander_trace_arrays_match_the_trace_csv(tmp_path):
    np = pytest.importorskip("numpy")
    summary, trace = touchdown.lander(data_file("scenarios", "lander_case_B.yaml"), out=tmp_path / "b", trace=True)
    with open(tmp_path / "b" / "trace.csv", encoding="utf-8") as f:
        header = f.readline().strip().split(",")
        rows = [line.strip().split(",") for line in f]
    assert list(trace) == header  # same columns, same order
    for k, name in enumerate(header):
        array = trace[name]
        assert isinstance(array, np.ndarray) and array.dtype == np.float64
        # trace.csv holds 10 significant digits: the arrays, printed so, give every cell's text.
        assert ["%.10g" % v for v in array] == [row[k] for row in rows], name
    assert [trace["depth%d_m" % i][-1] for i in range(1, 5)] == pytest.approx(summary["final_penetration_m"], rel=1e-9)

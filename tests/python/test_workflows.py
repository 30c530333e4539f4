"""touchdown.campaign and touchdown.compare write what the commands write and return their
summary.json."""
import json

import pytest

import touchdown
from conftest import data_file, run_touchdown


def _summary(directory):
    with open(directory / "summary.json", encoding="utf-8") as f:
        return json.load(f)


def test_campaign_equals_the_command_line(tmp_path):
    scenario = data_file("scenarios", "sutoh2017_single_footpad.yaml")
    run_touchdown("campaign", scenario, "--out", tmp_path / "cli")
    py = touchdown.campaign(scenario, tmp_path / "py")
    assert py == _summary(tmp_path / "cli")
    assert py == _summary(tmp_path / "py")
    assert (tmp_path / "py" / "plots" / "fig3_time_histories.svg").is_file()


def test_compare_equals_the_command_line(tmp_path):
    measured = data_file("datasets", "air_vs_vacuum_synthetic")
    run_touchdown("compare", measured, "--out", tmp_path / "cli")
    py = touchdown.compare(measured, tmp_path / "py")
    assert py == _summary(tmp_path / "cli")
    assert (tmp_path / "py" / "plots" / "parity.png").is_file()
    with pytest.raises(ValueError):
        touchdown.compare(measured, tmp_path / "both", simulated=tmp_path / "cli", model="m.yaml")

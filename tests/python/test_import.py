"""touchdown.import_raw: the shipped raw example imported as the command line imports it, the
summary in df.attrs, and a bad file refused with the command line's one-line message, nothing
written."""
import os
import shutil

import pytest

import touchdown
from conftest import data_file, touchdown_json

EXAMPLE = data_file("datasets", "rig_daq_synthetic_raw", "import.yaml")


def test_import_equals_the_command_line(tmp_path):
    printed = touchdown_json("import", EXAMPLE, "--out", tmp_path / "cli")
    drops = touchdown.import_raw(EXAMPLE, tmp_path / "py")
    made = drops.attrs["import"]
    assert made["drops"] == printed["drops"] == len(drops) == 12
    assert made["per_drop"] == printed["per_drop"]
    assert made["name"] == "rig_daq_synthetic" and made["penetration_from"] == "displacement"
    assert set(drops["data_origin"]) == {"synthetic"}
    assert (drops["touchdown_uncertainty_s"] > 0).all() and (drops["pretrigger_s"] > 0.005).all()
    for name in ["drops.csv", "README.md", "import.yaml", *drops["trace"]]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name


def test_a_bad_cell_is_refused_and_nothing_written(tmp_path):
    shutil.copytree(os.path.dirname(EXAMPLE), tmp_path / "set")
    raw = tmp_path / "set" / "raw" / "c4_lp_vac_v1.00_r1.csv"
    lines = raw.read_text().splitlines(keepends=True)
    lines[6] = lines[6].replace(",", ",x", 1)  # line 7: the force's cell no longer a number
    raw.write_text("".join(lines))
    with pytest.raises(ValueError, match=r"c4_lp_vac_v1\.00_r1\.csv: line 7, column 2 \(LoadCell\): not a finite number"):
        touchdown.import_raw(tmp_path / "set" / "import.yaml", tmp_path / "out")
    assert not (tmp_path / "out").exists()
    with pytest.raises(FileNotFoundError):
        touchdown.import_raw(tmp_path / "none.yaml", tmp_path / "out")

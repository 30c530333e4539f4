"""touchdown.drop and touchdown.force give what the command line prints, bit for bit; traces as
NumPy arrays match the trace CSV; pads and soils as names, files or dicts; errors as ValueError."""
import csv

import numpy as np
import pytest
import yaml

import touchdown
from conftest import data_file, run_touchdown, touchdown_json


@pytest.mark.parametrize("cli, kwargs", [
    (["--pad", "flat", "--soil", "fjs1_lp", "--speed", "1.0"], dict(pad="flat", soil="fjs1_lp", speed=1.0)),
    (["--pad", "curved", "--soil", "fjs1_cp", "--speed", "1.5", "--zeta", "2.1", "--gravity", "1.62"],
     dict(pad="curved", soil="fjs1_cp", speed=1.5, zeta=2.1, gravity=1.62)),
    (["--pad", "c4", "--soil", "fjs1_lp", "--speed", "0.7", "--mass", "3.0"],
     dict(pad="c4", soil="fjs1_lp", speed=0.7, mass=3.0)),
    (["--pad", "flat", "--soil", "fjs1_lp", "--speed", "1.0", "--free", "--tilt-deg", "5", "--horizontal-speed",
      "0.2", "--omega", "0,0.5,0"],
     dict(pad="flat", soil="fjs1_lp", speed=1.0, free=True, tilt_deg=5.0, horizontal_speed=0.2, omega=(0, 0.5, 0))),
    (["--pad", "curved", "--soil", "fjs1_lp", "--speed", "1.0", "--free", "--tilt-deg", "10", "--horizontal-speed",
      "0.3", "--fast"],
     dict(pad="curved", soil="fjs1_lp", speed=1.0, free=True, tilt_deg=10.0, horizontal_speed=0.3, fast=True)),
])
def test_drop_equals_the_command_line_json(cli, kwargs):
    # Dicts compare their floats exactly: both sides are the same doubles (JSON numbers are
    # written in shortest round-trip form).
    assert touchdown.drop(**kwargs) == touchdown_json("drop", *cli)


def _csv_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [row[i] for row in rows[1:]] for i, name in enumerate(rows[0])}, rows[0]


@pytest.mark.parametrize("extra_cli, extra_kwargs", [
    ([], {}),
    (["--free", "--tilt-deg", "3"], dict(free=True, tilt_deg=3.0)),
])
def test_trace_arrays_match_the_trace_csv(tmp_path, extra_cli, extra_kwargs):
    csv_path = tmp_path / "trace.csv"
    run_touchdown("drop", "--pad", "flat", "--soil", "fjs1_cp", "--speed", "0.7", "--trace", csv_path, *extra_cli)
    summary, trace = touchdown.drop(pad="flat", soil="fjs1_cp", speed=0.7, trace=True, **extra_kwargs)
    columns, header = _csv_columns(csv_path)
    assert list(trace) == header  # same columns, same order
    for name, values in columns.items():
        array = trace[name]
        assert isinstance(array, np.ndarray) and array.dtype == np.float64
        # The CSV holds 10 significant digits (std::setprecision(10)): the arrays, printed the
        # same way, give the same text in every cell.
        assert ["%.10g" % v for v in array] == values, name
    assert trace["penetration_m"][-1] == pytest.approx(summary["final_penetration_m"], rel=1e-12, abs=1e-15)


def test_force_equals_the_command_line_json():
    cli = touchdown_json("force", "--pad", "hex", "--soil", "fjs1_lp", "--depth", "0.01", "--tilt-deg", "10",
                         "--velocity", "0.1,0,-0.5", "--omega", "0,0.2,0", "--law", "agarwal2023")
    py = touchdown.force(pad="hex", soil="fjs1_lp", depth=0.01, tilt_deg=10.0, velocity=(0.1, 0.0, -0.5),
                         omega=(0.0, 0.2, 0.0), law="agarwal2023")
    assert py == cli
    assert py["force_N"][2] > 0.0  # the soil pushes up
    # The soil's dynamic term only when asked for, as --dynamic.
    cli = touchdown_json("force", "--pad", "flat", "--soil", "fjs1_lp", "--depth", "0.01", "--dynamic")
    py = touchdown.force(pad="flat", soil="fjs1_lp", depth=0.01, dynamic=True)
    assert py == cli and py["dynamic_term"]
    quasi_static = touchdown.force(pad="flat", soil="fjs1_lp", depth=0.01)
    assert not quasi_static["dynamic_term"] and quasi_static["force_N"][2] < py["force_N"][2]


def _soil_dict(name="fjs1_lp"):
    with open(data_file("soils", name + ".yaml"), encoding="utf-8") as f:
        return yaml.safe_load(f)


def test_a_soil_or_pad_dict_equals_the_named_one():
    named = touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0)
    with open(data_file("pads", "flat.yaml"), encoding="utf-8") as f:
        pad = yaml.safe_load(f)
    assert touchdown.drop(pad=pad, soil=_soil_dict(), speed=1.0) == named
    # A numeric zeta instead of the derivation: the same soil with that zeta.
    soil = {**_soil_dict(), "zeta_N_cm3": 2.5}
    assert touchdown.drop(pad="flat", soil=soil, speed=1.0) == touchdown.drop(pad="flat", soil="fjs1_lp",
                                                                             speed=1.0, zeta=2.5)


def test_a_soil_file_path_equals_the_named_soil(tmp_path):
    path = tmp_path / "my_soil.yaml"
    path.write_text(open(data_file("soils", "fjs1_cp.yaml"), encoding="utf-8").read())
    assert touchdown.drop(pad="flat", soil=path, speed=0.7) == touchdown.drop(pad="flat", soil="fjs1_cp", speed=0.7)


@pytest.mark.parametrize("change, field", [
    ({"zeta_N_cm3": -1.0}, "zeta_N_cm3"),
    ({"bulk_density_kg_m3": float("nan")}, "bulk_density_kg_m3"),
    ({"zeta": 1.0}, "zeta"),  # an unknown field
    ({"atmosphere": "water"}, "atmosphere"),
])
def test_a_bad_soil_dict_field_raises_value_error_naming_it(change, field):
    with pytest.raises(ValueError) as error:
        touchdown.drop(pad="flat", soil={**_soil_dict(), **change}, speed=1.0)
    message = str(error.value)
    assert "\n" not in message
    assert message.startswith("soil dict: ") and field in message, message
    assert "touchdown_" not in message  # the temporary file's path is not shown


def test_bad_arguments_raise_the_command_lines_message_with_python_names():
    with pytest.raises(ValueError, match=r"^touchdown\.drop: tilt_deg: must lie strictly between -90 and 90 deg \(on its side a pad does not land "
                                          r"on its bottom\), got 95$"):
        touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0, free=True, tilt_deg=95.0)
    with pytest.raises(ValueError, match=r"^touchdown\.drop: free: tilt_deg, horizontal_speed and omega need free"):
        touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0, tilt_deg=5.0)
    with pytest.raises(ValueError, match=r"impact_speed_m_s"):
        touchdown.drop(pad="flat", soil="fjs1_lp", speed=-1.0)
    with pytest.raises(ValueError, match=r"^touchdown\.force: depth: "):
        touchdown.force(pad="flat", soil="fjs1_lp", depth=20.0)
    with pytest.raises(ValueError, match=r"unknown name 'sand' \(known: "):
        touchdown.drop(pad="flat", soil="sand", speed=1.0)


def test_drops_in_threads_equal_the_same_drops_in_turn():
    # The simulation runs without the GIL: two threads simulate at once, with the same results.
    from concurrent.futures import ThreadPoolExecutor

    speeds = [0.7, 1.0, 1.5, 2.0]
    in_turn = [touchdown.drop(pad="curved", soil="fjs1_lp", speed=v) for v in speeds]
    with ThreadPoolExecutor(max_workers=2) as pool:
        threaded = list(pool.map(lambda v: touchdown.drop(pad="curved", soil="fjs1_lp", speed=v), speeds))
    assert threaded == in_turn


def test_a_mesh_pad_dict_reads_its_mesh_relative_to_the_working_directory(monkeypatch):
    with open(data_file("pads", "hex.yaml"), encoding="utf-8") as f:
        hex_pad = yaml.safe_load(f)  # mesh: {file: meshes/hex_pad.stl}, relative to data/pads
    monkeypatch.chdir(data_file("pads"))
    kwargs = dict(soil="fjs1_cp", depth=0.005, velocity=(0.0, 0.0, -0.3))
    assert touchdown.force(pad=hex_pad, **kwargs) == touchdown.force(pad="hex", **kwargs)

"""Pads, soils, landers and scenarios as objects with the loader's resolved fields, usable
wherever a name or a path is; simulations whose results are held in memory (traces as
DataFrames) when no output directory is given, leaving nothing behind."""
import gc
import json
import os
import tempfile

import pandas as pd
import pytest
import yaml

import touchdown
from conftest import data_file


def _yaml(*parts):
    with open(data_file(*parts), encoding="utf-8") as f:
        return yaml.safe_load(f)


@pytest.fixture
def private_tmp(tmp_path, monkeypatch):
    """tempfile's directory, watched: a test checks nothing is left in it."""
    root = tmp_path / "tmp"
    root.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(root))
    return root


def test_a_soil_reads_its_fields_as_the_loader_resolved_them():
    soil = touchdown.Soil.load("fjs1_lp")
    given = _yaml("soils", "fjs1_lp.yaml")
    assert soil.name == "fjs1_lp" and soil.atmosphere == "vacuum"
    assert soil.bulk_density_kg_m3 == given["bulk_density_kg_m3"]
    assert soil.fields["dynamic_lambda"] == given["dynamic_lambda"]
    assert soil.internal_friction_angle_deg == pytest.approx(given["internal_friction_angle_deg"], rel=1e-15)
    # The file derives zeta ("agarwal2023"); the object states the number the drop uses (the
    # drop's summary gives it at the drop's gravity, here the soil's reference gravity).
    assert given["zeta_N_cm3"] == "agarwal2023" and isinstance(soil.zeta_N_cm3, float)
    used = touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0)["zeta_N_cm3"]
    assert soil.zeta_N_cm3 == pytest.approx(used, rel=1e-14)
    assert os.path.samefile(os.fspath(soil), data_file("soils", "fjs1_lp.yaml"))
    assert touchdown.Soil.load(data_file("soils", "fjs1_lp.yaml")) == soil  # a path: the same soil
    assert "Soil('fjs1_lp'" in repr(soil) and "zeta_N_cm3=" in repr(soil)
    with pytest.raises(AttributeError, match="zeta"):
        soil.zeta


def test_a_pad_reads_its_file_and_its_rigid_body():
    pad = touchdown.Pad.load("flat")
    assert pad.mass_kg == _yaml("pads", "flat.yaml")["mass_kg"]
    assert pad.fields["profile"]["shape"] == "flat"
    body = pad.body
    assert body["mass_kg"] == pad.mass_kg
    assert touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0)["pad_mass_kg"] == body["mass_kg"]
    assert body["triangles"] > 0 and body["lowest_point_mm"] < 0.0
    # A mesh pad names its mesh by its resolved path; as a dict, relative to where it is said to be.
    hex_pad = touchdown.Pad.load("hex")
    mesh = hex_pad.fields["mesh"]["file"]
    assert os.path.isabs(mesh) and os.path.isfile(mesh)
    assert touchdown.Pad.from_dict(_yaml("pads", "hex.yaml"), relative_to=data_file("pads")) == hex_pad
    with pytest.raises(ValueError, match="^pad dict: mesh.file: .*meshes/hex_pad.stl: mesh file not found"):
        touchdown.Pad.from_dict(_yaml("pads", "hex.yaml"), relative_to=data_file("soils"))
    with pytest.raises(TypeError):
        touchdown.Pad.load(touchdown.Soil.load("fjs1_lp"))


def test_a_dict_built_pad_and_soil_give_the_named_ones_results():
    pad = touchdown.Pad.from_dict(_yaml("pads", "flat.yaml"))
    soil = touchdown.Soil.from_dict(_yaml("soils", "fjs1_lp.yaml"))
    assert pad == touchdown.Pad.load("flat") and soil == touchdown.Soil.load("fjs1_lp")
    assert pad.document["mass_kg"] == 1.6 and "Pad('flat'" in repr(pad) and "source='dict'" in repr(pad)
    named = touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0)
    assert touchdown.drop(pad=pad, soil=soil, speed=1.0) == named
    assert touchdown.drop(pad=touchdown.Pad.load("flat"), soil=touchdown.Soil.load("fjs1_lp"), speed=1.0) == named
    # An edited field is the field the drop uses.
    firm = touchdown.Soil.from_dict({**_yaml("soils", "fjs1_lp.yaml"), "zeta_N_cm3": 2.5})
    assert firm.zeta_N_cm3 == 2.5
    assert touchdown.drop(pad="flat", soil=firm, speed=1.0) == touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0,
                                                                                zeta=2.5)


def test_a_bad_dict_fails_when_made_naming_the_dict_and_leaves_nothing(private_tmp):
    with pytest.raises(ValueError) as error:
        touchdown.Soil.from_dict({**_yaml("soils", "fjs1_lp.yaml"), "zeta_N_cm3": -1.0})
    assert str(error.value).startswith("soil dict: ") and "zeta_N_cm3" in str(error.value)
    assert "touchdown_" not in str(error.value)
    with pytest.raises(ValueError, match="unknown name 'sand'"):
        touchdown.Soil.load("sand")
    assert os.listdir(private_tmp) == []


def test_a_dict_objects_file_lives_as_long_as_the_object(private_tmp):
    soil = touchdown.Soil.from_dict({"schema_version": 1, "zeta_N_cm3": 3.0})
    assert soil.name == "soil"  # no name: named after its kind
    path = os.fspath(soil)
    assert os.path.isfile(path) and os.path.dirname(os.path.dirname(path)) == str(private_tmp)
    del soil
    gc.collect()
    assert os.listdir(private_tmp) == []


def test_a_lander_resolves_its_masses_and_pad():
    lander = touchdown.Lander.load("sutoh2017_lander")
    given = _yaml("landers", "sutoh2017_lander.yaml")
    assert lander.name == "sutoh2017_lander" and lander.total_mass_kg == given["total_mass_kg"]
    pad = touchdown.Pad.load(data_file("landers", "sutoh2017_footpad.yaml"))
    assert lander.pad["mass_kg"] == pad.body["mass_kg"]
    assert lander.body_mass_kg == pytest.approx(given["total_mass_kg"] - 4 * pad.mass_kg, rel=1e-15)
    assert len(lander.legs) == 4
    # A lander dict whose pad is given as an object.
    built = touchdown.Lander.from_dict({**given, "pad": pad})
    assert built.fields == {**lander.fields, "file": built.fields["file"]}
    # Its own file as a dict: the pad beside it, as the file reads it, once told where it was.
    beside = touchdown.Lander.from_dict(given, relative_to=data_file("landers"))
    assert beside.fields == built.fields | {"file": beside.fields["file"]}
    # A bad field fails when made, named in the dict (not in the scenario it is resolved in).
    with pytest.raises(ValueError, match=r"^lander dict: total_mass_kg: must be positive"):
        touchdown.Lander.from_dict({**given, "total_mass_kg": -1.0, "pad": pad})


def test_a_scenario_resolves_as_touchdown_lander_writes_it(tmp_path):
    scenario = touchdown.Scenario.load("lander_case_A")
    given = _yaml("scenarios", "lander_case_A.yaml")
    assert scenario.name == "lander_case_A" and scenario.gravity_m_s2 == given["gravity_m_s2"]
    assert scenario.initial["drop_height_m"] == given["initial"]["drop_height_m"]
    assert scenario.lander["name"] == "sutoh2017_lander"
    assert [s["name"] for s in scenario.ground["soils"]] == ["fjs1_lp"]
    assert scenario.lander == touchdown.Lander.load("sutoh2017_lander").fields
    # As an edited dict, its lander an object: run by touchdown.lander like a file.
    higher = touchdown.Scenario.from_dict({**given, "lander": touchdown.Lander.load("sutoh2017_lander"),
                                           "initial": {"drop_height_m": 0.12}})
    assert higher.initial["drop_height_m"] == 0.12
    assert touchdown.lander(scenario)["final_penetration_m"] != touchdown.lander(higher)["final_penetration_m"]


def test_simulate_drop_gives_a_dataframe_trace():
    result = touchdown.simulate_drop(pad=touchdown.Pad.load("flat"), soil="fjs1_cp", speed=0.7)
    summary, trace = touchdown.drop(pad="flat", soil="fjs1_cp", speed=0.7, trace=True)
    assert result.summary == summary and result["peak_force_N"] == summary["peak_force_N"]
    assert isinstance(result.trace, pd.DataFrame)
    assert list(result.trace.columns) == ["t_s", "penetration_m", "velocity_m_s", "force_N"]
    for name, values in trace.items():
        assert (result.trace[name].to_numpy() == values).all(), name


def test_a_landing_in_memory_equals_the_one_on_disk_and_leaves_nothing(tmp_path, private_tmp):
    in_memory = touchdown.simulate_lander("lander_case_A")
    assert in_memory.out is None
    assert os.listdir(private_tmp) == []  # the private directory is gone, with all it held
    on_disk = touchdown.simulate_lander(touchdown.Scenario.load("lander_case_A"), out=tmp_path / "a", vtk=False)
    assert on_disk.out == str(tmp_path / "a")
    assert {"summary.json", "trace.csv", "events.csv", "scenario_resolved.yaml"} <= set(os.listdir(tmp_path / "a"))
    assert "vtk" not in os.listdir(tmp_path / "a")
    # Bit for bit: the same summary, trace and events.
    assert in_memory.summary == on_disk.summary
    with open(tmp_path / "a" / "summary.json", encoding="utf-8") as f:
        assert json.load(f) == in_memory.summary
    pd.testing.assert_frame_equal(in_memory.trace, on_disk.trace, check_exact=True)
    pd.testing.assert_frame_equal(in_memory.events, on_disk.events, check_exact=True)
    assert list(in_memory.trace.columns[:4]) == ["t_s", "x_m", "y_m", "z_m"]
    assert in_memory.events.columns.tolist() == ["t_s", "event", "pad"] and len(in_memory.events) > 0
    assert str(in_memory.events["pad"].dtype) == "Int64"
    depths = [in_memory.trace["depth%d_m" % i].iloc[-1] for i in range(1, 5)]
    assert depths == pytest.approx(in_memory.summary["final_penetration_m"], rel=1e-9)


def test_a_sweep_in_memory_equals_the_one_on_disk(tiny_sweep, private_tmp):
    out, _ = tiny_sweep
    result = touchdown.simulate_sweep(out.parent / "tiny.yaml", threads=1)
    assert result.out is None and os.listdir(private_tmp) == []
    on_disk, traces = touchdown.read_sweep(out, traces=True)
    pd.testing.assert_frame_equal(result.drops, on_disk, check_exact=True)
    assert sorted(result.traces) == sorted(traces)
    for index, trace in traces.items():
        pd.testing.assert_frame_equal(result.traces[index], trace, check_exact=True)


def test_a_campaign_in_memory_equals_the_one_on_disk(tmp_path, private_tmp):
    in_memory = touchdown.simulate_campaign("sutoh2017_single_footpad")
    assert in_memory.out is None and os.listdir(private_tmp) == []
    on_disk = touchdown.simulate_campaign("sutoh2017_single_footpad", out=tmp_path / "c")
    assert on_disk.out == str(tmp_path / "c") and os.path.isfile(tmp_path / "c" / "summary.csv")
    assert in_memory.summary == on_disk.summary
    pd.testing.assert_frame_equal(in_memory.drops, on_disk.drops, check_exact=True)
    assert list(in_memory.traces) == list(in_memory.drops["drop_id"]) and len(in_memory.traces) > 0
    for drop_id, trace in on_disk.traces.items():
        pd.testing.assert_frame_equal(in_memory.traces[drop_id], trace, check_exact=True)
    # The table's drops are the drops touchdown.drop gives (its numbers printed to 10 digits).
    row = in_memory.drops.iloc[0]
    drop = touchdown.drop(pad=row["pad"], soil=row["soil"], speed=row["impact_speed_m_s"])
    assert row["final_penetration_m"] == pytest.approx(drop["final_penetration_m"], rel=1e-9)


def test_objects_pickle_and_copy_for_other_processes():
    # Pad, Soil.from_dict, Lander and Scenario objects go to multiprocessing and concurrent.futures:
    # they pickle (a dict-made one with its content) and copy; they raised RecursionError before.
    import concurrent.futures
    import copy
    import pickle

    objects = [touchdown.Pad.load("flat"), touchdown.Lander.load("sutoh2017_lander"),
               touchdown.Scenario.load("lander_case_A"),
               touchdown.Soil.from_dict({"name": "picklable", "zeta_N_cm3": 3, "bulk_density_kg_m3": 1540})]
    for obj in objects:
        back = pickle.loads(pickle.dumps(obj))
        assert back == obj and type(back) is type(obj)
        assert copy.deepcopy(obj) == obj and copy.copy(obj) is obj
        assert os.path.isfile(os.fspath(back))
    soil = objects[-1]
    with concurrent.futures.ProcessPoolExecutor(max_workers=1) as pool:
        depth = pool.submit(_final_depth_of, soil).result()
    assert depth == pytest.approx(touchdown.drop(pad="flat", soil=soil, speed=1.0)["final_penetration_m"], rel=1e-12)


def _final_depth_of(soil):
    return touchdown.drop(pad="flat", soil=soil, speed=1.0)["final_penetration_m"]


def test_fields_are_read_only_and_a_change_raises():
    # Setting a field or changing `fields` silently did nothing: both raise now; a deep copy of the
    # fields is plain dicts to change and build another object from.
    import copy

    pad = touchdown.Pad.load("flat")
    with pytest.raises(AttributeError, match="read-only"):
        pad.mass_kg = 2.0
    with pytest.raises(TypeError, match="read-only"):
        pad.fields["mass_kg"] = 2.0
    with pytest.raises(TypeError, match="read-only"):
        pad.fields["profile"]["radius_mm"] = 60
    assert pad.mass_kg == 1.6
    changed = copy.deepcopy(pad.fields)
    changed["mass_kg"] = 2.0
    del changed["body"]
    assert touchdown.Pad.from_dict(changed).mass_kg == 2.0
    assert json.loads(json.dumps(pad.fields)) == copy.deepcopy(pad.fields)

"""The ParaView output read with VTK's own reader (vtkXMLPolyDataReader, Debian's python3-vtk9):
every piece of a free drop's and a lander's .pvd series opens, with the points, cells and per-element
fields written, and its geometry and fields agree with the CSV traces of the same run: the elements'
forces sum to each pad's soil force, the craters are no deeper than the pads went, and no file holds
a negative zero.

Skipped when the vtk module is not installed (tools/install_deps.sh installs python3-vtk9)."""
import glob
import os
import re
import xml.etree.ElementTree as ET

import numpy as np
import pandas as pd
import pytest
import yaml

from conftest import data_file, run_touchdown

vtk = pytest.importorskip("vtk")
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

PAD_FIELDS = ["normal_stress_Pa", "shear_stress_Pa", "depth_m", "leading"]
PAD_VECTORS = ["traction_Pa", "element_force_N"]
NEGATIVE_ZERO = re.compile(r"(?<![\w.])-0(?![\w.])")


def _series(pvd):
    """The .pvd's DataSet entries: [(time, part name, file path)]."""
    root = ET.parse(pvd).getroot()
    directory = os.path.dirname(pvd)
    return [(float(d.get("timestep")), d.get("name") or d.get("part"), os.path.join(directory, d.get("file")))
            for d in root.iter("DataSet")]


def _read(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    assert reader.GetErrorCode() == 0, path
    return reader.GetOutput()


def _cell_array(poly, name):
    array = poly.GetCellData().GetArray(name)
    assert array is not None, name
    values = vtk_to_numpy(array)
    assert len(values) == poly.GetNumberOfCells(), name
    return values


def _points(poly):
    return vtk_to_numpy(poly.GetPoints().GetData())


def _cell_vectors(poly, name):
    values = _cell_array(poly, name)
    assert values.shape == (poly.GetNumberOfCells(), 3), name
    return values


def _triangles(poly):
    """Each triangle's corners, [cells, 3 corners, xyz]."""
    offsets = vtk_to_numpy(poly.GetPolys().GetOffsetsArray())
    connectivity = vtk_to_numpy(poly.GetPolys().GetConnectivityArray())
    assert np.all(np.diff(offsets) == 3)
    return _points(poly)[connectivity.reshape(-1, 3)]


def _check_vectors(pad):
    """traction times the element's area is its force, and normal_stress_Pa is the traction's
    component into the pad (the outward normal from the corners' counter-clockwise order)."""
    corners = _triangles(pad)
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    area = 0.5 * np.linalg.norm(cross, axis=1)
    normal = cross / np.linalg.norm(cross, axis=1)[:, None]
    traction, force = _cell_vectors(pad, "traction_Pa"), _cell_vectors(pad, "element_force_N")
    scale = np.abs(force).max() + 1e-30
    np.testing.assert_allclose(traction * area[:, None], force, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(-(traction * normal).sum(axis=1) * area, _cell_array(pad, "normal_stress_Pa") * area,
                               rtol=0, atol=1e-9 * scale)


def _no_negative_zero(directory):
    for path in glob.glob(os.path.join(directory, "*.vt[pu]")) + glob.glob(os.path.join(directory, "*.pvd")):
        with open(path, encoding="utf-8") as f:
            match = NEGATIVE_ZERO.search(f.read())
        assert match is None, f"{path}: a negative zero at {match.start()}"


def _coarse(source, target, **changes):
    """A copy of a data file with some fields changed (coarser pads: the test reads every frame)."""
    with open(source, encoding="utf-8") as f:
        content = yaml.safe_load(f)
    content.update(changes)
    with open(target, "w", encoding="utf-8") as f:
        yaml.safe_dump(content, f)
    return target


def test_free_drop_series_reads_back_and_matches_the_trace(tmp_path):
    pad = _coarse(data_file("pads", "flat.yaml"), tmp_path / "flat.yaml", angular_segments=24)
    run_touchdown("drop", "--pad", pad, "--soil", "fjs1_lp", "--speed", 1.0, "--free", "--tilt-deg", 10,
                  "--vtk", tmp_path / "vtk", "--trace", tmp_path / "trace.csv")
    trace = pd.read_csv(tmp_path / "trace.csv")
    entries = _series(str(tmp_path / "vtk" / "drop.pvd"))
    pads = [(t, f) for t, part, f in entries if part == "pad"]
    craters = [f for _, part, f in entries if part == "crater"]
    assert [part for _, part, _ in entries[:3]] == ["pad", "crater", "soil"]
    # One frame per trace sample, at its time.
    assert len(pads) == len(trace)
    np.testing.assert_allclose([t for t, _ in pads], trace["t_s"], rtol=1e-9, atol=1e-12)
    cells = None
    deepest = 0.0
    for (t, path), crater_path, (_, row) in zip(pads, craters, trace.iterrows()):
        pad = _read(path)
        cells = cells or pad.GetNumberOfCells()
        assert pad.GetNumberOfCells() == cells > 100  # the contact mesh, the same in every frame
        fields = {name: _cell_array(pad, name) for name in PAD_FIELDS}
        # The lowest point is the trace's penetration below the surface z = 0.
        assert _points(pad)[:, 2].min() == pytest.approx(-row["penetration_m"], abs=1e-9)
        assert fields["depth_m"].max() <= row["penetration_m"] + 1e-9
        assert np.all(fields["shear_stress_Pa"] >= 0.0)
        assert set(np.unique(fields["leading"])) <= {0.0, 1.0}
        # No stress on elements wholly above the surface (centroid more than half the 16 mm pad
        # thickness up); stress where the pad pushes into the soil.
        above = fields["depth_m"] < -0.01
        assert np.all(fields["normal_stress_Pa"][above] == 0.0)
        if row["force_N"] > 1.0 and row["velocity_m_s"] > 1e-3:
            assert fields["normal_stress_Pa"].max() > 0.0 and fields["leading"].sum() > 0
        _check_vectors(pad)
        # The crater: as deep as the pad has been (to the grid's resolution), never deeper.
        deepest = max(deepest, row["penetration_m"])
        crater_depth = vtk_to_numpy(_read(crater_path).GetPointData().GetArray("crater_depth_m"))
        assert crater_depth.min() == 0.0
        assert crater_depth.max() <= deepest + 1e-9
    assert crater_depth.max() > 0.8 * deepest
    _no_negative_zero(str(tmp_path / "vtk"))
    soil = _read(entries[2][2])
    assert soil.GetNumberOfCells() == 400  # 20 x 20 quads
    assert np.all(_points(soil)[:, 2] == 0.0)


def test_lander_series_reads_back_and_matches_the_trace(tmp_path):
    out = tmp_path / "case_A"
    pad = _coarse(data_file("landers", "sutoh2017_footpad.yaml"), tmp_path / "pad.yaml", angular_segments=16)
    lander = _coarse(data_file("landers", "sutoh2017_lander.yaml"), tmp_path / "lander.yaml", pad=str(pad))
    scenario = _coarse(data_file("scenarios", "lander_case_A.yaml"), tmp_path / "case_A.yaml", lander=str(lander))
    run_touchdown("lander", scenario, "--out", out)
    trace = pd.read_csv(out / "trace.csv")
    entries = _series(str(out / "vtk" / "lander.pvd"))
    assert [part for _, part, _ in entries[:5]] == ["pads", "body", "legs", "crater", "soil"]
    frames = [entries[i:i + 5] for i in range(0, len(entries), 5)]
    assert len(frames) > 20
    elements = None
    for frame in frames:
        t = frame[0][0]
        pads = _read(frame[0][2])
        elements = elements or pads.GetNumberOfCells() // 4
        assert pads.GetNumberOfCells() == 4 * elements
        number = _cell_array(pads, "pad_number")
        force = _cell_array(pads, "pad_force_N")
        for i in range(1, 5):
            assert (number == i).sum() == elements
            assert np.all(force[number == i] == force[number == i][0])  # one value per pad
        # The frame's sample: at its time (of the samples at an event's time, the one whose forces
        # these are). Each pad's force is the trace's force<i>_N (written to 10 digits).
        rows = trace[(trace["t_s"] - t).abs() <= 1e-9 * max(1.0, abs(t))]
        pad_forces = [force[number == i][0] for i in range(1, 5)]
        matching = [r for _, r in rows.iterrows()
                    if all(abs(r[f"force{i}_N"] - pad_forces[i - 1]) <= 1e-9 * max(1.0, pad_forces[i - 1])
                           for i in range(1, 5))]
        assert matching, f"frame at t = {t}: no trace sample with the pads' forces {pad_forces}"
        row = matching[-1]
        points = _points(pads)
        offsets = vtk_to_numpy(pads.GetPolys().GetOffsetsArray())
        connectivity = vtk_to_numpy(pads.GetPolys().GetConnectivityArray())
        for i in range(1, 5):
            # Pad i's lowest point is its depth below the level ground (case A: z = 0).
            of_pad = np.repeat(number == i, np.diff(offsets))
            assert points[connectivity[of_pad], 2].min() == pytest.approx(-row[f"depth{i}_m"], abs=1e-9)
        for name in PAD_FIELDS + ["held"]:
            _cell_array(pads, name)
        # The elements' forces (the evaluation that gives the stresses) sum to the pad's soil force:
        # its magnitude exactly as written (pad_force_N), its vertical part as the trace's fz<i>_N
        # (10 digits). A held pad's load is a constraint force: its elements carry none.
        _check_vectors(pads)
        element_force = _cell_vectors(pads, "element_force_N")
        held = _cell_array(pads, "held")
        for i in range(1, 5):
            total = element_force[number == i].sum(axis=0)
            if held[number == i][0]:
                assert np.all(element_force[number == i] == 0.0)
                continue
            assert np.linalg.norm(total) == pytest.approx(pad_forces[i - 1], rel=1e-10, abs=1e-9)
            assert total[2] == pytest.approx(row[f"fz{i}_N"], rel=1e-9, abs=1e-9)
        craters = _read(frame[3][2])
        crater_depth = vtk_to_numpy(craters.GetPointData().GetArray("crater_depth_m"))
        assert crater_depth.min() == 0.0
        deepest = max(0.0, trace[trace["t_s"] <= row["t_s"]][[f"depth{i}_m" for i in range(1, 5)]].to_numpy().max())
        assert crater_depth.max() <= deepest + 1e-9
        legs = _read(frame[2][2])
        assert legs.GetNumberOfCells() == 4
        leg_points = _points(legs).reshape(4, 2, 3)
        for i in range(4):
            joint = [row[f"joint{i + 1}_{c}_m"] for c in "xyz"]
            np.testing.assert_allclose(leg_points[i, 1], joint, atol=1e-8)
        assert set(np.unique(_cell_array(legs, "leg_number"))) == {1.0, 2.0, 3.0, 4.0}
        _cell_array(legs, "leg_force_N"), _cell_array(legs, "stroke_m")
        assert _read(frame[1][2]).GetNumberOfPolys() == 1  # the body: the hips' polygon
    assert crater_depth.max() > 0.8 * deepest  # the last frame: the pads at rest in their craters
    _no_negative_zero(str(out / "vtk"))
    soil = _read(frames[0][4][2])
    assert soil.GetNumberOfCells() == 1600  # 40 x 40 quads
    assert set(np.unique(_cell_array(soil, "soil"))) == {0.0}  # case A: one soil

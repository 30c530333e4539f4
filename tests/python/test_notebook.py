"""examples/notebooks/touchdown_tour.ipynb runs from top to bottom in a fresh python3 kernel
(nbclient, ipykernel) and shows what its text says: the campaign's drops, the paper's Fig. 3, the
study's tip-over probability and its figure. Run in a copy in a temporary directory, so the
repository's notebook keeps no outputs. Skipped when nbclient, nbformat or ipykernel is missing
(tools/install_deps.sh tests installs them)."""
import os
import re
import shutil

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

import touchdown  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
NOTEBOOK = os.path.join(ROOT, "examples", "notebooks", "touchdown_tour.ipynb")


def _kernel_environment():
    """The kernel imports the touchdown under test and draws inline (MPLBACKEND=Agg, as CTest sets
    it for the other tests, would draw nothing into the notebook)."""
    env = dict(os.environ)
    env.pop("MPLBACKEND", None)
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(touchdown.__file__)))
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [package_parent, env.get("PYTHONPATH")]))
    env["TOUCHDOWN_DATA_DIR"] = touchdown.data_dir()
    return env


def _outputs(notebook, kind):
    """Every output of the code cells with the MIME type (or stream text) `kind`, in order."""
    found = []
    for cell in notebook.cells:
        for output in cell.get("outputs", []):
            if kind == "stream" and output.output_type == "stream" and output.name == "stdout":
                found.append(output.text)
            elif kind in output.get("data", {}):
                found.append(output.data[kind])
    return found


def test_the_tour_runs_and_shows_its_results(tmp_path):
    copy = tmp_path / "touchdown_tour.ipynb"
    shutil.copyfile(NOTEBOOK, copy)
    notebook = nbformat.read(copy, as_version=4)
    assert all(not cell.get("outputs") for cell in notebook.cells if cell.cell_type == "code"), \
        "the repository's notebook is stored without outputs"
    client = nbclient.NotebookClient(notebook, timeout=600, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute(env=_kernel_environment())  # a cell that raises fails here (CellExecutionError)
    errors = [o for c in notebook.cells for o in c.get("outputs", []) if o.output_type == "error"]
    assert errors == []

    text = "\n".join(_outputs(notebook, "stream") + _outputs(notebook, "text/plain"))
    # The campaign: all twelve drops in its table, and the paper's checks.
    for drop_id in ("flat_fjs1_lp_v0.70", "c4_fjs1_lp_v1.00", "curved_fjs1_lp_v1.50", "flat_fjs1_cp_v1.00"):
        assert drop_id in text
    assert "curved_over_flat_penetration_lp" in text
    assert "fig3_time_histories.png" in text  # the command's own figures listed
    # The study: its probability and interval, as numbers.
    match = re.search(r"(\d+) landings, (\d+) tipped over: P\(tip-over\) = ([0-9.]+), "
                      r"95 % interval \[([0-9.]+), ([0-9.]+)\]", text)
    assert match, text
    landings, tipped = int(match[1]), int(match[2])
    probability, low, high = map(float, match.group(3, 4, 5))
    assert landings == 8 and 0 <= tipped <= landings
    assert probability == pytest.approx(tipped / landings, abs=1e-3)
    assert 0.0 <= low <= probability <= high <= 1.0
    assert "max_tilt_deg" in text  # the percentiles table
    # Two figures drawn inline: Fig. 3 and the study's tilts.
    assert len(_outputs(notebook, "image/png")) == 2

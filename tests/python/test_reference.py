"""docs/reference.md says what the code does: every input table is what tools/reference_tables.py
generates from the loaders' own tables (`touchdown schema --json`: keys, units, ranges, defaults)
and lists exactly the keys its loader accepts (read from the loader's own refusal of an unknown
key, which names them), and every output table exactly the keys or columns the command writes, in
their order for CSV files.

Uses only the touchdown executable and PyYAML. A failure names the table and the keys that differ:
update docs/reference.md (or the code) so that both say the same."""
import csv
import json
import os
import re
import sqlite3
import subprocess

import pytest
import yaml

from conftest import BINARY, DATA, ROOT, data_file, run_touchdown

REFERENCE = os.path.join(ROOT, "docs", "reference.md")
UNKNOWN = "zz_not_a_field"


def _tables():
    """({table id: [first-column names in order]}, {table id: {name: third column}}) for every
    `<!-- kind: id -->` marked table; a cell names one or more keys in backticks; `<i>` in a name
    stands for the pads 1..4 (the row's names repeated for each pad)."""
    tables, present, current = {}, {}, None
    with open(REFERENCE, encoding="utf-8") as f:
        for line in f:
            marker = re.match(r"<!-- (?:fields|params|columns|keys): (\S+) -->", line)
            if marker:
                current = marker.group(1)
                tables.setdefault(current, [])
                present.setdefault(current, {})
                continue
            if current is None:
                continue
            if not line.startswith("|"):
                if line.strip():
                    current = None
                continue
            cells = line.split("|")
            names = re.findall(r"`([^`]+)`", cells[1])
            if not names:
                continue
            if any("<i>" in n for n in names):
                names = [n.replace("<i>", str(i)) for i in range(1, 5) for n in names]
            tables[current].extend(names)
            for n in names:
                present[current][n] = cells[3].strip()
    return tables, present


TABLES, PRESENT = _tables()


def _known_keys(args, cwd):
    """Runs touchdown, which must refuse the unknown key; the keys its message names."""
    done = subprocess.run([BINARY, *map(str, args)], cwd=cwd, capture_output=True, text=True, check=False)
    assert done.returncode == 2, done.stderr
    assert UNKNOWN in done.stderr, done.stderr
    listed = re.search(r"known: (.*)$", done.stderr.strip()) or re.search(r"unknown parameter \((.*)\)$",
                                                                          done.stderr.strip())
    assert listed, done.stderr
    return re.split(r", |; lander sweeps: ", listed.group(1))


def _load(*parts):
    with open(os.path.join(DATA, *parts), encoding="utf-8") as f:
        return yaml.safe_load(f)


def _write(path, content):
    with open(path, "w", encoding="utf-8") as f:
        yaml.safe_dump(content, f, sort_keys=False)
    return path


def _inject(content, path):
    """content with the unknown key added to the mapping at `path` (keys and list indices)."""
    node = content
    for step in path:
        node = node[step]
    node[UNKNOWN] = 1
    return content


def _absolute(content, data_kind, *keys):
    """Catalogue-relative file names of a copied file made absolute."""
    for key in keys:
        name = content[key]
        if name.endswith(".yaml"):
            content[key] = os.path.join(DATA, data_kind, name)
    return content


def _pad(tmp, path, base="flat.yaml", extra=None):
    pad = _load("pads", base)
    pad.update(extra or {})
    f = _write(tmp / "pad.yaml", _inject(pad, path))
    return ["drop", "--pad", f, "--soil", "fjs1_lp", "--speed", 1]


def _soil(tmp, path, base="fjs1_lp.yaml"):
    f = _write(tmp / "soil.yaml", _inject(_load("soils", base), path))
    return ["drop", "--pad", "flat", "--soil", f, "--speed", 1]


def _model(tmp, path):
    model = {"schema_version": 1, "type": "model", "name": "m",
             "soils": {"fjs1_lp": {"zeta_N_cm3": 2.0, "fit": {"method": "test"}}}}
    f = _write(tmp / "model.yaml", _inject(model, path))
    return ["drop", "--pad", "flat", "--soil", "fjs1_lp", "--speed", 1, "--model", f]


def _campaign(tmp, path):
    scenario = _load("scenarios", "sutoh2017_single_footpad.yaml")
    f = _write(tmp / "campaign.yaml", _inject(scenario, path))
    return ["campaign", f, "--out", tmp / "out"]


def _lander_scenario(tmp, path, base="lander_case_B.yaml", extra=None):
    scenario = _load("scenarios", base)
    scenario.update(extra or {})
    f = _write(tmp / "scenario.yaml", _inject(scenario, path))
    return ["lander", f, "--out", tmp / "out", "--no-vtk"]


def _lander(tmp, path, extra=None):
    lander = _absolute(_load("landers", "sutoh2017_lander.yaml"), "landers", "pad")
    for key, value in (extra or {}).items():
        lander["legs"][key] = value
    lander_file = _write(tmp / "lander.yaml", _inject(lander, path))
    scenario = _load("scenarios", "lander_case_A.yaml")
    scenario["lander"] = str(lander_file)
    return ["lander", _write(tmp / "scenario.yaml", scenario), "--out", tmp / "out", "--no-vtk"]


def _sweep(tmp, path, base=("sweeps", "pad_trade.yaml"), command=None):
    plan = _load(*base)
    if "lander" in plan:
        plan["lander"]["scenario"] = os.path.join(DATA, base[0], plan["lander"]["scenario"])
    f = _write(tmp / "plan.yaml", _inject(plan, path))
    command = command or ("stability" if plan.get("type") == "stability" else "sweep")
    return [command, f, "--out", tmp / "out"]


SOIL_FIELD = {"ground": {"soil": "fjs1_lp", "soil_field": {"soils": ["fjs1_lp", "fjs1_cp"], "probabilities": [0.5, 0.5],
                                                           "cell_size_m": 0.1, "half_extent_m": 1.0, "seed": 1}}}
def _synth(tmp, path):
    spec = _load("datasets", "air_vs_vacuum_synthetic.synth.yaml")
    f = _write(tmp / "synth.yaml", _inject(spec, path))
    return ["synth", f, "--out", tmp / "out"]


CONE = {"cone_limit": {"half_angle_deg": 30, "stiffness_N_m_rad": 100}}
STUDY = ("studies", "lunar_paper_lander.yaml")
INPUTS = {
    "pad": lambda t: _pad(t, []),
    "pad.profile": None,  # per shape, below
    "pad.mesh_kind": lambda t: _mesh_pad(t, []),
    "pad.mesh": lambda t: _mesh_pad(t, ["mesh"]),
    "pad.inertia_kg_m2": lambda t: _pad(t, ["inertia_kg_m2"], extra={"inertia_kg_m2": {"ixx": 1, "iyy": 1, "izz": 1}}),
    "soil": lambda t: _soil(t, []),
    "soil.bekker": lambda t: _soil(t, ["bekker"], "fjs1_lp_bekker.yaml"),
    "model": lambda t: _model(t, []),
    "model.soil": lambda t: _model(t, ["soils", "fjs1_lp"]),
    "model.soil.fit": lambda t: _model(t, ["soils", "fjs1_lp", "fit"]),
    "campaign": lambda t: _campaign(t, []),
    "campaign.drops": lambda t: _campaign(t, ["drops", 0]),
    "campaign.paper_checks": lambda t: _campaign(t, ["paper_checks", 0]),
    "lander_scenario": lambda t: _lander_scenario(t, []),
    "lander_scenario.ground": lambda t: _lander_scenario(t, ["ground"]),
    "lander_scenario.ground.patches": lambda t: _lander_scenario(t, ["ground", "patches", 0]),
    "lander_scenario.ground.soil_field": lambda t: _lander_scenario(t, ["ground", "soil_field"], extra=SOIL_FIELD),
    "lander_scenario.initial": lambda t: _lander_scenario(t, ["initial"]),
    "lander_scenario.simulation": lambda t: _lander_scenario(t, ["simulation"]),
    "lander": lambda t: _lander(t, []),
    "lander.legs": lambda t: _lander(t, ["legs"]),
    "lander.legs.cone_limit": lambda t: _lander(t, ["legs", "cone_limit"], extra=CONE),
    "sweep": lambda t: _sweep(t, []),
    "sweep.trade": lambda t: _sweep(t, ["trade"], command="trade"),  # only trade reads its limits
    "sweep.lander": lambda t: _sweep(t, ["lander"], base=STUDY),
    "study": lambda t: _sweep(t, ["study"], base=STUDY),
    "synth": lambda t: _synth(t, []),
    "synth.drops": lambda t: _synth(t, ["drops", 0]),
    "synth.noise": lambda t: _synth(t, ["noise"]),
}


def _mesh_pad(tmp, path):
    pad = _load("pads", "hex.yaml")
    pad["mesh"]["file"] = os.path.join(DATA, "pads", pad["mesh"]["file"])
    f = _write(tmp / "pad.yaml", _inject(pad, path))
    return ["drop", "--pad", f, "--soil", "fjs1_lp", "--speed", 1]


def test_input_tables_are_what_the_loaders_tables_generate():
    """tools/reference_tables.py would write docs/reference.md as it is: every block the loaders
    read has its table, every key its unit, range, default and a meaning."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("reference_tables", os.path.join(ROOT, "tools", "reference_tables.py"))
    tables = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tables)
    with open(REFERENCE, encoding="utf-8") as f:
        text = f.read()
    generated, problems = tables.regenerate(text, tables.schema(BINARY))
    assert not problems, problems
    assert generated == text, "docs/reference.md's input tables are out of date: run python3 tools/reference_tables.py"


@pytest.mark.parametrize("table", sorted(k for k, v in INPUTS.items() if v))
def test_input_table_lists_the_loaders_keys(table, tmp_path):
    assert table in TABLES, f"docs/reference.md has no table '{table}'"
    known = _known_keys(INPUTS[table](tmp_path), tmp_path)
    documented = TABLES[table] + (["provenance"] if "provenance" in known and "provenance" not in TABLES[table] else [])
    assert sorted(set(known)) == sorted(set(documented)), f"table {table}: code {known}, docs {TABLES[table]}"


def test_profile_table_lists_every_shapes_keys(tmp_path):
    keys = set()
    for shape in ["flat", "chamfer", "exponential", "spherical_cap", "cone", "table"]:
        pad = _load("pads", "flat.yaml")
        pad["profile"] = {"shape": shape}
        keys |= set(_known_keys(_pad_with(tmp_path, pad), tmp_path))
    assert sorted(keys) == sorted(TABLES["pad.profile"])


def _pad_with(tmp, pad):
    return ["drop", "--pad", _write(tmp / "pad.yaml", _inject(pad, ["profile"])), "--soil", "fjs1_lp", "--speed", 1]


def _model_with_effects(tmp, effects):
    model = {"schema_version": 1, "type": "model", "name": "m", "effects": effects}
    return ["drop", "--pad", "flat", "--soil", "fjs1_lp", "--speed", 1, "--model", _write(tmp / "model.yaml", model)]


def test_effect_tables_list_the_effect_library(tmp_path):
    ids = [k.rstrip(")") for k in _known_keys(_model_with_effects(tmp_path, {UNKNOWN: {}}), tmp_path)]
    assert ids == TABLES["model.effects"]  # in the library's order
    for effect in ids:
        known = _known_keys(_model_with_effects(tmp_path, {effect: {UNKNOWN: 1}}), tmp_path)
        documented = [p.split(".", 1)[1] for p in TABLES["model.effects.parameters"] if p.startswith(effect + ".")]
        assert sorted(known) == sorted(["interval_95"] + documented), effect


def test_sweep_parameter_table_lists_every_parameter(tmp_path):
    known = _known_keys(_sweep(tmp_path, ["fixed"]), tmp_path)
    assert known == TABLES["sweep_params"]  # in the code's order


# Outputs: CSV headers and database columns equal their tables, in order; JSON keys are those
# of the table, the "always" ones in every output.

def _header(path):
    with open(path, newline="", encoding="utf-8") as f:
        return next(csv.reader(f))


def _check_keys(table, keys):
    keys = set(keys)
    documented = set(TABLES[table])
    always = {k for k, p in PRESENT[table].items() if p == "always"}
    assert keys <= documented, f"table {table} lacks {sorted(keys - documented)}"
    assert always <= keys, f"table {table} says always, but the output lacks {sorted(always - keys)}"


def _check_columns(table, columns, substitute=None):
    documented = TABLES[table]
    for placeholder, value in (substitute or {}).items():
        documented = [c.replace(placeholder, value) for c in documented]
    assert list(columns) == documented, f"table {table}: output {list(columns)}, docs {documented}"


def test_drop_outputs_match_their_tables(tmp_path):
    rig = json.loads(run_touchdown("drop", "--pad", "flat", "--soil", "fjs1_lp", "--speed", 1,
                                   "--trace", tmp_path / "rig.csv"))
    free = json.loads(run_touchdown("drop", "--pad", "flat", "--soil", "fjs1_lp", "--speed", 1, "--free",
                                    "--tilt-deg", 5, "--trace", tmp_path / "free.csv"))
    model = tmp_path / "model.yaml"
    model.write_text("type: model\neffects: {rate_damping: {c_N_s_m3: 1000}}\n")
    with_model = json.loads(run_touchdown("drop", "--pad", "flat", "--soil", "fjs1_lp", "--speed", 1, "--model", model))
    for summary in (rig, free, with_model):
        _check_keys("drop.summary", summary)
    assert {"effects", "effects_not_applied", "model"} <= set(with_model)
    _check_columns("drop.trace", _header(tmp_path / "rig.csv"))
    _check_columns("drop.free_trace", _header(tmp_path / "free.csv"))


def test_campaign_outputs_match_their_tables(tmp_path):
    run_touchdown("campaign", data_file("scenarios", "sutoh2017_single_footpad.yaml"), "--out", tmp_path / "c")
    with open(tmp_path / "c" / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    _check_keys("campaign.summary", summary)
    for drop in summary["drops"]:
        _check_keys("drop.summary", {k for k in drop if k not in ("drop_id", "trace")})
    for check in summary["paper_checks"]:
        _check_keys("campaign.checks_out", check)
    _check_columns("campaign.summary_csv", _header(tmp_path / "c" / "summary.csv"))


def test_lander_outputs_match_their_tables(tmp_path):
    summary = json.loads(run_touchdown("lander", data_file("scenarios", "lander_case_B.yaml"), "--out", tmp_path / "l",
                                       "--no-vtk"))
    _check_keys("lander.summary", summary)
    assert "paper_check" in summary and "time_to_rest_s" in summary
    _check_columns("lander.trace", _header(tmp_path / "l" / "trace.csv"))
    _check_columns("lander.events", _header(tmp_path / "l" / "events.csv"))


STUDY_PLAN = """schema_version: 1
type: stability
name: tiny_study
lander: {{scenario: {scenario}}}
fixed: {{impact_speed_m_s: 1.0}}
random:
  samples: 3
  seed: 1
  roll_deg: {{uniform: [-3, 3]}}
  pitch_deg: {{uniform: [-3, 3]}}
study: {{map: {{x: roll_deg, y: pitch_deg, bins: [2, 2]}}, worst_cases: 2}}
"""


def test_sweep_and_stability_outputs_match_their_tables(tmp_path):
    plan = tmp_path / "study.yaml"
    plan.write_text(STUDY_PLAN.format(scenario=data_file("scenarios", "lander_case_A.yaml")))
    run_touchdown("stability", plan, "--out", tmp_path / "s", "--threads", 2)
    # A study stores summaries only: no ParaView series (docs/paraview.md).
    assert not [p for p in (tmp_path / "s").rglob("*") if p.suffix in (".vtp", ".pvd")]
    with sqlite3.connect(tmp_path / "s" / "results.sqlite") as db:
        _check_columns("sweep.drops", [row[1] for row in db.execute("PRAGMA table_info(drops)")])
        _check_keys("sweep.meta", [row[0] for row in db.execute("SELECT key FROM meta")])
    with open(tmp_path / "s" / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    _check_keys("stability.summary", summary)
    assert "map" in summary
    assert sorted(summary["percentiles"]) == sorted(TABLES["stability.metrics"])  # JSON: sorted keys
    _check_columns("stability.percentiles", _header(tmp_path / "s" / "percentiles.csv"))
    with open(tmp_path / "s" / "percentiles.csv", newline="", encoding="utf-8") as f:
        assert [row["metric"] for row in csv.DictReader(f)] == TABLES["stability.metrics"]
    _check_columns("stability.tip_over_map", _header(tmp_path / "s" / "tip_over_map.csv"),
                   {"<x>": "roll_deg", "<y>": "pitch_deg"})


def test_trade_outputs_match_their_tables(tmp_path):
    plan = tmp_path / "trade.yaml"
    plan.write_text("schema_version: 1\ntype: sweep\nname: t\nfixed: {gravity_m_s2: 9.81}\n"
                    "grid: {pad: [flat, c4], soil: [fjs1_lp], impact_speed_m_s: [1.0]}\n"
                    "trade: {allowable_final_penetration_mm: 15}\n")
    run_touchdown("trade", plan, "--out", tmp_path / "t", "--threads", 1)
    _check_columns("trade.csv", _header(tmp_path / "t" / "trade.csv"))
    with open(tmp_path / "t" / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    _check_keys("trade.summary", summary)
    assert [list(row) for row in summary["rows"]][0] == sorted(TABLES["trade.csv"])  # JSON: sorted keys

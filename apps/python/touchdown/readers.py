"""Readers of touchdown's outputs as pandas DataFrames (pure Python: sqlite3, csv, json).

    read_sweep(path)        a sweep's results database (DIR/results.sqlite, or DIR)
    read_dataset(dir)       a dataset directory (drops.csv and its traces)
    read_stability(dir)     a stability study's outputs (summary.json, CSV tables, landings)

The formats: drop_tests/sweep/results_db.h, drop_tests/dataset/dataset.h,
drop_tests/stability/study_outputs.h. Numbers read back exactly (the database holds IEEE doubles;
CSV numbers are parsed with pandas' round-trip parser).

A file that is not there raises FileNotFoundError; one that cannot be read as its format
(not a database, truncated JSON, an empty CSV) ValueError naming the file; both the messages of
the command line's readers.
"""
import errno
import json
import os
import sqlite3
import urllib.parse
from dataclasses import dataclass

from . import _touchdown

# The columns of a trace BLOB in the sweep database (pad::DropSample, four float64 per sample).
SWEEP_TRACE_COLUMNS = ("t_s", "penetration_m", "velocity_m_s", "force_N")


def _pandas():
    import pandas  # imported when a reader is used, so `import touchdown` works without pandas

    return pandas


def _missing(path, what):
    """FileNotFoundError with the command line's one-line message and errno set."""
    error = FileNotFoundError(f"{path}: {what}")
    error.errno = errno.ENOENT
    return error


def _results_db(path):
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, "results.sqlite")
    if not os.path.exists(path):
        raise _missing(path, "no sweep results database (results.sqlite)")
    if not os.path.isfile(path):
        raise ValueError(f"{path}: is not a file (a sweep results database, results.sqlite)")
    return path


def _connect_reader(path):
    """The database opened as the command line's readers open it (ResultsDb::Access::kReadOnly),
    writing nothing: where this process may write the file and its directory, read-write with
    query_only (SQLite's -wal and -shm files come and go as for any connection); else read-only
    storage, mode=ro. There SQLite reads a WAL database through a -shm index it must create beside
    the file; where it cannot (the directory not writable) and no -wal file holds commits, the file
    alone is the whole database and is opened immutable."""
    directory = os.path.dirname(path) or "."
    writable_dir = os.access(directory, os.W_OK)
    if writable_dir and os.access(path, os.W_OK):
        mode = "mode=rw"
    elif not writable_dir and not os.path.exists(path + "-wal"):
        mode = "mode=ro&immutable=1"
    else:
        mode = "mode=ro"
    db = sqlite3.connect("file:" + urllib.parse.quote(os.path.abspath(path)) + "?" + mode, uri=True)
    db.execute("PRAGMA query_only=1")
    return db


# The columns of the `drops` table that only lander drops fill (drop_tests/sweep/results_db.h,
# "Lander drops only"): NaN, or "" for the soils and ground case, in a rig or free drop's row.
LANDER_COLUMNS = (
    "roll_deg", "pitch_deg",
    *(f"pad{i}_final_penetration_m" for i in range(1, 5)),
    "final_roll_deg", "final_pitch_deg", "tipped_over",
    *(f"pad{i}_soil" for i in range(1, 5)), "ground_case",
    "max_tilt_deg", "peak_leg_force_N", "max_stroke_m",
    *(f"pad{i}_peak_force_N" for i in range(1, 5)),
    "slope_deg", "downhill_azimuth_deg", "yaw_relative_to_slope_deg", "horizontal_azimuth_deg",
    "angular_rate_x_deg_s", "angular_rate_y_deg_s", "angular_rate_z_deg_s",
    "max_joint_swing_deg", "tip_over_edge", "tip_over_azimuth_deg", "min_stability_margin_m",
)

# read_sweep's `kind`: the drop kinds (drops.drop_kind) each keeps.
_KIND_ROWS = {"rig": ("rig", "free"), "lander": ("lander",)}


def read_sweep(path, traces=False, kind=None):
    """A sweep's drops as a DataFrame, one row per stored drop in drop_index order, the columns of
    the database's `drops` table (NULL metrics, failed or not applicable, as NaN). `path` is the
    results.sqlite file or the sweep's output directory. df.attrs["meta"] holds the meta table, its
    numbers as int or float and load_dependent_failures as bool. A metric NULL in every row (a
    lander column of a rig sweep) is a float column of NaN.

    The columns come in two groups, listed in table order in df.attrs: "rig_columns", those every
    drop has (its identity, status, conditions and the pad-drop metrics: final_penetration_m,
    peak_force_N, ...; a lander drop's are the whole lander's, e.g. its deepest pad), and
    "lander_columns", those only lander drops fill (LANDER_COLUMNS: per-pad penetrations and
    forces, attitudes, tipped_over, ...). kind="rig" gives the rig and free drops with the rig
    columns only; kind="lander" the lander drops with every column; None (default) every drop
    and column. The index is 0..n-1 either way.

    With traces=True, returns (drops, traces): traces maps drop_index to a DataFrame with the
    columns t_s, penetration_m, velocity_m_s, force_N (drops stored with traces only; with
    `kind`, those of the drops kept).
    """
    if kind is not None and kind not in _KIND_ROWS:
        raise ValueError(f"read_sweep: kind: must be 'rig', 'lander' or None, got {kind!r}")
    pd = _pandas()
    path = _results_db(path)
    try:
        db = _connect_reader(path)
        try:
            drops = pd.read_sql_query("SELECT * FROM drops ORDER BY drop_index", db)
            declared = {row[1]: row[2].upper() for row in db.execute("PRAGMA table_info(drops)")}
            meta = db.execute("SELECT key, value FROM meta").fetchall()
            rows = db.execute("SELECT drop_index, samples, data FROM traces ORDER BY drop_index").fetchall() \
                if traces else None
        finally:
            db.close()
    except (sqlite3.Error, pd.errors.DatabaseError) as e:
        raise ValueError(f"{path}: SQLite cannot use this database: {_sqlite_reason(e)}") from None
    # A metric that is NULL in every row (a lander column of a rig sweep) comes back from SQLite
    # as None in an object column; the table declares it REAL, so it is a float column of NaN.
    for column, declared_type in declared.items():
        if declared_type == "REAL" and drops[column].dtype == object:
            drops[column] = pd.to_numeric(drops[column], errors="coerce").astype("float64")
    drops = _of_kind(drops, kind)
    drops.attrs["meta"] = {key: _typed_meta(key, value) for key, value in meta}
    if not traces:
        return drops
    import numpy as np

    kept = set(drops["drop_index"])
    by_drop = {}
    for index, samples, blob in rows:
        if index not in kept:
            continue
        values = np.frombuffer(blob, dtype="<f8").reshape(samples, len(SWEEP_TRACE_COLUMNS))
        by_drop[index] = pd.DataFrame(values.copy(), columns=list(SWEEP_TRACE_COLUMNS))
    return drops, by_drop


def _of_kind(drops, kind):
    """The rows and columns read_sweep's `kind` keeps, with attrs["rig_columns"] and
    attrs["lander_columns"] naming the two groups of columns (see read_sweep)."""
    lander = [c for c in drops.columns if c in LANDER_COLUMNS]
    rig = [c for c in drops.columns if c not in LANDER_COLUMNS]
    if kind is not None:
        drops = drops[drops["drop_kind"].isin(_KIND_ROWS[kind])]
        drops = drops[rig] if kind == "rig" else drops
        drops = drops.reset_index(drop=True)
    drops.attrs["rig_columns"] = rig
    drops.attrs["lander_columns"] = lander if kind != "rig" else []
    return drops


# The meta table's values are text; these keys are written from numbers or a yes/no flag
# (drop_tests/sweep/sweep.cpp). Every other key (sweep_name, plan_digest, shard, source, model)
# is text.
_META_TYPES = {
    "format_version": int,
    "total_drops": int,
    "max_drop_evaluations": int,
    "max_drop_wall_time_s": float,
    # "no", or "yes: " and why the wall-clock limit makes failures load dependent.
    "load_dependent_failures": lambda text: text.startswith("yes"),
}


def _typed_meta(key, value):
    """A meta value as the type it was written from (_META_TYPES), else the text itself."""
    convert = _META_TYPES.get(key)
    if convert is None or not isinstance(value, str):
        return value
    try:
        return convert(value)
    except ValueError:
        return value  # written by another version: left as the database holds it


def _sqlite_reason(error):
    """SQLite's own words; pandas wraps them as 'Execution failed on sql ...: reason'."""
    cause = error.__cause__ or error.__context__
    return str(cause if isinstance(cause, sqlite3.Error) else error)


def _read_csv(path, **kwargs):
    pd = _pandas()
    path = os.fspath(path)
    if not os.path.exists(path):
        raise _missing(path, "file not found")
    try:
        return pd.read_csv(path, float_precision="round_trip", **kwargs)
    except (pd.errors.EmptyDataError, pd.errors.ParserError, UnicodeDecodeError, ValueError) as e:
        raise ValueError(f"{path}: not a readable CSV table: {e}") from None


# drops.csv columns that are text (drop ids such as "001" stay text).
_DATASET_TEXT_COLUMNS = {"drop_id": str, "pad": str, "soil": str, "atmosphere": str, "trace": str}


def read_dataset(directory, traces=False):
    """A dataset's drops.csv as a DataFrame (the columns drop_id, pad, soil, atmosphere,
    impact_speed_m_s, pad_mass_kg, gravity_m_s2, trace, then the optional and extra columns).

    With traces=True, returns (drops, traces): traces maps drop_id to the trace's DataFrame
    (t_s, penetration_m, force_N and any further columns).
    """
    directory = os.fspath(directory)
    drops_csv = os.path.join(directory, "drops.csv")
    if not os.path.isfile(drops_csv):
        raise _missing(directory, "no dataset (drops.csv missing)")
    _touchdown.check_dataset(directory, bool(traces))  # ValueError naming file, line and column
    drops = _read_csv(drops_csv, dtype=_DATASET_TEXT_COLUMNS, keep_default_na=False, na_values={
        c: [""] for c in ("final_penetration_m", "peak_force_N")})
    if not traces:
        return drops
    by_drop = {row.drop_id: _read_csv(os.path.join(directory, row.trace)) for row in drops.itertuples()}
    return drops, by_drop


@dataclass
class StabilityStudy:
    """A stability study's outputs (docs/stability_studies.md)."""

    summary: dict          # summary.json: landings, tip-over probability and interval, percentiles, map
    percentiles: object    # percentiles.csv: metric, unit, landings, p50, p95, p99, max
    tip_over_map: object   # tip_over_map.csv: per map cell, ranges, landings, tip-overs, probability (None: no map)
    landings: object       # results.sqlite's drops (read_sweep): one row per landing (a rare-event
                           # run's: every landing it spent, from DIR/subset/ and, for importance,
                           # DIR/importance/, with a `run` column naming the folder)


def read_stability(directory):
    """The outputs of `touchdown stability STUDY.yaml --out DIR` (a finished study: summary.json
    is written last) as a StabilityStudy of a dict and DataFrames."""
    directory = os.fspath(directory)
    summary_json = os.path.join(directory, "summary.json")
    if not os.path.isfile(summary_json):
        raise _missing(directory, "no finished stability study (summary.json missing)")
    try:
        with open(summary_json, encoding="utf-8") as f:
            summary = json.load(f)
    except (json.JSONDecodeError, UnicodeDecodeError) as e:
        raise ValueError(f"{summary_json}: not valid JSON: {e}") from None
    map_csv = os.path.join(directory, "tip_over_map.csv")  # only for a study with a `map`
    # A rare-event run (summary "method": subset or importance) keeps its subset pass, every
    # level's landings, in DIR/subset/results.sqlite; importance sampling its own pass (the design
    # point's refinement and its sample) in DIR/importance/results.sqlite.
    method = summary.get("method", "monte_carlo")
    percentiles = _read_csv(os.path.join(directory, "percentiles.csv"))
    tip_over_map = _read_csv(map_csv) if os.path.isfile(map_csv) else None
    if method == "monte_carlo":
        landings = read_sweep(directory)
    else:
        runs = ["subset"] + (["importance"] if method == "importance" else [])
        parts = [read_sweep(os.path.join(directory, run)).assign(run=run) for run in runs]
        landings = _pandas().concat(parts, ignore_index=True)
    return StabilityStudy(summary=summary, percentiles=percentiles, tip_over_map=tip_over_map, landings=landings)

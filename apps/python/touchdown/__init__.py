"""touchdown from Python: lander footpads hitting granular soil (granular RFT).

The functions mirror the command line and return what it prints, as Python objects:

    import touchdown
    summary = touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0)      # touchdown drop ...
    summary, trace = touchdown.drop(pad="flat", soil="fjs1_lp", speed=1.0, trace=True)
    touchdown.force(pad="flat", soil="fjs1_lp", depth=0.01)             # touchdown force ...
    touchdown.lander("data/scenarios/lander_case_A.yaml")                # touchdown lander ...

the workflows run as their commands do (campaign, compare, calibrate, diagnose, trade, synth,
export, sweep, stability: outputs into a new directory, the summary returned), and the readers
give pandas DataFrames of a sweep's database, a dataset and a stability study
(read_sweep, read_dataset, read_stability). Pads and soils are catalogue names ("flat",
"fjs1_lp"), YAML files, or dicts with a YAML file's content; the scenario, sweep or study a
workflow runs is a file or, as on the command line, a bundled one's name ("lander_case_B"). Bad input raises ValueError with
the command line's one-line message (naming the Python argument: "touchdown.sweep: threads: ..."),
an input file that is not there FileNotFoundError, a path the system refuses OSError, a failed
solver RuntimeError. The long calls (sweep, stability, trade, diagnose, calibrate_targets) show a
progress bar (tqdm, when installed; progress=False: none; a callable gets (done, total)), and
Ctrl-C stops them within about a second (KeyboardInterrupt), a sweep's or study's committed drops
kept for a rerun to resume. docs/python.md describes every function and field.
"""
import collections.abc
import contextlib
import json
import math
import numbers
import os
import tempfile


def _installed_data_dir():
    """An installed package (PREFIX/lib/python3/dist-packages/touchdown) uses the data installed
    beside it (PREFIX/share/touchdown), unless TOUCHDOWN_DATA_DIR says otherwise."""
    prefix = os.path.abspath(os.path.join(os.path.dirname(__file__), *[os.pardir] * 4))
    data = os.path.join(prefix, "share", "touchdown")
    if not os.environ.get("TOUCHDOWN_DATA_DIR") and os.path.isdir(os.path.join(data, "pads")):
        os.environ["TOUCHDOWN_DATA_DIR"] = data


_installed_data_dir()
from . import _touchdown  # noqa: E402

__version__ = _touchdown.__version__  # the CMake project's version, as `touchdown --version` prints
from .readers import StabilityStudy, read_dataset, read_stability, read_sweep
from .objects import Lander, Pad, Scenario, Soil  # noqa: E402
from .results import (CampaignResult, DropResult, LanderResult, SweepResult, simulate_campaign,  # noqa: E402
                      simulate_drop, simulate_lander, simulate_stability, simulate_sweep)

__all__ = ["__version__", "drop", "force", "lander", "sweep", "stability", "campaign", "compare", "calibrate", "calibrate_targets", "validate", "diagnose", "trade",
           "synth", "export", "data_dir", "read_sweep", "read_dataset", "read_stability", "StabilityStudy"]
__all__ += ["Pad", "Soil", "Lander", "Scenario", "simulate_drop", "simulate_lander", "simulate_campaign",
            "simulate_sweep", "simulate_stability", "DropResult", "LanderResult", "CampaignResult", "SweepResult"]


def data_dir():
    """The directory of the bundled pads, soils and scenarios ($TOUCHDOWN_DATA_DIR when set)."""
    return _touchdown.data_dir()


def drop(pad, soil, speed, *, mass=None, gravity=_touchdown.EARTH_GRAVITY_M_S2, zeta=None, model=None, free=False, tilt_deg=0.0,
         tilt_axis="x", horizontal_speed=0.0, omega=(0.0, 0.0, 0.0), law=None, fast=False, trace=False):
    """One drop, as `touchdown drop`: the summary dict the command prints as JSON.

    With trace=True, returns (summary, trace): trace maps the trace CSV's column names (t_s,
    penetration_m, velocity_m_s, force_N; a free drop adds force_x_N, horizontal_m, tilt_deg) to
    NumPy arrays.
    """
    with _catalog_files(pad=pad, soil=soil) as files:
        summary, columns = _touchdown.drop(
            pad=files["pad"], soil=files["soil"], speed=speed, mass=mass, gravity=gravity, zeta=zeta,
            model=_path_text(model), free=free, tilt_deg=tilt_deg, tilt_axis=tilt_axis,
            horizontal_speed=horizontal_speed, omega=tuple(omega), law=law, fast=fast, trace=trace)
    result = json.loads(summary)
    return (result, columns) if trace else result


def force(pad, soil, depth, *, tilt_deg=0.0, tilt_axis="x", velocity=(0.0, 0.0, -1.0), omega=(0.0, 0.0, 0.0),
          law=None, zeta=None, gravity=_touchdown.EARTH_GRAVITY_M_S2, dynamic=False):
    """The quasi-static soil wrench on a pad held at a depth, as `touchdown force` (a dict): force_N,
    moment_Nm [N m] about the reference point, world frame, z up. `velocity` [m/s] and `omega`
    [rad/s] give RFT its direction of motion; dynamic=True adds the soil's dynamic term at that
    velocity (`touchdown force --dynamic`)."""
    with _catalog_files(pad=pad, soil=soil) as files:
        text = _touchdown.force(pad=files["pad"], soil=files["soil"], depth=depth, tilt_deg=tilt_deg,
                                tilt_axis=tilt_axis, velocity=tuple(velocity), omega=tuple(omega), law=law,
                                zeta=zeta, gravity=gravity, dynamic=bool(dynamic))
    return json.loads(text)


def lander(scenario, *, model=None, out=None, trace=False, vtk=True):
    """A lander scenario file run as `touchdown lander`: its summary dict. With out=DIR, also its
    outputs (summary.json, trace.csv, events.csv, plots/, vtk/; vtk=False leaves vtk/ out, as
    --no-vtk) into the new directory DIR. With trace=True: (summary, {column: float64 array}), the
    columns of trace.csv under its names."""
    summary, arrays = _touchdown.lander(scenario=_path_text(scenario), model=_path_text(model),
                                        out=_path_text(out), trace=trace, vtk=vtk)
    return (json.loads(summary), arrays) if trace else json.loads(summary)


def campaign(scenario, out, *, model=None):
    """A campaign scenario file run as `touchdown campaign SCENARIO --out OUT [--model MODEL]`: the
    drops' tables, traces and figures into the new directory OUT (every drop with the model file's
    zeta and effect terms, as drop's `model`); returns its summary.json as a dict."""
    return json.loads(_touchdown.campaign(scenario=_path_text(scenario), out=_path_text(out),
                                          model=_path_text(model)))


def compare(measured, out, *, simulated=None, model=None, sensor_sampling="period_mean"):
    """`touchdown compare MEASURED --out OUT [--simulated DIR | --model MODEL] [--sensor-sampling S]`: the
    measured dataset against drops simulated here (with `model`, or the catalogue's soils; recorded as
    `sensor_sampling` says the measured ones were: "instantaneous" or "period_mean") or the `simulated`
    dataset joined on the conditions; the outputs into the new directory OUT; returns summary.json's dict."""
    if simulated is not None and model is not None:
        raise ValueError("compare: give simulated or model, not both")
    return json.loads(_touchdown.compare(measured=_path_text(measured), simulated=_path_text(simulated),
                                         model=_path_text(model), out=_path_text(out),
                                         sensor_sampling=sensor_sampling))


def calibrate(measured, out, *, law="rft", per="soil", atmosphere="all", confidence=0.95, soil=None, pad=None,
              shear_from=None, report=None):
    """`touchdown calibrate MEASURED --out OUT` (`--law --per --atmosphere --confidence --soil --pad
    --shear-from --report`): fits the measured dataset's drops and writes OUT, a model file (law "rft":
    zeta per soil, or one for all with per="all") or a Bekker soil file (law "bekker"). Returns the fit:
    {"law": "rft", "fits": [{group, soils, zeta_N_cm3, low_N_cm3, high_N_cm3, ...}]} or {"law":
    "bekker", soils, n, k_c_kN_m_n1, k_phi_kN_m_n2, drops, samples, residual_rms_N, ...}. With
    `report` (law "rft", per="soil") also writes that JSON file and returns its content: the fits,
    each soil's zeta [N/cm^3] with its covariance (what a stability study's soil_uncertainty draws
    from) and the command."""
    return json.loads(_touchdown.calibrate(
        measured=_path_text(measured), out=_path_text(out), law=law, per=per, atmosphere=atmosphere,
        confidence=confidence, soil=_path_text(soil), pad=_path_text(pad), shear_from=_path_text(shear_from),
        report=_path_text(report)))


def calibrate_targets(targets, out, *, report=None, threads=0, evaluate_only=False, progress=True):
    """`touchdown calibrate --targets TARGETS --out OUT [--report R] [--threads N] [--evaluate-only]`:
    fits the free parameters of a targets file to its published scalar targets (bounded least
    squares; docs/calibration_targets.md), writes the model file OUT (and the JSON report R), and
    returns the report as a dict: per parameter its value, bounds and interval, per target its value,
    simulated value, residual and whether it was fitted or predicted. `progress` counts the fit's
    evaluations of the targets, whose number is not known ahead (total 0; see sweep); Ctrl-C
    abandons the fit, writing nothing."""
    with _progress_reporter(progress, "calibrate_targets", "evaluations") as reporter:
        return json.loads(_touchdown.calibrate_targets(targets=_path_text(targets), out=_path_text(out),
                                                       report=_path_text(report), threads=threads,
                                                       evaluate_only=evaluate_only, progress=reporter))


def validate(*, sources=None, out=None):
    """`touchdown validate [--sources DIR] [--out OUT]`: simulates the published measurements of the
    validation sources (default: the bundled ones; docs/validation.md) and returns validation.json as
    a dict (per source measured, simulated and error per variant, and each trend's exponents); with
    `out`, also writes validation.json, validation.md and plots/ into that new directory."""
    return json.loads(_touchdown.validate(sources=_path_text(sources), out=_path_text(out)))


def diagnose(measured, out, *, model=None, threads=0, pairs=True, min_step_explained=0.5, law_candidate=False,
             base="rft", sensor_sampling="auto", fit_on=(), drop_nuisances=True, floor_from_base=False,
             count_stop_samples=False, search_within_floor=False, rig_offsets="every", refit_drops=True,
             progress=True):
    """`touchdown diagnose MEASURED --out OUT [--model M] [--threads N] [--no-pairs]
    [--min-step-explained X] [--law-candidate] [--base rft|bekker] [--sensor-sampling
    auto|instantaneous|period_mean] [--fit-on ID,...] [--no-drop-nuisances] [--floor-from-base]
    [--count-stop-samples] [--search-within-floor] [--rig-offsets every|candidate] [--no-refit-drops]`:
    the model-gap workflow into the new directory OUT
    (docs/model_gap.md); returns diagnosis.json as a dict (the command prints a part of it).
    `pairs=False` is `--no-pairs`: forward selection stops after the first term. `fit_on` (drop
    ids) is `--fit-on`: every model is fitted on those drops and predicts the others.
    `drop_nuisances=False` is `--no-drop-nuisances`: every drop at its nominal strength, speed and time.
    `floor_from_base=True` is `--floor-from-base`: the replicates' floor read from the base's residuals only.
    `count_stop_samples=True` is `--count-stop-samples`: the two samples either side of each stop counted.
    `search_within_floor=True` is `--search-within-floor`: terms added after a model within the floor.
    `rig_offsets="candidate"` is `--rig-offsets candidate`: the record's common offsets a candidate term.
    `refit_drops=False` is `--no-refit-drops`: the training drops' nuisances as the joint fit left them.
    `progress` counts the candidate models fitted (see sweep); Ctrl-C abandons the fit, writing nothing."""
    with _progress_reporter(progress, "diagnose", "fits") as report:
        return json.loads(_touchdown.diagnose(measured=_path_text(measured), model=_path_text(model),
                                              out=_path_text(out), threads=threads, pairs=pairs,
                                              min_step_explained=min_step_explained,
                                              law_candidate=law_candidate, base=base,
                                              sensor_sampling=sensor_sampling, fit_on=_id_list(fit_on, "diagnose", "fit_on"),
                                              drop_nuisances=bool(drop_nuisances),
                                              floor_from_base=bool(floor_from_base),
                                              count_stop_samples=bool(count_stop_samples),
                                              search_within_floor=bool(search_within_floor),
                                              rig_offsets=rig_offsets, refit_drops=bool(refit_drops),
                                              progress=report))


def trade(plan, out, *, model=None, threads=0, progress=True):
    """`touchdown trade PLAN --out OUT [--model M] [--threads N]`: runs, or resumes, the sweep into
    OUT, then writes trade.csv, summary.json and plots/; returns summary.json as a dict, with this
    run's counts under "run" (total, already_done, computed, failed, threads, seconds; not in the
    file). `progress` and Ctrl-C as for sweep (stopped: the drops kept, no trade outputs)."""
    with _progress_reporter(progress, "trade", "drops") as report:
        summary, run = _touchdown.trade(plan=_path_text(plan), out=_path_text(out), model=_path_text(model),
                                        threads=threads, progress=report)
    result = json.loads(summary)
    result["run"] = run
    return result


def synth(spec, out):
    """`touchdown synth SPEC --out OUT`: a SYNTHETIC measured-like dataset into the new directory
    OUT; returns read_dataset(out), with df.attrs["synth"] = {"drops": n, "hidden_effect": id or
    None}."""
    made = _touchdown.synth(spec=_path_text(spec), out=_path_text(out))
    drops = read_dataset(out)
    drops.attrs["synth"] = made
    return drops


def import_raw(mapping, out):
    """`touchdown import MAPPING --out OUT`: raw DAQ files of drop tests, as the mapping file names
    them (docs/import.md), into the new dataset directory OUT; returns read_dataset(out), with
    df.attrs["import"] the summary the command prints (name, drops, penetration_from, and per drop
    its touchdown in the raw file's clock with its uncertainty)."""
    made = json.loads(_touchdown.import_raw(mapping=_path_text(mapping), out=_path_text(out)))
    drops = read_dataset(out)
    drops.attrs["import"] = made
    return drops


__all__ += ["import_raw"]


def export(sweep, to, *, full_traces=False, threads=0):
    """`touchdown export SWEEP_DIR --to DATASET_DIR [--full-traces] [--threads N]`: a sweep's
    results as a dataset (drops.csv and traces/, or lander_drops.csv for a lander sweep) in the new
    directory `to`. Returns the counts the command prints: exported, failed, resimulated, lander."""
    return _touchdown.export(sweep=_path_text(sweep), to=_path_text(to), full_traces=full_traces, threads=threads)


def sweep(plan, out, *, model=None, threads=0, progress=True):
    """A sweep file run as `touchdown sweep PLAN --out OUT` (one process, every core unless
    `threads`, 0 to 4096; a rerun resumes): the drops as read_sweep(out) gives them. df.attrs["run"]
    holds this run's counts (total, already_done, computed, failed, threads, seconds). Ctrl-C
    stops it as it stops the command: the running drops finish and are committed, then
    KeyboardInterrupt.

    progress=True shows a tqdm bar (tqdm.auto: a widget in a notebook, text on a terminal; none
    when tqdm is not installed) once the call has run a second; False shows nothing; a callable is
    called as progress(done, total) from the calling thread, every 0.1 s while the counts change
    (total 0: not known). A callable that raises stops the call as Ctrl-C does, with its exception."""
    with _progress_reporter(progress, "sweep", "drops") as report:
        run = _touchdown.sweep(plan=_path_text(plan), out=_path_text(out), model=_path_text(model), threads=threads,
                               progress=report)
    drops = read_sweep(out)
    drops.attrs["run"] = run
    return drops


def stability(study, out, *, model=None, samples=None, threads=0, progress=True, method="monte_carlo"):
    """A stability study run as `touchdown stability STUDY --out OUT [--samples N] [--method M]`: its
    landings, then summary.json, the CSV tables and plots in OUT; returns read_stability(out).
    `method`: "monte_carlo" (the study's landings), "subset" or "importance" (the rare-event
    estimators; `samples` is then the landings per level or of the importance sample, default 1000,
    and summary.json's "rare_event" holds the coefficient of variation, landings spent and design
    points). Ctrl-C stops it once the running landings are committed (KeyboardInterrupt, no analysis
    written; a rerun resumes). `progress` as for sweep: the landings, then each follow-up's re-runs
    anew."""
    with _progress_reporter(progress, "stability", "landings") as report:
        _touchdown.stability(study=_path_text(study), out=_path_text(out), model=_path_text(model), samples=samples,
                             threads=threads, progress=report, method=method)
    return read_stability(out)


class _TqdmBar:
    """progress=True: a tqdm.auto bar (a notebook's widget, else text on stderr), made at the first
    counts and shown once the call has run a second (quick calls show nothing). A new stage (the
    total changes, or the count goes back) starts the bar anew."""

    def __init__(self, tqdm, label, unit):
        self._tqdm, self._label, self._unit = tqdm, label, unit
        self._bar, self._total = None, None

    def __call__(self, done, total):
        total = total or None  # 0: not known
        if self._bar is None or total != self._total or done < self._bar.n:
            self.close()
            self._bar = self._tqdm(total=total, desc=self._label, unit=" " + self._unit, delay=1.0,
                                   dynamic_ncols=True, leave=True)
            self._total = total
        self._bar.update(done - self._bar.n)

    def close(self):
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def _tqdm_auto():
    """tqdm.auto's bar class, or None without tqdm. Its notice that a notebook lacks ipywidgets
    (it then draws text) is no news to the user of a call."""
    import warnings
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            from tqdm.auto import tqdm
    except ImportError:
        return None
    return tqdm


@contextlib.contextmanager
def _progress_reporter(progress, function, unit):
    """What the compiled call `function` reports (done, total) to: None, the user's callable, or a
    tqdm bar closed when the call ends, however it ends."""
    if callable(progress):
        yield progress
        return
    if progress is not True and progress is not False and progress is not None:
        raise ValueError(f"touchdown.{function}: progress: must be True, False or a callable, got {progress!r}")
    tqdm = _tqdm_auto() if progress else None
    if tqdm is None:
        yield None
        return
    bar = _TqdmBar(tqdm, function, unit)
    try:
        yield bar
    finally:
        bar.close()


def _path_text(path):
    return "" if path is None else os.fspath(path)


def _id_list(ids, function, argument):
    """A list of ids from one id or an iterable of them, as ValueError names the argument otherwise."""
    ids = [ids] if isinstance(ids, str) else list(ids)
    for value in ids:
        if not isinstance(value, str):
            raise ValueError(f"touchdown.{function}: {argument}: must be drop ids (text), got '{value}'")
    return ids


@contextlib.contextmanager
def _catalog_files(**entries):
    """Names and paths as they are; each dict written as a YAML file into a temporary directory
    that the loaders read like any other (same validation, same errors: the temporary path in a
    message becomes "pad dict" or "soil dict")."""
    with tempfile.TemporaryDirectory(prefix="touchdown_") as tmp:
        files, renames = {}, {}
        for kind, value in entries.items():
            if isinstance(value, collections.abc.Mapping):
                path = os.path.join(tmp, kind + ".yaml")
                with open(path, "w", encoding="utf-8") as f:
                    f.write(_yaml_text(_absolute_mesh(value)) + "\n")
                files[kind], renames[path] = path, kind + " dict"
            else:
                files[kind] = os.fspath(value)
        try:
            yield files
        except (ValueError, OSError, RuntimeError) as e:
            message = str(e)
            if not any(path in message for path in renames):
                raise
            for path, name in renames.items():
                message = message.replace(path, name)
            renamed = type(e)(message)
            if isinstance(e, OSError):
                renamed.errno = e.errno
            raise renamed from None


def _absolute_mesh(pad):
    """A mesh file named relative in a dict is relative to the working directory (a pad file's is
    relative to the file)."""
    mesh = pad.get("mesh")
    if isinstance(mesh, dict) and isinstance(mesh.get("file"), (str, os.PathLike)):
        return {**pad, "mesh": {**mesh, "file": os.path.abspath(mesh["file"])}}
    return pad


def _yaml_text(value):
    """A dict, list or scalar as YAML flow text: strings quoted, floats in their shortest exact
    form (repr), non-finite floats as YAML's .nan and .inf, so the loader's checks see them."""
    if isinstance(value, collections.abc.Mapping):
        return "{" + ", ".join(_yaml_text(str(k)) + ": " + _yaml_text(v) for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_yaml_text(v) for v in value) + "]"
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        if math.isnan(x):
            return ".nan"
        if math.isinf(x):
            return ".inf" if x > 0 else "-.inf"
        return repr(x)
    if hasattr(value, "tolist"):  # a NumPy array or scalar
        return _yaml_text(value.tolist())
    return json.dumps(os.fspath(value) if isinstance(value, os.PathLike) else str(value), ensure_ascii=False)

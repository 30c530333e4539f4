"""Simulations whose results are objects held in memory, traces as pandas DataFrames.

    r = touchdown.simulate_drop(pad="flat", soil="fjs1_lp", speed=1.0)
    r.summary["final_penetration_m"], r.trace["force_N"]          # dict, DataFrame
    r = touchdown.simulate_lander("lander_case_A")                 # no out: nothing kept on disk
    r.trace[["t_s", "z_m", "tilt_deg"]], r.events

The functions run the same calls as touchdown.drop, lander, campaign, sweep and stability (the same
library code, the same numbers). Given `out`, the outputs are written there as by those calls and
the result is read from the run; without it, a call that writes files runs in a private
temporary directory (tempfile, prefix "touchdown_") and reads everything back into memory, and
only that directory is removed afterwards.
"""
import contextlib
import os
import tempfile
from dataclasses import dataclass, field
from typing import Optional


def _pandas():
    import pandas  # imported when used, so `import touchdown` works without pandas

    return pandas


@dataclass
class DropResult:
    """One drop: `summary`, the dict `touchdown drop` prints; `trace`, the trace CSV's columns as
    a DataFrame at full precision (t_s, penetration_m, velocity_m_s, force_N; a free drop adds
    force_x_N, horizontal_m, tilt_deg and the pose x_m .. wz_rad_s)."""

    summary: dict
    trace: object

    def __getitem__(self, key):
        """result["peak_force_N"]: the summary's value, as with the dict touchdown.drop returns."""
        return self.summary[key]


@dataclass
class LanderResult:
    """One landing: `summary` (summary.json's dict, as touchdown.lander returns it), `trace`
    (trace.csv's columns at full precision, a DataFrame), `events` (events.csv: t_s, event, pad;
    pad an Int64 column, <NA> for an event of the whole lander) and `out`, the directory the
    outputs were written to (None: they were not kept)."""

    summary: dict
    trace: object
    events: object
    out: Optional[str] = None

    def __getitem__(self, key):
        return self.summary[key]


@dataclass
class SweepResult:
    """A sweep: `drops` (read_sweep's DataFrame; attrs["run"] this run's counts), `traces`
    (drop_index to its trace's DataFrame, for a plan that stores traces; else empty) and `out`
    (None: not kept)."""

    drops: object
    traces: dict = field(default_factory=dict)
    out: Optional[str] = None


@dataclass
class CampaignResult:
    """A campaign: `summary` (summary.json's dict, as touchdown.campaign returns it), `drops`
    (summary.csv: one row per drop, its conditions, metrics and trace file), `traces` (drop_id to
    its trace CSV's DataFrame) and `out` (None: not kept)."""

    summary: dict
    drops: object
    traces: dict = field(default_factory=dict)
    out: Optional[str] = None


@contextlib.contextmanager
def _output_directory(out):
    """`out` itself; for None, a new directory inside a private temporary one that is removed,
    with only what the run wrote in it, when the block ends."""
    if out is not None:
        yield os.fspath(out)
        return
    with tempfile.TemporaryDirectory(prefix="touchdown_") as scratch:
        yield os.path.join(scratch, "run")


def simulate_drop(pad, soil, speed, **options):
    """touchdown.drop(pad, soil, speed, **options) with its trace, as a DropResult. `pad` and
    `soil` as for drop: names, paths, dicts or Pad and Soil objects."""
    from . import drop

    options.pop("trace", None)
    summary, trace = drop(pad, soil, speed, trace=True, **options)
    return DropResult(summary=summary, trace=_pandas().DataFrame(trace))


def simulate_lander(scenario, *, model=None, out=None, vtk=True):
    """touchdown.lander's landing as a LanderResult. With `out`, its outputs go into that new
    directory as with lander(out=...) (vtk=False leaves out vtk/); without, they are written to
    a private temporary directory (no vtk/), read back and removed."""
    from . import lander

    kept = out is not None
    with _output_directory(out) as directory:
        summary, trace = lander(scenario, model=model, out=directory, trace=True, vtk=vtk and kept)
        events = _read_events(os.path.join(directory, "events.csv"))
    return LanderResult(summary=summary, trace=_pandas().DataFrame(trace), events=events,
                        out=directory if kept else None)


def simulate_sweep(plan, *, out=None, model=None, threads=0):
    """touchdown.sweep's drops and stored traces as a SweepResult; without `out`, run in a
    private temporary directory, read into memory and removed (so nothing resumes later)."""
    from . import read_sweep, sweep

    kept = out is not None
    with _output_directory(out) as directory:
        drops = sweep(plan, directory, model=model, threads=threads)
        _, traces = read_sweep(directory, traces=True)
    return SweepResult(drops=drops, traces=traces, out=directory if kept else None)


def simulate_campaign(scenario, *, out=None):
    """touchdown.campaign's drops as a CampaignResult; without `out`, run in a private temporary
    directory, read into memory and removed."""
    from . import campaign
    from .readers import _read_csv

    kept = out is not None
    with _output_directory(out) as directory:
        summary = campaign(scenario, directory)
        drops = _read_csv(os.path.join(directory, "summary.csv"), dtype={"drop_id": str, "trace": str})
        traces = {row.drop_id: _read_csv(os.path.join(directory, row.trace)) for row in drops.itertuples()}
    return CampaignResult(summary=summary, drops=drops, traces=traces, out=directory if kept else None)


def simulate_stability(study, *, out=None, model=None, samples=None, threads=0):
    """touchdown.stability's StabilityStudy; without `out`, run in a private temporary directory,
    read into memory and removed."""
    from . import stability

    with _output_directory(out) as directory:
        return stability(study, directory, model=model, samples=samples, threads=threads)


def _read_events(path):
    from .readers import _read_csv

    return _read_csv(path, dtype={"t_s": "float64", "event": str, "pad": "Int64"}, keep_default_na=False,
                     na_values={"pad": [""]})

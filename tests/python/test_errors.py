"""The module refuses what the command line refuses, with messages naming Python arguments; its
readers name the file they cannot read; results on read-only storage can be read (by the readers
and by the command line's export and merge); Ctrl-C stops a study and keeps what it committed."""
import errno
import os
import shutil
import signal
import sqlite3
import subprocess
import sys
import textwrap
import time

import pytest

import touchdown
from conftest import BINARY, data_file, run_touchdown

TINY_PLAN = ("schema_version: 1\ntype: sweep\nname: tiny\nfixed: {gravity_m_s2: 9.81}\n"
             "grid: {pad: [flat], soil: [fjs1_lp], impact_speed_m_s: [1.0]}\n")
TRADE_PLAN = TINY_PLAN + "trade: {allowable_final_penetration_mm: 15, allowable_peak_force_N: 400}\n"


def _study(path, speeds):
    path.write_text("schema_version: 1\ntype: stability\nname: level\n"
                    f"lander: {{scenario: {data_file('scenarios', 'lander_case_A.yaml')}}}\n"
                    f"grid: {{impact_speed_m_s: {speeds}}}\n")
    return path


@pytest.mark.parametrize("threads", [-1, 4097, 100000, 10**6, 10**30])
def test_threads_out_of_range_raise_value_error_before_anything_runs(tmp_path, threads):
    # The command line's range (--threads 0 to 4096): refused with a message naming the argument,
    # never an abort from starting more threads than the process can.
    (tmp_path / "plan.yaml").write_text(TINY_PLAN)
    (tmp_path / "trade.yaml").write_text(TRADE_PLAN)
    study = _study(tmp_path / "study.yaml", "[0.8]")
    calls = {
        "sweep": lambda: touchdown.sweep(tmp_path / "plan.yaml", tmp_path / "s", threads=threads),
        "stability": lambda: touchdown.stability(study, tmp_path / "t", threads=threads),
        "trade": lambda: touchdown.trade(tmp_path / "trade.yaml", tmp_path / "r", threads=threads),
        "export": lambda: touchdown.export(tmp_path / "s", tmp_path / "e", threads=threads),
        "diagnose": lambda: touchdown.diagnose(tmp_path / "m", tmp_path / "d", threads=threads),
        "calibrate_targets": lambda: touchdown.calibrate_targets(tmp_path / "x.yaml", tmp_path / "x_out.yaml",
                                                                 threads=threads),
    }
    for name, call in calls.items():
        with pytest.raises(ValueError, match=rf"^touchdown\.{name}: threads: must be between 0 and 4096 threads, got "):
            call()
    assert sorted(os.listdir(tmp_path)) == ["plan.yaml", "study.yaml", "trade.yaml"]  # nothing ran


def test_threads_must_be_a_whole_number(tmp_path):
    (tmp_path / "plan.yaml").write_text(TINY_PLAN)
    for threads in (2.5, "2", True, None):
        with pytest.raises(ValueError, match=r"^touchdown\.sweep: threads: must be a whole number from 0"):
            touchdown.sweep(tmp_path / "plan.yaml", tmp_path / "s", threads=threads)


def test_the_largest_thread_count_runs(tmp_path):
    (tmp_path / "plan.yaml").write_text(TINY_PLAN)
    drops = touchdown.sweep(tmp_path / "plan.yaml", tmp_path / "s", threads=4096)
    assert drops.attrs["run"]["computed"] == 1 and list(drops["status"]) == ["ok"]


def test_samples_out_of_range_names_the_python_argument(tmp_path):
    study = tmp_path / "study.yaml"
    study.write_text("schema_version: 1\ntype: stability\nname: mc\n"
                     f"lander: {{scenario: {data_file('scenarios', 'lander_case_A.yaml')}}}\n"
                     "random: {samples: 4, seed: 1, impact_speed_m_s: {uniform: [0.5, 1.0]}}\n")
    with pytest.raises(ValueError, match=r"^touchdown\.stability: samples: must be between 1 and 1e\+09 samples, got 0$"):
        touchdown.stability(study, tmp_path / "out", samples=0)
    grid = _study(tmp_path / "grid.yaml", "[0.8]")
    with pytest.raises(ValueError, match=r"^touchdown\.stability: samples: the study .*grid\.yaml has no random block"):
        touchdown.stability(grid, tmp_path / "out", samples=5)
    assert not (tmp_path / "out").exists()


def test_diagnose_choices_name_the_python_argument(tmp_path):
    for argument, value, allowed in [("base", "bekkerr", "rft or bekker"),
                                     ("sensor_sampling", "averaged", "auto or period_mean or instantaneous"),
                                     ("min_step_explained", 1.5, r"a share in \[0, 1\]")]:
        with pytest.raises(ValueError, match=rf"^touchdown\.diagnose: {argument}: must be {allowed}, got '{value}'$"):
            touchdown.diagnose(tmp_path / "m", tmp_path / "d", **{argument: value})
    with pytest.raises(ValueError, match=r"^touchdown\.diagnose: fit_on: must be drop ids \(text\), got '3'$"):
        touchdown.diagnose(tmp_path / "m", tmp_path / "d", fit_on=["d1", 3])
    assert not (tmp_path / "d").exists()


def test_a_missing_input_file_raises_file_not_found(tmp_path):
    missing = tmp_path / "nope.yaml"
    for call in (lambda: touchdown.lander(missing), lambda: touchdown.stability(missing, tmp_path / "o"),
                 lambda: touchdown.sweep(missing, tmp_path / "o"), lambda: touchdown.campaign(missing, tmp_path / "o")):
        with pytest.raises(FileNotFoundError, match=rf"^{missing}: file not found$") as error:
            call()
        assert error.value.errno == errno.ENOENT
    with pytest.raises(FileNotFoundError, match="no sweep results database"):
        touchdown.read_sweep(tmp_path)
    with pytest.raises(FileNotFoundError, match="no finished stability study"):
        touchdown.read_stability(tmp_path)
    with pytest.raises(FileNotFoundError, match="no dataset"):
        touchdown.read_dataset(tmp_path)


def test_readers_name_the_file_they_cannot_read(tiny_sweep, tmp_path):
    # A study directory whose files are damaged: ValueError naming the file, not a parser's error.
    study = tmp_path / "study"
    study.mkdir()
    (study / "summary.json").write_text('{"landings": 4,')  # cut short
    with pytest.raises(ValueError, match=rf"^{study / 'summary.json'}: not valid JSON"):
        touchdown.read_stability(study)
    (study / "summary.json").write_text('{"landings": 4}')
    (study / "percentiles.csv").write_text("")
    with pytest.raises(ValueError, match=rf"^{study / 'percentiles.csv'}: not a readable CSV table"):
        touchdown.read_stability(study)
    (study / "results.sqlite").write_bytes(b"x" * 4096)
    with pytest.raises(ValueError, match=rf"^{study / 'results.sqlite'}: SQLite cannot use this database: "
                                         "file is not a database$"):
        touchdown.read_sweep(study)
    _, dataset = tiny_sweep
    broken = tmp_path / "dataset"
    shutil.copytree(dataset, broken)
    (broken / "drops.csv").write_text("")
    with pytest.raises(ValueError, match=rf"^{broken / 'drops.csv'}: line 1: empty file"):
        touchdown.read_dataset(broken)


# The child's prelude: its view of READ_ONLY made read-only storage, and checked to be (a write
# there fails), before the test's code runs. As root (where permissions stop no write) a read-only
# bind mount in a mount namespace of its own; otherwise the directory's permissions (0555).
_READ_ONLY_PRELUDE = textwrap.dedent("""\
    import os, subprocess, sys
    read_only = os.environ["READ_ONLY"]
    if os.geteuid() == 0:
        subprocess.run(["mount", "--bind", read_only, read_only], check=True)
        subprocess.run(["mount", "-o", "remount,ro,bind", read_only, read_only], check=True)
    try:
        open(os.path.join(read_only, "probe"), "w").close()
        sys.exit("the directory is still writable")
    except OSError:
        pass
    """)


def _run_on_read_only_storage(read_only, code):
    """Runs the Python `code` in a child that sees the directory `read_only` as read-only storage
    (skips the test where this machine cannot make it so)."""
    env = {**os.environ, "READ_ONLY": str(read_only)}
    command = [sys.executable, "-c", _READ_ONLY_PRELUDE + textwrap.dedent(code)]
    if os.geteuid() == 0:
        if not shutil.which("unshare") or subprocess.run(["unshare", "--mount", "true"], check=False).returncode:
            pytest.skip("root without a mount namespace: no way to make storage read-only here")
        command = ["unshare", "--mount", "--propagation", "private", *command]
    else:
        os.chmod(read_only, 0o555)
    try:
        return subprocess.run(command, env=env, capture_output=True, text=True, check=False, timeout=300)
    finally:
        os.chmod(read_only, 0o755)


def test_results_on_read_only_storage_can_be_read_exported_and_merged(tiny_sweep, tmp_path):
    out, _ = tiny_sweep
    read_only = tmp_path / "archive"
    shutil.copytree(out, read_only / "out")
    files = sorted(os.listdir(read_only / "out"))
    expected = touchdown.read_sweep(out)
    done = _run_on_read_only_storage(read_only, f"""
        import subprocess, touchdown
        drops = touchdown.read_sweep({str(read_only / 'out')!r})
        assert len(drops) == 4 and list(drops["status"]) == ["ok"] * 4, drops
        for args in (["export", "{read_only / 'out'}", "--to", "{tmp_path / 'dataset'}"],
                     ["merge", "{read_only / 'out'}", "--out", "{tmp_path / 'merged'}"]):
            done = subprocess.run([{BINARY!r}, *args], capture_output=True, text=True)
            assert done.returncode == 0, (args, done.stderr)
        print(drops.to_json())
        """)
    assert done.returncode == 0, done.stderr
    assert sorted(os.listdir(read_only / "out")) == files  # nothing written beside the database
    assert len(touchdown.read_dataset(tmp_path / "dataset")) == 4
    merged = touchdown.read_sweep(tmp_path / "merged")
    assert list(merged["final_penetration_m"]) == list(expected["final_penetration_m"])


def _stored_landings(db_path):
    if not os.path.exists(db_path):
        return 0
    try:
        with sqlite3.connect(f"file:{db_path}?mode=ro", uri=True) as db:
            return db.execute("SELECT COUNT(*) FROM drops").fetchone()[0]
    except sqlite3.Error:  # not created yet
        return 0


def test_ctrl_c_stops_a_study_keeping_the_committed_landings(tmp_path):
    # Enough landings that the study cannot finish before its first commit (every 0.5 s) on a fast,
    # idle machine: 30 landings of about 16 ms each once all fitted in the first transaction.
    landings_in_study = 120
    study = _study(tmp_path / "study.yaml",
                   "[" + ", ".join(f"{0.5 + 0.005 * k:.3f}" for k in range(landings_in_study)) + "]")
    out = tmp_path / "out"
    child = subprocess.Popen([sys.executable, "-c", textwrap.dedent(f"""
        import touchdown
        try:
            touchdown.stability({str(study)!r}, {str(out)!r}, threads=1)
        except KeyboardInterrupt:
            print("KeyboardInterrupt")
            raise SystemExit(130)
        """)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120
        while _stored_landings(out / "results.sqlite") == 0:  # a first landing committed
            assert child.poll() is None and time.monotonic() < deadline, child.communicate()
            time.sleep(0.1)
        child.send_signal(signal.SIGINT)
        interrupted = time.monotonic()
        stdout, stderr = child.communicate(timeout=30)
        stopped_after = time.monotonic() - interrupted
    finally:
        child.kill()
    assert child.returncode == 130 and stdout.strip() == "KeyboardInterrupt", stderr
    assert stopped_after < 10  # the landing in flight, not the study's other ones
    landings = _stored_landings(out / "results.sqlite")
    assert 0 < landings < landings_in_study
    assert not (out / "summary.json").exists()  # no analysis of a stopped study
    # A rerun resumes from what was committed.
    result = touchdown.stability(study, out, threads=2)
    assert result.summary["landings"] == landings_in_study


def test_options_in_messages_are_named_as_python_arguments(tmp_path):
    # The libraries' checks of command-line options name the Python arguments when Python calls.
    same = tmp_path / "model.yaml"
    with pytest.raises(ValueError, match=rf"^touchdown\.calibrate_targets: report: must differ from out \({same}\)$"):
        touchdown.calibrate_targets(tmp_path / "targets.yaml", same, report=same)
    with pytest.raises(ValueError, match=r"^touchdown\.calibrate: shear_from: soil 'fjs1_lp' has no bekker block"):
        touchdown.calibrate(data_file("datasets", "air_vs_vacuum_synthetic"), tmp_path / "soil.yaml", law="bekker",
                            soil="fjs1_lp", atmosphere="vacuum", shear_from="fjs1_lp")


def test_hostile_yaml_and_mesh_pads_raise_value_error_instead_of_killing_python(tmp_path):
    # An alias inside its own anchor made the loader recurse until the interpreter died; nested
    # aliases ran for minutes. Both are refused by the one YAML loader, from Python as from the CLI.
    rec = tmp_path / "rec.yaml"
    rec.write_text("a: &a [*a]\n", encoding="utf-8")
    with pytest.raises(ValueError, match=r"nested more than 64 levels deep"):
        touchdown.drop(pad=str(rec), soil="fjs1_lp", speed=1.0)
    with pytest.raises(ValueError, match=r"nested more than 64 levels deep"):
        touchdown.lander(str(rec))
    laughs = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
        "l%d: &l%d [%s]\n" % (k, k, ", ".join(["*l%d" % (k - 1)] * 10)) for k in range(1, 9))
    bomb = tmp_path / "bomb.yaml"
    bomb.write_text("schema_version: 1\nname: s\nzeta_N_cm3: 3\n" + laughs, encoding="utf-8")
    start = time.monotonic()
    with pytest.raises(ValueError, match=r"expands to more than 1000000 values"):
        touchdown.drop(pad="flat", soil=str(bomb), speed=1.0)
    assert time.monotonic() - start < 10.0
    # synth with a mesh pad killed the interpreter; it is refused naming the spec's field.
    spec = tmp_path / "hex.synth.yaml"
    spec.write_text("schema_version: 1\ntype: synth\nseed: 1\n"
                    "drops:\n  - {pads: [hex], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n", encoding="utf-8")
    with pytest.raises(ValueError, match=r"drops\[0\]\.pads: 'hex' is a mesh pad"):
        touchdown.synth(str(spec), out=str(tmp_path / "out"))
    assert not (tmp_path / "out").exists()


def test_read_dataset_checks_the_required_columns(tmp_path):
    # A drops.csv without the required columns was read as if it were a dataset.
    (tmp_path / "ds").mkdir()
    (tmp_path / "ds" / "drops.csv").write_text("drop_id,pad\nd0,flat\n")
    with pytest.raises(ValueError, match=r"drops\.csv: .*soil"):
        touchdown.read_dataset(tmp_path / "ds")


def test_a_subset_study_larger_than_memory_is_refused_naming_samples(tmp_path):
    # A billion samples per level allocated without bound before the first landing (11 GB in 24 s).
    study = tmp_path / "study.yaml"
    study.write_text("schema_version: 1\ntype: stability\nname: big\n"
                     f"lander: {{scenario: {data_file('scenarios', 'lander_case_A.yaml')}}}\n"
                     "random: {samples: 4, seed: 1, slope_deg: {uniform: [0, 10]}}\n")
    with pytest.raises(ValueError, match=r"samples: 1000000000: a subset run holds each level.s landings in memory"):
        touchdown.stability(study, tmp_path / "out", samples=10**9, method="subset")
    assert not (tmp_path / "out").exists()


def test_two_threads_writing_one_out_both_finish(tmp_path):
    # The staging name was per process: two threads writing one `out` collided ("cannot move the
    # finished file into place: Success"). Each writer stages apart now, as two processes do.
    import threading

    errors = []

    def run():
        try:
            touchdown.campaign(data_file("scenarios", "sutoh2017_single_footpad.yaml"), tmp_path / "out")
        except Exception as e:  # noqa: BLE001 - collected for the assertion
            errors.append(e)

    threads = [threading.Thread(target=run) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    assert (tmp_path / "out" / "summary.json").is_file()
    assert [p for p in os.listdir(tmp_path) if ".partial-" in p] == []

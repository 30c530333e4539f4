// The Python module's compiled part, touchdown._touchdown: the commands' library functions with
// keyword arguments, each returning the JSON text the command prints (the package, __init__.py,
// parses it, resolves pads and soils given as dicts, and adds the readers). Simulations run with
// the GIL released, so other Python threads go on meanwhile; the long calls (sweep, stability,
// trade, diagnose, calibrate_targets) stop on Ctrl-C and report their progress to a callable.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <future>
#include <iterator>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>

#include "drop_tests/dataset/calibration_run.h"
#include "drop_tests/dataset/compare.h"
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/dataset/daq_import.h"
#include "drop_tests/dataset/sensor_sampling.h"
#include "drop_tests/dataset/synth.h"
#include "drop_tests/gap/diagnose.h"
#include "drop_tests/scenario/campaign.h"
#include "drop_tests/drop/drop_request.h"
#include "drop_tests/drop/force_request.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"  // io::FormatNumber
#include "drop_tests/formats/output_path.h"
#include "drop_tests/util/progress.h"
#include "drop_tests/util/work_pool.h"
#include "drop_tests/scenario/lander_outputs.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/scenario/lander_trace_columns.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_followups.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/stability/study_rare_event.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_export.h"
#include "drop_tests/sweep/trade_run.h"
#include "drop_tests/targets/targets_calibration.h"
#include "drop_tests/validation/validate.h"
#include "lander/integ/cvode_integrator.h"
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"
#include "error_translation.h"
#include "objects_bindings.h"

namespace py = pybind11;

namespace touchdown::python {
namespace {

// A `threads` keyword argument checked as --threads is (limits::kThreads, 0: every core), before
// anything runs: a whole number, else InputError naming the argument ("touchdown.sweep: threads").
int ThreadsArgument(const py::object& value, const std::string& function) {
  const bool whole = PyIndex_Check(value.ptr()) && !PyBool_Check(value.ptr());
  if (!whole) {
    throw MakeInputError(function, "threads",
                         "must be a whole number from 0 (every core) to " + std::to_string(limits::kMaxThreads) +
                             ", got " + py::repr(value).cast<std::string>());
  }
  const py::int_ whole_value(value);
  double n = PyLong_AsDouble(whole_value.ptr());
  if (n == -1.0 && PyErr_Occurred()) {  // beyond a double: out of range all the same
    PyErr_Clear();
    n = whole_value > py::int_(0) ? HUGE_VAL : -HUGE_VAL;
  }
  limits::Require(limits::kThreads, n, function, "threads");
  return static_cast<int>(n);
}

// A long call's progress: the counts the library keeps up to date (io::ProgressCounts) from its
// threads, and the Python callable, or None, that this thread calls with (done, total) when they
// change; total 0: not known.
class ProgressReport {
 public:
  explicit ProgressReport(py::object callback) : callback_(std::move(callback)) {}
  io::ProgressCounts* counts() { return &counts_; }
  // Calls the callable if the counts changed (the GIL held). False when it raised: the Python
  // error is set.
  bool Poll() {
    if (callback_.is_none()) return true;
    const int64_t done = counts_.done.load(), total = counts_.total.load();
    if (done == shown_done_ && total == shown_total_) return true;
    shown_done_ = done, shown_total_ = total;
    try {
      callback_(done, total);
    } catch (py::error_already_set& e) {
      e.restore();
      return false;
    }
    return true;
  }

 private:
  py::object callback_;
  io::ProgressCounts counts_;
  int64_t shown_done_ = 0, shown_total_ = 0;  // nothing to tell before the job has counted
};

// Runs `work` (C++ only, no Python) on a worker thread, the GIL released, while this thread runs
// Python's signal handlers and reports progress every 0.1 s. One that raises (Ctrl-C:
// KeyboardInterrupt), or a progress callable that raises, sets `stop`: a sweep lets its running
// drops finish, commits them and returns; a fit (io::StopScope) abandons its loop at the next
// simulation; the exception goes on to the caller. Python runs signal handlers only in its main
// thread, so a call from another thread runs to the end.
template <typename Work>
auto RunInterruptible(std::atomic<int>& stop, ProgressReport& progress, Work work) {
  auto done = std::async(std::launch::async, [&stop, work = std::move(work)]() mutable {
    const io::StopScope scope(&stop);
    return work();
  });
  bool interrupted = false;
  for (;;) {
    {
      py::gil_scoped_release unlocked;
      if (done.wait_for(std::chrono::milliseconds(100)) == std::future_status::ready) break;
    }
    if (!interrupted && (PyErr_CheckSignals() != 0 || !progress.Poll())) {
      interrupted = true;
      stop.store(SIGINT);
    }
  }
  if (interrupted) {
    try {
      done.get();
    } catch (...) {  // the interruption is what the caller asked for; a later failure gives way to it
    }
    throw py::error_already_set();
  }
  auto result = done.get();
  if (!progress.Poll()) throw py::error_already_set();  // the final counts
  return result;
}

// A drop's trace as columns named as in its trace CSV (drop::WriteTraceCsv), at full precision.
py::dict TraceArrays(const drop::PadDrop& d) {
  auto column = [](const auto& samples, auto field) {
    py::array_t<double> a(static_cast<py::ssize_t>(samples.size()));
    double* out = a.mutable_data();
    for (const auto& s : samples) *out++ = s.*field;
    return a;
  };
  py::dict trace;
  if (d.free) {
    const auto& s = d.free->trace;
    using S = pad::FreeDropSample;
    trace["t_s"] = column(s, &S::t_s);
    trace["penetration_m"] = column(s, &S::penetration_m);
    trace["velocity_m_s"] = column(s, &S::velocity_m_s);
    trace["force_N"] = column(s, &S::force_N);
    trace["force_x_N"] = column(s, &S::force_x_N);
    trace["horizontal_m"] = column(s, &S::horizontal_m);
    trace["tilt_deg"] = column(s, &S::tilt_deg);
    // The pose columns of the trace CSV (drop_tests/drop/free_drop_output.cpp), in its order.
    auto component = [&s](auto field, int k) {
      py::array_t<double> a(static_cast<py::ssize_t>(s.size()));
      double* out = a.mutable_data();
      for (const S& x : s) *out++ = (x.*field)[k];
      return a;
    };
    const char* position[3] = {"x_m", "y_m", "z_m"};
    const char* quaternion[4] = {"qw", "qx", "qy", "qz"};
    const char* rate[3] = {"wx_rad_s", "wy_rad_s", "wz_rad_s"};
    for (int k = 0; k < 3; ++k) trace[position[k]] = component(&S::p_WB, k);
    for (int k = 0; k < 4; ++k) trace[quaternion[k]] = component(&S::q_WB, k);
    for (int k = 0; k < 3; ++k) trace[rate[k]] = component(&S::w_W, k);
  } else {
    const auto& s = d.result.trace;
    using S = pad::DropSample;
    trace["t_s"] = column(s, &S::t_s);
    trace["penetration_m"] = column(s, &S::penetration_m);
    trace["velocity_m_s"] = column(s, &S::velocity_m_s);
    trace["force_N"] = column(s, &S::force_N);
  }
  return trace;
}

// touchdown drop: the summary JSON text and, when asked, the trace's columns (else None).
py::tuple Drop(const drop::DropRequest& request, bool with_trace) {
  const drop::RequestNaming naming{"touchdown.drop", false};
  const drop::DropConditions conditions = drop::RequestConditions(request, naming);
  std::optional<drop::PadDrop> result;
  {
    py::gil_scoped_release unlocked;
    const io::PadSpec pad = drop::RequestPad(request, naming);
    result = drop::RunDrop(drop::ResolveDropRequest(request, pad, conditions, naming));
  }
  const std::string summary = drop::RequestSummaryJson(request, *result).dump(2);
  return py::make_tuple(summary, with_trace ? py::object(TraceArrays(*result)) : py::object(py::none()));
}

std::string Force(const drop::ForceRequest& request) {
  py::gil_scoped_release unlocked;
  return drop::ForceJson(request, {"touchdown.force", false}).dump(2);
}

// The lander trace's columns (trace.csv's, scenario::LanderTraceColumns) as arrays.
py::dict LanderTraceArrays(const std::vector<lander::LanderSample>& trace) {
  py::dict arrays;
  for (const scenario::LanderTraceColumn& c : scenario::LanderTraceColumns()) {
    py::array_t<double> a(static_cast<py::ssize_t>(trace.size()));
    double* out = a.mutable_data();
    for (const lander::LanderSample& s : trace) *out++ = c.value(s);
    arrays[py::str(c.name)] = a;
  }
  return arrays;
}

// touchdown lander: the summary JSON text and, when asked, the trace's columns (else None); the
// outputs into `out` when given (a new directory).
py::tuple Lander(const std::string& scenario_arg, const std::string& model, const std::string& out, bool with_trace,
                 bool vtk) {
  std::optional<scenario::LanderRun> run;
  {
    py::gil_scoped_release unlocked;
    const std::string scenario_path = io::ResolveInputDocument(io::InputDocument::kLander, scenario_arg);
    const io::OutputTarget target(out, {scenario_path, model});
    if (!out.empty()) io::CheckOutputDirectory(target, io::OutputKind::kLander);
    scenario::LanderScenario scenario = scenario::LoadLanderScenario(scenario_path);
    if (!model.empty()) scenario.model = model::LoadModelFile(model);
    run = scenario::RunLanderScenario(scenario);
    if (!out.empty()) scenario::WriteLanderOutputs(*run, target, {.vtk = vtk});
  }
  const std::string summary = scenario::LanderSummaryJson(*run).dump(2);
  return py::make_tuple(summary, with_trace ? py::object(LanderTraceArrays(run->result.trace)) : py::object(py::none()));
}

// touchdown sweep (one process, progress to the callable): runs, or resumes, the plan's drops into
// out/results.sqlite; the run's counts.
py::dict RunCounts(const sweep::SweepRunSummary& s) {
  py::dict d;
  d["total"] = s.total, d["already_done"] = s.already_done, d["computed"] = s.computed, d["failed"] = s.failed;
  d["threads"] = s.threads, d["seconds"] = s.seconds;
  return d;
}

py::dict Sweep(const std::string& plan_arg, const std::string& out, const std::string& model,
               const py::object& threads_arg, py::object progress_arg) {
  const int threads = ThreadsArgument(threads_arg, "touchdown.sweep");
  const std::string plan_path = io::ResolveInputDocument(io::InputDocument::kSweep, plan_arg);
  std::atomic<int> stop{0};
  ProgressReport progress(std::move(progress_arg));
  return RunCounts(RunInterruptible(stop, progress, [&] {
    const sweep::SweepPlan plan = sweep::LoadSweepPlan(plan_path, model);
    io::OpenOutputDirectory({out, {plan_path, model}}, io::OutputKind::kSweep);
    sweep::SweepRunOptions options;
    options.threads = threads;
    options.progress = sweep::ProgressMode::kNone;
    options.progress_counts = progress.counts();
    options.stop = &stop;
    return sweep::RunSweep(plan, out, options);
  }));
}

// touchdown campaign: the drops into `out` (a new directory); its summary.json's text.
std::string Campaign(const std::string& scenario_arg, const std::string& out, const std::string& model) {
  py::gil_scoped_release unlocked;
  const std::string scenario_path = io::ResolveInputDocument(io::InputDocument::kCampaign, scenario_arg);
  const io::OutputTarget target(out, {scenario_path, model});
  io::CheckOutputDirectory(target, io::OutputKind::kCampaign);
  scenario::CampaignScenario scenario = scenario::LoadCampaignScenario(scenario_path);
  if (!model.empty()) scenario::SetCampaignModel(scenario, model);
  scenario::RunCampaignToDirectory(scenario, target);
  std::ifstream in(std::filesystem::path(out) / "summary.json");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// touchdown compare: the comparison (summary.json's content) and its outputs in `out`.
std::string Compare(const std::string& measured, const std::string& simulated, const std::string& model,
                    const std::string& out, const std::string& sensor_sampling) {
  const std::optional<pad::SensorSampling> sampling = dataset::ParseSensorSampling(sensor_sampling);
  if (!sampling)
    throw MakeInputError("touchdown.compare", "sensor_sampling",
                         "must be " + dataset::SensorSamplingChoices() + ", got '" + sensor_sampling + "'");
  py::gil_scoped_release unlocked;
  const io::OutputTarget target(out, {measured, simulated, model});
  return dataset::ComparisonJson(dataset::RunComparison(measured, simulated, model, target, *sampling)).dump(2);
}

// touchdown stability: the study's landings as a sweep into `out`, then its analysis there.
// Stopped (Ctrl-C), the committed landings stay for a rerun to resume; no analysis is written.
py::dict Stability(const std::string& study_arg, const std::string& out, const std::string& model,
                   std::optional<int64_t> samples, const py::object& threads_arg, py::object progress_arg,
                   const std::string& method_arg) {
  const int threads = ThreadsArgument(threads_arg, "touchdown.stability");
  const std::string study_path = io::ResolveInputDocument(io::InputDocument::kStudy, study_arg);
  const stability::StudyMethod method = stability::ParseStudyMethod(method_arg, "method");
  const bool rare_event = method != stability::StudyMethod::kMonteCarlo;
  std::atomic<int> stop{0};
  ProgressReport progress(std::move(progress_arg));
  return RunCounts(RunInterruptible(stop, progress, [&] {
    // With a rare-event method `samples` is the landings per level (or of the importance sample).
    const stability::Study study =
        stability::LoadStudy(study_path, model, rare_event ? std::nullopt : samples, {"touchdown.stability", false});
    const int64_t per_level = samples.value_or(stability::kDefaultRareEventSamples);
    if (rare_event) stability::RequireRareEventStudy(study, method, per_level);
    io::OpenOutputDirectory({out, {study_path, model}}, io::OutputKind::kSweep);
    sweep::SweepRunOptions options;
    options.threads = threads;
    options.progress = sweep::ProgressMode::kNone;
    options.progress_counts = progress.counts();  // the landings, then each follow-up's
    options.stop = &stop;
    if (rare_event) {  // the CLI's `--method` path (apps/stability_command.cpp), the same analysis
      const stability::RareEventStudyResult r = stability::RunRareEventStudy(study, method, per_level, out, options);
      sweep::SweepRunSummary s;
      s.total = r.landings, s.already_done = r.already_done, s.computed = r.computed, s.failed = r.failed;
      s.stop_signal = r.stop_signal, s.threads = threads;
      if (r.stop_signal == 0) stability::WriteRareEventAnalysis(study, r, out);
      return s;
    }
    const sweep::SweepRunSummary s = sweep::RunSweep(study.plan, out, options);
    if (s.stop_signal != 0) return s;
    // The follow-ups (re-checks, joint-range sensitivity) on the same threads, stopped alike.
    const stability::StudyFollowUps f =
        stability::RunStudyFollowUps(study, stability::ReadStudyRecords(study, out), out, options);
    if (f.stop_signal == 0) stability::WriteStudyAnalysis(study, out, f);
    return s;
  }));
}

// touchdown calibrate: the fit (dataset::CalibrationJson) and the model or soil file `out`.
std::string Calibrate(const std::string& measured, const std::string& out, const std::string& law,
                      const std::string& per, const std::string& atmosphere, double confidence, const std::string& soil,
                      const std::string& pad, const std::string& shear_from, const std::string& report) {
  const auto fail = [](const std::string& field, const std::string& allowed, const std::string& value) {
    throw MakeInputError("touchdown.calibrate", field, "must be " + allowed + ", got '" + value + "'");
  };
  dataset::CalibrationRequest r;
  r.measured = measured, r.out = out, r.confidence = confidence;
  r.law = dataset::ParseCalibrationLaw(law, "touchdown.calibrate", "law");
  if (per != "soil" && per != "all") fail("per", "soil or all", per);
  r.per_soil = per == "soil";
  if (atmosphere != "all") {
    r.atmosphere = rft::ParseAtmosphere(atmosphere);
    if (!r.atmosphere) fail("atmosphere", "vacuum, air or all", atmosphere);
  }
  if (!(confidence >= limits::kMinConfidence && confidence <= limits::kMaxConfidence))
    throw MakeInputError("touchdown.calibrate", "confidence", "must be between 0.5 and 0.9999, got " + std::to_string(confidence));
  r.soil = soil, r.pad = pad, r.shear_from = shear_from, r.report = report;
  r.naming = {"touchdown.calibrate", false};
  py::gil_scoped_release unlocked;
  const dataset::CalibrationRun run = dataset::RunCalibration(r);
  return (report.empty() ? dataset::CalibrationJson(run) : dataset::ZetaCalibrationReportJson(r, run)).dump(2);
}

// touchdown calibrate --targets: the report's content (targets::TargetsCalibrationReportJson), the model file in `out`.
std::string CalibrateTargets(const std::string& targets_file, const std::string& out, const std::string& report,
                             const py::object& threads_arg, bool evaluate_only, py::object progress_arg) {
  const int threads = ThreadsArgument(threads_arg, "touchdown.calibrate_targets");
  std::atomic<int> stop{0};
  ProgressReport progress(std::move(progress_arg));
  return RunInterruptible(stop, progress, [&] {
    targets::TargetsCalibrationRequest r;
    r.targets = targets_file, r.out = out, r.report = report, r.threads = threads, r.evaluate_only = evaluate_only;
    r.naming = {"touchdown.calibrate_targets", false};
    r.progress.counts = progress.counts();
    const targets::TargetsCalibration c = targets::RunTargetsCalibration(r);
    return targets::TargetsCalibrationReportJson(r, c).dump(2);
  });
}

// touchdown validate: validation.json's content; the outputs in `out` when given.
std::string Validate(const std::string& sources, const std::string& out) {
  py::gil_scoped_release unlocked;
  return validation::ValidationJson(validation::ValidateSources(sources, out)).dump(2);
}

// touchdown diagnose: diagnosis.json's content, the outputs in `out`.
std::string Diagnose(const std::string& measured, const std::string& model, const std::string& out,
                     const py::object& threads_arg, bool pairs, double min_step_explained, bool law_candidate,
                     const std::string& base, const std::string& sensor_sampling,
                     const std::vector<std::string>& fit_on, bool drop_nuisances, bool floor_from_base,
                     bool count_stop_samples, bool search_within_floor, const std::string& rig_offsets,
                     bool refit_drops, py::object progress_arg) {
  const int threads = ThreadsArgument(threads_arg, "touchdown.diagnose");
  const auto fail = [](const std::string& field, const std::string& allowed, const std::string& value) {
    throw MakeInputError("touchdown.diagnose", field, "must be " + allowed + ", got '" + value + "'");
  };
  const gap::DiagnoseBase diagnose_base = gap::ParseDiagnoseBase(base, "touchdown.diagnose", "base");
  const gap::RigOffsets offsets = gap::ParseRigOffsets(rig_offsets, "touchdown.diagnose", "rig_offsets");
  const std::optional<pad::SensorSampling> sampling = dataset::ParseSensorSampling(sensor_sampling);
  if (!sampling && sensor_sampling != "auto")
    fail("sensor_sampling", "auto or " + dataset::SensorSamplingChoices(), sensor_sampling);
  if (!(min_step_explained >= 0.0 && min_step_explained <= 1.0))
    fail("min_step_explained", "a share in [0, 1]", io::FormatNumber(min_step_explained));
  std::atomic<int> stop{0};
  ProgressReport progress(std::move(progress_arg));
  return RunInterruptible(stop, progress, [&] {
    gap::DiagnoseOptions o;
    o.threads = io::ThreadsFor(threads);
    o.try_pairs = pairs;
    o.min_step_explained = min_step_explained;
    o.law_candidate = law_candidate;
    o.fit_on = fit_on;
    o.base = diagnose_base;
    o.sensor_sampling = sampling;  // nullopt: auto
    o.drop_nuisances = drop_nuisances;
    o.refit_drops = refit_drops;
    o.floor_from_best_model = !floor_from_base;
    o.skip_stop_samples = !count_stop_samples;
    o.stop_within_floor = !search_within_floor;
    o.rig_offsets = offsets;
    o.progress.counts = progress.counts();
    if (!model.empty()) o.start_model = model::LoadModelFile(model);
    return gap::DiagnosisJson(gap::DiagnoseToDirectory(measured, o, {out, {measured, model}})).dump(2);
  });
}

// touchdown trade: summary.json's content (sweep::TradeJson) and the sweep's run counts.
py::tuple Trade(const std::string& plan_path, const std::string& out, const std::string& model,
                const py::object& threads_arg, py::object progress_arg) {
  const int threads = ThreadsArgument(threads_arg, "touchdown.trade");
  std::atomic<int> stop{0};
  ProgressReport progress(std::move(progress_arg));
  const sweep::TradeRun run = RunInterruptible(stop, progress, [&] {
    sweep::SweepRunOptions options;
    options.threads = threads;
    options.progress = sweep::ProgressMode::kNone;
    options.progress_counts = progress.counts();
    options.stop = &stop;
    return sweep::RunTrade(io::ResolveInputDocument(io::InputDocument::kTrade, plan_path), model, out, options);
  });
  return py::make_tuple(sweep::TradeJson(run.rows, run.limits).dump(2), RunCounts(run.sweep));
}

// touchdown synth: the dataset into `out`; what the command reports (drops, the hidden effect).
py::dict Synth(const std::string& spec_path, const std::string& out) {
  std::optional<dataset::SynthRun> run;
  {
    py::gil_scoped_release unlocked;
    run = dataset::SynthesizeToDirectory(spec_path, {out, {spec_path}});
  }
  py::dict d;
  d["drops"] = run->drops;
  d["hidden_effect"] = run->spec.hidden_effect ? py::object(py::str(run->spec.hidden_effect->id))
                       : run->spec.floor      ? py::object(py::str("floor_stiffening"))
                                              : py::object(py::none());
  return d;
}

// touchdown export: the sweep `dir` as the dataset `to`; the counts the command reports.
py::dict Export(const std::string& dir, const std::string& to, bool full_traces, const py::object& threads_arg) {
  const int threads = ThreadsArgument(threads_arg, "touchdown.export");
  sweep::ExportSummary s;
  {
    py::gil_scoped_release unlocked;
    const io::OutputTarget out(to, {dir});
    io::CheckOutputDirectory(out, io::OutputKind::kDataset);
    sweep::ExportOptions options;
    options.full_traces = full_traces;
    options.threads = threads;
    s = sweep::ExportSweep(dir, out, options);
  }
  py::dict d;
  d["exported"] = s.exported, d["failed"] = s.failed, d["resimulated"] = s.resimulated, d["lander"] = s.lander;
  return d;
}

}  // namespace
}  // namespace touchdown::python

PYBIND11_MODULE(_touchdown, m) {
  using namespace touchdown;
  m.doc() = "touchdown's compiled core; use the touchdown package (docs/python.md)";
  m.attr("__version__") = TOUCHDOWN_VERSION;  // the CMake project's version, as `touchdown --version`
  // The package's default gravity, the same constant as the commands' (rft/gravity_constants.h).
  m.attr("EARTH_GRAVITY_M_S2") = rft::kEarthGravity_m_s2;
  py::register_exception_translator(&python::TranslateErrors);
  m.def("data_dir", &io::DataDirectory, "The directory of the bundled pads, soils and scenarios");
  // read_dataset's check: the dataset reader's, before pandas reads the files (its columns,
  // numbers and ids, and with traces each trace's), so a drops.csv without a required column is
  // refused here as `compare` or `diagnose` refuse it.
  m.def(
      "check_dataset",
      [](const std::string& directory, bool traces) {
        dataset::DatasetReadOptions options;
        options.load_traces = traces;
        options.check_catalog = false;  // a dataset may name pads and soils this machine lacks
        dataset::ReadDataset(directory, options);
      },
      py::arg("directory"), py::arg("traces"));
  m.def(
      "drop",
      [](std::string pad, std::string soil, double speed, std::optional<double> mass, double gravity,
         std::optional<double> zeta, std::string model, bool free, double tilt_deg, std::string tilt_axis,
         double horizontal_speed, std::array<double, 3> omega, std::optional<std::string> law, bool fast, bool trace) {
        drop::DropRequest r;
        r.pad = std::move(pad), r.soil = std::move(soil), r.model = std::move(model);
        r.speed_m_s = speed, r.mass_kg = mass, r.gravity_m_s2 = gravity, r.zeta_N_cm3 = zeta;
        r.free = free, r.tilt_deg = tilt_deg, r.tilt_axis = std::move(tilt_axis);
        r.horizontal_speed_m_s = horizontal_speed, r.omega_rad_s = omega, r.law = std::move(law);
        r.fast = fast;
        return python::Drop(r, trace);
      },
      py::arg("pad"), py::arg("soil"), py::arg("speed"), py::arg("mass"), py::arg("gravity"), py::arg("zeta"),
      py::arg("model"), py::arg("free"), py::arg("tilt_deg"), py::arg("tilt_axis"), py::arg("horizontal_speed"),
      py::arg("omega"), py::arg("law"), py::arg("fast"), py::arg("trace"));
  m.def(
      "force",
      [](std::string pad, std::string soil, double depth, double tilt_deg, std::string tilt_axis,
         std::array<double, 3> velocity, std::array<double, 3> omega, std::optional<std::string> law, std::optional<double> zeta,
         double gravity, bool dynamic) {
        drop::ForceRequest r;
        r.pad = std::move(pad), r.soil = std::move(soil), r.depth_m = depth, r.tilt_deg = tilt_deg;
        r.tilt_axis = std::move(tilt_axis), r.velocity_m_s = velocity, r.omega_rad_s = omega;
        r.law = std::move(law), r.zeta_N_cm3 = zeta, r.gravity_m_s2 = gravity, r.dynamic = dynamic;
        return python::Force(r);
      },
      py::arg("pad"), py::arg("soil"), py::arg("depth"), py::arg("tilt_deg"), py::arg("tilt_axis"),
      py::arg("velocity"), py::arg("omega"), py::arg("law"), py::arg("zeta"), py::arg("gravity"), py::arg("dynamic"));
  m.def("lander", &python::Lander, py::arg("scenario"), py::arg("model"), py::arg("out"), py::arg("trace"),
        py::arg("vtk"));
  m.def("calibrate", &python::Calibrate, py::arg("measured"), py::arg("out"), py::arg("law"), py::arg("per"),
        py::arg("atmosphere"), py::arg("confidence"), py::arg("soil"), py::arg("pad"), py::arg("shear_from"), py::arg("report"));
  m.def("diagnose", &python::Diagnose, py::arg("measured"), py::arg("model"), py::arg("out"), py::arg("threads"),
        py::arg("pairs"), py::arg("min_step_explained"), py::arg("law_candidate"), py::arg("base"),
        py::arg("sensor_sampling"), py::arg("fit_on"), py::arg("drop_nuisances") = true,
        py::arg("floor_from_base") = false, py::arg("count_stop_samples") = false,
        py::arg("search_within_floor") = false, py::arg("rig_offsets") = "every", py::arg("refit_drops") = true,
        py::arg("progress") = py::none());
  m.def("calibrate_targets", &python::CalibrateTargets, py::arg("targets"), py::arg("out"), py::arg("report"),
        py::arg("threads"), py::arg("evaluate_only"), py::arg("progress") = py::none());
  m.def("validate", &python::Validate, py::arg("sources"), py::arg("out"));
  m.def("trade", &python::Trade, py::arg("plan"), py::arg("out"), py::arg("model"), py::arg("threads"),
        py::arg("progress") = py::none());
  m.def("synth", &python::Synth, py::arg("spec"), py::arg("out"));
  // touchdown import: the dataset into `out`; the summary the command prints, as JSON text.
  m.def(
      "import_raw",
      [](const std::string& mapping, const std::string& out) {
        py::gil_scoped_release unlocked;
        return dataset::ImportSummaryJson(dataset::ImportToDirectory(mapping, {out, {mapping}}), out).dump(2);
      },
      py::arg("mapping"), py::arg("out"));
  m.def("export", &python::Export, py::arg("sweep"), py::arg("to"), py::arg("full_traces"), py::arg("threads"));
  m.def("campaign", &python::Campaign, py::arg("scenario"), py::arg("out"), py::arg("model"));
  m.def("compare", &python::Compare, py::arg("measured"), py::arg("simulated"), py::arg("model"), py::arg("out"),
        py::arg("sensor_sampling"));
  m.def("sweep", &python::Sweep, py::arg("plan"), py::arg("out"), py::arg("model"), py::arg("threads"),
        py::arg("progress") = py::none());
  m.def("stability", &python::Stability, py::arg("study"), py::arg("out"), py::arg("model"), py::arg("samples"),
        py::arg("threads"), py::arg("progress") = py::none(), py::arg("method") = "monte_carlo");
  python::RegisterObjectBindings(m);  // Pad, Soil, Lander, Scenario (objects_bindings.cpp)
}

// The Python module's compiled part, touchdown._touchdown: the commands' library functions with
// keyword arguments, each returning the JSON text the command prints (the package, __init__.py,
// parses it, resolves pads and soils given as dicts, and adds the readers). Simulations run with
// the GIL released, so other Python threads go on meanwhile.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "drop_tests/dataset/compare.h"
#include "drop_tests/scenario/campaign.h"
#include "drop_tests/drop/drop_request.h"
#include "drop_tests/drop/force_request.h"
#include "drop_tests/io/catalog.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/scenario/lander_scenario.h"
#include "drop_tests/scenario/lander_trace_columns.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/sweep/sweep.h"
#include "lander/integ/cvode_integrator.h"
#include "rft/input_error.h"

namespace py = pybind11;

namespace touchdown::python {
namespace {

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
    result = drop::RunDropRequest(request, conditions);
  }
  const std::string summary = drop::SummaryJson(*result).dump(2);
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
py::tuple Lander(const std::string& scenario_path, const std::string& model, const std::string& out, bool with_trace) {
  std::optional<scenario::LanderRun> run;
  {
    py::gil_scoped_release unlocked;
    const io::OutputTarget target(out, {scenario_path, model});
    if (!out.empty()) io::CheckOutputDirectory(target, io::OutputKind::kLander);
    scenario::LanderScenario scenario = scenario::LoadLanderScenario(scenario_path);
    if (!model.empty()) scenario.model = model::LoadModelFile(model);
    run = scenario::RunLanderScenario(scenario);
    if (!out.empty()) scenario::WriteLanderOutputs(*run, target);
  }
  const std::string summary = scenario::LanderSummaryJson(*run).dump(2);
  return py::make_tuple(summary, with_trace ? py::object(LanderTraceArrays(run->result.trace)) : py::object(py::none()));
}

// touchdown sweep (one process, no progress output): runs, or resumes, the plan's drops into
// out/results.sqlite; the run's counts.
py::dict RunCounts(const sweep::SweepRunSummary& s) {
  py::dict d;
  d["total"] = s.total, d["already_done"] = s.already_done, d["computed"] = s.computed, d["failed"] = s.failed;
  d["threads"] = s.threads, d["seconds"] = s.seconds;
  return d;
}

py::dict Sweep(const std::string& plan_path, const std::string& out, const std::string& model, int threads) {
  sweep::SweepRunSummary s;
  {
    py::gil_scoped_release unlocked;
    const sweep::SweepPlan plan = sweep::LoadSweepPlan(plan_path, model);
    io::OpenOutputDirectory({out, {plan_path, model}}, io::OutputKind::kSweep);
    sweep::SweepRunOptions options;
    options.threads = threads;
    options.progress = sweep::ProgressMode::kNone;
    s = sweep::RunSweep(plan, out, options);
  }
  return RunCounts(s);
}

// touchdown campaign: the drops into `out` (a new directory); its summary.json's text.
std::string Campaign(const std::string& scenario_path, const std::string& out) {
  py::gil_scoped_release unlocked;
  const io::OutputTarget target(out, {scenario_path});
  io::CheckOutputDirectory(target, io::OutputKind::kCampaign);
  scenario::RunCampaignToDirectory(scenario::LoadCampaignScenario(scenario_path), target);
  std::ifstream in(std::filesystem::path(out) / "summary.json");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// touchdown compare: the comparison (summary.json's content) and its outputs in `out`.
std::string Compare(const std::string& measured, const std::string& simulated, const std::string& model,
                    const std::string& out) {
  py::gil_scoped_release unlocked;
  const io::OutputTarget target(out, {measured, simulated, model});
  return dataset::ComparisonJson(dataset::RunComparison(measured, simulated, model, target)).dump(2);
}

// touchdown stability: the study's landings as a sweep into `out`, then its analysis there.
py::dict Stability(const std::string& study_path, const std::string& out, const std::string& model,
                   std::optional<int64_t> samples, int threads) {
  sweep::SweepRunSummary s;
  {
    py::gil_scoped_release unlocked;
    const stability::Study study = stability::LoadStudy(study_path, model, samples);
    io::OpenOutputDirectory({out, {study_path, model}}, io::OutputKind::kSweep);
    sweep::SweepRunOptions options;
    options.threads = threads;
    options.progress = sweep::ProgressMode::kNone;
    s = sweep::RunSweep(study.plan, out, options);
    stability::WriteStudyAnalysis(study, out);
  }
  return RunCounts(s);
}

// The command line's exit statuses as Python exceptions, with the same one-line messages:
// bad input (2) ValueError, a path the OS refused (2) OSError, a failed solver (3) RuntimeError.
void TranslateErrors(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const InputError& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const integ::IntegrationFailure& e) {
    PyErr_SetString(PyExc_RuntimeError, (std::string("integration failed: ") + e.what()).c_str());
  } catch (const std::filesystem::filesystem_error& e) {
    const std::string path = e.path1().empty() ? std::string("a path") : e.path1().string();
    PyErr_SetString(PyExc_OSError, (path + ": " + e.code().message()).c_str());
  }
}

}  // namespace
}  // namespace touchdown::python

PYBIND11_MODULE(_touchdown, m) {
  using namespace touchdown;
  m.doc() = "touchdown's compiled core; use the touchdown package (docs/python.md)";
  py::register_exception_translator(&python::TranslateErrors);
  m.def("data_dir", &io::DataDirectory, "The directory of the bundled pads, soils and scenarios");
  m.def(
      "drop",
      [](std::string pad, std::string soil, double speed, std::optional<double> mass, double gravity,
         std::optional<double> zeta, std::string model, bool free, double tilt_deg, std::string tilt_axis,
         double horizontal_speed, std::array<double, 3> omega, std::optional<std::string> law, bool trace) {
        drop::DropRequest r;
        r.pad = std::move(pad), r.soil = std::move(soil), r.model = std::move(model);
        r.speed_m_s = speed, r.mass_kg = mass, r.gravity_m_s2 = gravity, r.zeta_N_cm3 = zeta;
        r.free = free, r.tilt_deg = tilt_deg, r.tilt_axis = std::move(tilt_axis);
        r.horizontal_speed_m_s = horizontal_speed, r.omega_rad_s = omega, r.law = std::move(law);
        return python::Drop(r, trace);
      },
      py::arg("pad"), py::arg("soil"), py::arg("speed"), py::arg("mass"), py::arg("gravity"), py::arg("zeta"),
      py::arg("model"), py::arg("free"), py::arg("tilt_deg"), py::arg("tilt_axis"), py::arg("horizontal_speed"),
      py::arg("omega"), py::arg("law"), py::arg("trace"));
  m.def(
      "force",
      [](std::string pad, std::string soil, double depth, double tilt_deg, std::string tilt_axis,
         std::array<double, 3> velocity, std::array<double, 3> omega, std::optional<std::string> law, std::optional<double> zeta,
         double gravity) {
        drop::ForceRequest r;
        r.pad = std::move(pad), r.soil = std::move(soil), r.depth_m = depth, r.tilt_deg = tilt_deg;
        r.tilt_axis = std::move(tilt_axis), r.velocity_m_s = velocity, r.omega_rad_s = omega;
        r.law = std::move(law), r.zeta_N_cm3 = zeta, r.gravity_m_s2 = gravity;
        return python::Force(r);
      },
      py::arg("pad"), py::arg("soil"), py::arg("depth"), py::arg("tilt_deg"), py::arg("tilt_axis"),
      py::arg("velocity"), py::arg("omega"), py::arg("law"), py::arg("zeta"), py::arg("gravity"));
  m.def("lander", &python::Lander, py::arg("scenario"), py::arg("model"), py::arg("out"), py::arg("trace"));
  m.def("campaign", &python::Campaign, py::arg("scenario"), py::arg("out"));
  m.def("compare", &python::Compare, py::arg("measured"), py::arg("simulated"), py::arg("model"), py::arg("out"));
  m.def("sweep", &python::Sweep, py::arg("plan"), py::arg("out"), py::arg("model"), py::arg("threads"));
  m.def("stability", &python::Stability, py::arg("study"), py::arg("out"), py::arg("model"), py::arg("samples"),
        py::arg("threads"));
}

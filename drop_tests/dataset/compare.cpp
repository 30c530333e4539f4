#include "drop_tests/dataset/compare.h"

#include "drop_tests/dataset/calibrate.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "drop_tests/dataset/sensor_model.h"
#include "drop_tests/formats/json_number.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/dataset/calibrate.h"
#include "drop_tests/dataset/sensor_sampling.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/formats/plot_decimation.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/plot_runner.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::dataset {

namespace fs = std::filesystem;

namespace {
bool Close(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); }

double ExtraOrZero(const Dataset& ds, const DatasetDrop& d, const std::string& column) {
  return ds.ExtraNumber(d, column).value_or(0.0);
}

// The mean over the defined (finite) values; `used` counts them.
double Mean(const std::vector<double>& v, size_t* used = nullptr) {
  double s = 0.0;
  size_t n = 0;
  for (double x : v)
    if (std::isfinite(x)) s += x, ++n;
  if (used) *used = n;
  return n ? s / n : std::nan("");
}

double RelError(double simulated, double measured) {
  return measured != 0.0 ? (simulated - measured) / measured : std::nan("");
}

}  // namespace

double InterpolateClamped(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (xs.empty()) return std::nan("");
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const size_t k = static_cast<size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + w * (ys[k] - ys[k - 1]);
}

NrmseResult ForceNrmseTime(const DatasetTrace& m, const DatasetTrace& s) {
  NrmseResult r;
  r.samples = m.size();
  if (m.size() == 0 || s.size() == 0) return {std::nan(""), r.samples, 0};
  const double peak = *std::max_element(m.force_N.begin(), m.force_N.end());
  double sum = 0.0;
  for (size_t i = 0; i < m.size(); ++i) {
    // Before the simulated trace begins (its touchdown: t = 0, or -dt with a sensor offset) the
    // pad is in the air (no force); after it ends, at rest.
    const double f_sim = m.t_s[i] < s.t_s.front() ? 0.0 : InterpolateClamped(s.t_s, s.force_N, m.t_s[i]);
    sum += (f_sim - m.force_N[i]) * (f_sim - m.force_N[i]);
    ++r.used;
  }
  r.value = peak > 0.0 ? std::sqrt(sum / r.used) / peak : std::nan("");
  return r;
}

NrmseResult ForceNrmsePenetration(const DatasetTrace& m, const DatasetTrace& s) {
  NrmseResult r;
  if (m.size() == 0 || s.size() == 0) return {std::nan(""), 0, 0};
  const double peak = *std::max_element(m.force_N.begin(), m.force_N.end());
  // The simulated stroke as a strictly increasing F(d): up to its stop (LoadingStrokeEnd), so the
  // fall to the weight in a record that goes on into the rest is not taken for the stroke.
  std::vector<double> ds, fs;
  const size_t s_end = LoadingStrokeEnd(s);
  for (size_t i = 0; i <= s_end; ++i)
    if (s.penetration_m[i] >= 0.0 && (ds.empty() || s.penetration_m[i] > ds.back())) {
      ds.push_back(s.penetration_m[i]);
      fs.push_back(s.force_N[i]);
    }
  // The measured loading stroke, cut where the force falls from the soil's capacity to the weight
  // (as calibrate cuts it): with noise on the penetration a rest sample is often the deepest, and
  // rest samples (force m g against the simulated F(d) near the final depth) made this metric
  // 0.4-0.8 on drops whose force against time agrees to 1 %.
  double sum = 0.0;
  for (const size_t i : LoadingStrokeIndices(m)) {
    const double d = m.penetration_m[i];
    ++r.samples;
    if (ds.size() < 2 || d > ds.back()) continue;  // beyond the simulated stroke
    const double f_sim = InterpolateClamped(ds, fs, d);
    sum += (f_sim - m.force_N[i]) * (f_sim - m.force_N[i]);
    ++r.used;
  }
  r.value = r.used > 0 && peak > 0.0 ? std::sqrt(sum / r.used) / peak : std::nan("");
  return r;
}

double RecordingSimulationRate_Hz(const Dataset& measured) {
  double fastest = 0.0;
  for (const DatasetDrop& d : measured.drops) {
    const double period = SamplePeriod(d.trace);
    if (period > 0.0) fastest = std::max(fastest, 1.0 / period);
  }
  return SimulationRateFor_Hz(fastest);
}

Dataset SimulateMeasuredDrops(const Dataset& measured, const std::optional<model::ModelFile>& model,
                              pad::SensorSampling sampling) {
  Dataset out;
  out.extra_columns = {"tilt_deg",       "horizontal_speed_m_s",   "zeta_N_cm3",    "time_to_rest_s",
                       "mean_conversion_rate_W", "final_tilt_deg", "horizontal_travel_m"};
  std::map<std::string, io::PadSpec> pads;
  std::map<std::string, rft::SoilParameters> soils;
  const std::string file = (fs::path(measured.directory) / "drops.csv").string();
  const rft::EffectTerms effects = model ? model::ModelEffectTerms(*model) : rft::EffectTerms{};
  const std::string effects_source = model ? model->source : "";
  const double rate_hz = RecordingSimulationRate_Hz(measured);
  for (const DatasetDrop& m : measured.drops) {
    const std::string pad_ref = measured.PadReference(m), soil_ref = measured.SoilReference(m);
    if (!pads.count(pad_ref)) pads.emplace(pad_ref, io::LoadPad(pad_ref));
    if (!soils.count(soil_ref)) soils.emplace(soil_ref, model ? model::ApplyModel(*model, io::LoadSoil(soil_ref)) : io::LoadSoil(soil_ref));
    // The drop's own conditions, atmosphere included (gas_cushion acts on the drops in air);
    // a tilt or a horizontal speed makes it a free 6-DOF drop (tilt about x, travel along +x).
    drop::DropConditions c =
        drop::DropConditionsFor(measured.Row(m), effects, effects_source, file + ": drop " + m.drop_id);
    c.free = !pads.at(pad_ref).is_axisymmetric();  // a mesh pad has no rig profile: the free pad, straight down
    drop::DropRunOptions run;
    run.rig.sample_rate_hz = run.free.sample_rate_hz = rate_hz;
    const drop::PadDrop d = drop::RunDrop(drop::ResolveDrop(pads.at(pad_ref), soils.at(soil_ref), c, run));
    DatasetDrop s;
    s.drop_id = m.drop_id;
    s.pad = m.pad;
    s.soil = m.soil;
    s.atmosphere = m.atmosphere;
    s.impact_speed_m_s = m.impact_speed_m_s;
    s.pad_mass_kg = m.pad_mass_kg;
    s.gravity_m_s2 = m.gravity_m_s2;
    s.trace_file = "traces/" + m.drop_id + ".csv";
    // What the rig would record: the measured drop's sensor on its own sample times (RecordedTrace,
    // sensor_sampling.h), with a sensor_offset's shifts (the recorded time runs dt behind the true
    // one, the recorded penetration reads dz more). Interpolating the simulation at the measured
    // instants instead would compare a point value with a sensor's mean, which differ most at the
    // stop (a 0.05 force NRMSE on a drop simulated with the true model, measured).
    s.trace = RecordedTrace(d.result, m.gravity_m_s2, c.effects, m.trace.t_s, sampling, SamplePeriod(m.trace));
    // The summaries as the measured drop has them: its columns from the simulation itself, or,
    // where it has none, from the recorded trace as the measured drop's come from its own.
    if (m.final_penetration_m) s.final_penetration_m = d.result.final_penetration_m + c.effects.sensor_dz_m;
    if (m.peak_force_N) s.peak_force_N = d.result.peak_force_N;
    s.extra = {io::FormatNumber(ExtraOrZero(measured, m, "tilt_deg")),  // as the measured drop gives it
               io::FormatNumber(c.horizontal_speed_m_s),
               io::FormatNumber(units::ZetaToN_cm3(d.zeta_effective_N_m3)),
               io::FormatNumber(d.result.time_to_rest_s),
               io::FormatNumber(d.result.mean_conversion_rate_W),
               io::FormatNumber(d.free ? d.free->final_tilt_deg : 0.0),
               io::FormatNumber(d.free ? d.free->horizontal_travel_m : 0.0)};
    out.drops.push_back(std::move(s));
  }
  return out;
}

std::vector<const DatasetDrop*> JoinOnConditions(const Dataset& measured, const Dataset& simulated) {
  std::vector<const DatasetDrop*> partners;
  for (const DatasetDrop& m : measured.drops) {
    const DatasetDrop* match = nullptr;
    for (const DatasetDrop& s : simulated.drops) {
      if (s.pad != m.pad || s.soil != m.soil || s.atmosphere != m.atmosphere) continue;
      if (!Close(s.impact_speed_m_s, m.impact_speed_m_s) || !Close(s.pad_mass_kg, m.pad_mass_kg) ||
          !Close(s.gravity_m_s2, m.gravity_m_s2))
        continue;
      bool same = true;
      for (const char* column : {"tilt_deg", "horizontal_speed_m_s"})
        same &= Close(ExtraOrZero(simulated, s, column), ExtraOrZero(measured, m, column));
      if (same) {
        match = &s;
        break;
      }
    }
    if (!match)
      throw MakeInputError((fs::path(measured.directory) / "drops.csv").string(), "drop " + m.drop_id,
                           "no simulated drop in " + simulated.directory + " with the same pad, soil, atmosphere, "
                           "impact speed, mass and gravity");
    partners.push_back(match);
  }
  return partners;
}

Comparison CompareDrops(const Dataset& measured, const std::vector<const DatasetDrop*>& partners) {
  Comparison c;
  std::vector<double> pen, peak, pen_signed, peak_signed, nrmse_t, nrmse_d;
  for (size_t i = 0; i < measured.drops.size(); ++i) {
    const DatasetDrop& m = measured.drops[i];
    const DatasetDrop& s = *partners[i];
    DropComparison d;
    d.drop_id = m.drop_id;
    d.simulated_id = s.drop_id;
    d.pad = m.pad;
    d.soil = m.soil;
    d.atmosphere = m.atmosphere;
    d.impact_speed_m_s = m.impact_speed_m_s;
    d.measured_final_penetration_m = m.FinalPenetration();
    d.simulated_final_penetration_m = s.FinalPenetration();
    d.measured_peak_force_N = m.PeakForce();
    d.simulated_peak_force_N = s.PeakForce();
    d.final_penetration_rel_error = RelError(d.simulated_final_penetration_m, d.measured_final_penetration_m);
    d.peak_force_rel_error = RelError(d.simulated_peak_force_N, d.measured_peak_force_N);
    d.force_nrmse_time = ForceNrmseTime(m.trace, s.trace);
    d.force_nrmse_penetration = ForceNrmsePenetration(m.trace, s.trace);
    if (d.measured_final_penetration_m == 0.0) c.zero_final_penetration_drops.push_back(d.drop_id);
    if (d.measured_peak_force_N == 0.0) c.zero_peak_force_drops.push_back(d.drop_id);
    pen.push_back(std::abs(d.final_penetration_rel_error));
    peak.push_back(std::abs(d.peak_force_rel_error));
    pen_signed.push_back(d.final_penetration_rel_error);
    peak_signed.push_back(d.peak_force_rel_error);
    nrmse_t.push_back(d.force_nrmse_time.value);
    nrmse_d.push_back(d.force_nrmse_penetration.value);
    c.drops.push_back(std::move(d));
  }
  c.final_penetration_rel_error = Mean(pen, &c.final_penetration_drops_used);
  c.peak_force_rel_error = Mean(peak, &c.peak_force_drops_used);
  c.final_penetration_bias = Mean(pen_signed);
  c.peak_force_bias = Mean(peak_signed);
  c.force_nrmse = Mean(nrmse_t, &c.force_nrmse_drops_used);
  c.force_nrmse_penetration = Mean(nrmse_d, &c.force_nrmse_penetration_drops_used);
  return c;
}

// JSON never carries null or NaN for a number: an undefined value (a relative error of a drop
// measured at 0, a mean over no drop) is left out, and the summary says which drops and how many.
void DropUndefined(nlohmann::json& j) {
  for (auto it = j.begin(); it != j.end();) {
    if (it->is_null()) it = j.erase(it);
    else ++it;
  }
}

nlohmann::json ComparisonJson(const Comparison& c) {
  nlohmann::json drops = nlohmann::json::array();
  for (const DropComparison& d : c.drops)
    drops.push_back({{"drop_id", d.drop_id},
                     {"simulated_id", d.simulated_id},
                     {"pad", d.pad},
                     {"soil", d.soil},
                     {"atmosphere", rft::AtmosphereName(d.atmosphere)},
                     {"impact_speed_m_s", d.impact_speed_m_s},
                     {"measured_final_penetration_m", io::FiniteOrNull(d.measured_final_penetration_m)},
                     {"simulated_final_penetration_m", io::FiniteOrNull(d.simulated_final_penetration_m)},
                     {"final_penetration_rel_error", io::FiniteOrNull(d.final_penetration_rel_error)},
                     {"measured_peak_force_N", io::FiniteOrNull(d.measured_peak_force_N)},
                     {"simulated_peak_force_N", io::FiniteOrNull(d.simulated_peak_force_N)},
                     {"peak_force_rel_error", io::FiniteOrNull(d.peak_force_rel_error)},
                     {"force_nrmse_time", io::FiniteOrNull(d.force_nrmse_time.value)},
                     {"force_nrmse_penetration", io::FiniteOrNull(d.force_nrmse_penetration.value)},
                     {"penetration_samples", d.force_nrmse_penetration.samples},
                     {"penetration_samples_used", d.force_nrmse_penetration.used}});
  for (nlohmann::json& d : drops) DropUndefined(d);
  nlohmann::json summary{{"drops_compared", c.drops.size()},
          {"drops_used",
           {{"final_penetration_rel_error", c.final_penetration_drops_used},
            {"peak_force_rel_error", c.peak_force_drops_used},
            {"force_nrmse", c.force_nrmse_drops_used},
            {"force_nrmse_penetration", c.force_nrmse_penetration_drops_used}}},
          {"drops_measured_zero",
           {{"final_penetration", c.zero_final_penetration_drops}, {"peak_force", c.zero_peak_force_drops}}},
          {"simulated_from", c.simulated_from},
          {"final_penetration_rel_error", io::FiniteOrNull(c.final_penetration_rel_error)},
          {"peak_force_rel_error", io::FiniteOrNull(c.peak_force_rel_error)},
          {"force_nrmse", io::FiniteOrNull(c.force_nrmse)},
          {"force_nrmse_penetration", io::FiniteOrNull(c.force_nrmse_penetration)},
          {"final_penetration_bias", io::FiniteOrNull(c.final_penetration_bias)},
          {"peak_force_bias", io::FiniteOrNull(c.peak_force_bias)},
          {"definitions",
           {{"final_penetration_rel_error", "mean over drops of |d_sim - d_meas| / d_meas"},
            {"peak_force_rel_error", "mean over drops of |F_sim - F_meas| / F_meas"},
            {"force_nrmse", "mean over drops of sqrt(mean_i (F_sim(t_i) - F_i)^2) / max_i F_i, "
                            "over all measured samples i (F_sim recorded at t_i through the measured drop's sensor when "
                            "simulated here, a joined dataset's interpolated in time)"},
            {"force_nrmse_penetration", "mean over drops of sqrt(mean_i (F_sim(d_i) - F_i)^2) / max_i F_i, "
                                        "over the measured loading stroke where the simulated stroke reaches"},
            {"bias", "signed means of the relative errors (simulated - measured) / measured"},
            {"drops_used", "the number of drops each mean is taken over: a relative error is undefined for a drop "
                           "measured at 0 (drops_measured_zero), an NRMSE for a measured peak force of 0; an "
                           "undefined value is left out of the drop's entry"}}},
          {"drops", drops}};
  DropUndefined(summary);
  return summary;
}

namespace {
// The instant after which neither trace carries force (above 1 % of the larger peak): the time
// axis ends a little after it, not where the longer recording happens to stop.
double ContactEnd(const DatasetTrace& a, const DatasetTrace& b) {
  double peak = 0.0, end = 0.0;
  for (const DatasetTrace* t : {&a, &b})
    for (double f : t->force_N) peak = std::max(peak, std::abs(f));
  for (const DatasetTrace* t : {&a, &b})
    for (size_t k = 0; k < t->size(); ++k)
      if (std::abs(t->force_N[k]) > 0.01 * peak) end = std::max(end, t->t_s[k]);
  return end;
}

// One drop: force against time and against penetration, measured (black points) and simulated
// (the pad's colour, the soil's dash).
std::string DropFigure(const DatasetDrop& m, const DatasetDrop& sim_drop) {
  const std::string meas = io::GnuplotQuote("plots/data/" + m.drop_id + "_measured.csv");
  const std::string sim = io::GnuplotQuote("plots/data/" + m.drop_id + "_simulated.csv");
  const std::string line = io::PadSoilLine(m.pad, m.soil);
  const double end_s = ContactEnd(m.trace, sim_drop.trace);
  const std::string xrange = end_s > 0.0 ? "set xrange [*:" + io::FormatNumber(1.15 * end_s * units::kMsPerS) + "]\n" : "";
  const std::string body =
      "set multiplot layout 1,2 title " +
      io::GnuplotQuote(m.drop_id + ": " + m.pad + " on " + io::SoilDisplayName(m.soil) + " (" + rft::AtmosphereName(m.atmosphere) + "), " +
                       io::FormatNumber(m.impact_speed_m_s) + " m/s") +
      "\nset key top right\nset xlabel 't [ms]'\nset ylabel 'force [N]'\n" + xrange + "plot " + meas +
      " using ($1*1000):3 skip 1 with points pt 7 ps 0.6 lc rgb '#000000' title 'measured', " + sim +
      " using ($1*1000):3 skip 1 with lines " + line + " title 'simulated'\nset xlabel 'penetration [mm]'\nset xrange [*:*]\nplot " + meas +
      " using ($2*1000):3 skip 1 with points pt 7 ps 0.6 lc rgb '#000000' title 'measured', " + sim +
      " using ($2*1000):3 skip 1 with lines " + line + " title 'simulated'\nunset multiplot\n";
  return io::Figure("plots/drops/" + m.drop_id, body, io::kFigureStrip);
}

// Every drop at once: simulated against measured final penetration and peak force, the line of
// agreement and +-10 % about it; a point's colour is its pad, filled in vacuum, open in air.
// plots/data/parity.csv holds the points.
std::string ParityFigure(const Comparison& c, const fs::path& dir) {
  double top[2] = {0.0, 0.0};
  io::WriteFileAtomically((dir / "plots" / "data" / "parity.csv").string(), [&](std::ostream& out) {
    out << "measured_penetration_mm,simulated_penetration_mm,measured_peak_force_N,simulated_peak_force_N,colour,"
           "point_type\n";
    for (const DropComparison& d : c.drops) {
      const double v[4] = {d.measured_final_penetration_m * units::kMmPerM, d.simulated_final_penetration_m * units::kMmPerM,
                           d.measured_peak_force_N, d.simulated_peak_force_N};
      for (int k = 0; k < 4; ++k) out << (std::isfinite(v[k]) ? io::FormatNumber(v[k]) : "NaN") << ',';
      for (int k = 0; k < 4; ++k)
        if (std::isfinite(v[k])) top[k / 2] = std::max(top[k / 2], v[k]);
      out << std::stoi(io::PadColour(d.pad).substr(1), nullptr, 16) << ',' << (d.atmosphere == rft::Atmosphere::kAir ? 6 : 7) << '\n';
    }
  });
  // The key: one entry per pad (its colour) and per atmosphere (filled or open), from points
  // drawn at NaN, so the colours of the data points need no legend of their own.
  std::vector<std::string> pads;
  for (const DropComparison& d : c.drops)
    if (std::find(pads.begin(), pads.end(), d.pad) == pads.end()) pads.push_back(d.pad);
  std::string key;
  for (const std::string& pad : pads)
    key += ", NaN with points pt 5 ps 1.8 lc rgb '" + io::PadColour(pad) + "' title " + io::GnuplotQuote("pad: " + pad);
  key += ", NaN with points pt 7 ps 1.8 lc rgb '#000000' title 'vacuum', NaN with points pt 6 ps 1.8 lc rgb '#000000' title 'air'";
  std::string body = "set multiplot layout 1,2 title 'Simulated against measured, every drop (colour: pad; filled: "
                     "vacuum, open: air; dashed: +-10 %)'\nset key top left\nset size ratio -1\n";
  const char* names[2] = {"final penetration [mm]", "peak force [N]"};
  for (int p = 0; p < 2; ++p) {
    const std::string hi = io::FormatNumber(top[p] > 0.0 ? 1.1 * top[p] : 1.0);
    body += std::string("set xlabel 'measured ") + names[p] + "'\nset ylabel 'simulated " + names[p] + "'\nset xrange [0:" +
            hi + "]\nset yrange [0:" + hi + "]\nplot x with lines lw 1.5 lc rgb '#000000' title 'agreement', 1.1*x with lines " +
            io::kPaperBandLine + " notitle, 0.9*x with lines " + io::kPaperBandLine +
            " notitle, 'plots/data/parity.csv' skip 1 using " + std::to_string(2 * p + 1) + ":" + std::to_string(2 * p + 2) +
            ":6:5 with points pt variable ps 1.8 lc rgb variable notitle" + (p == 0 ? key : std::string()) + "\n";
  }
  return io::Figure("plots/parity", body + "unset multiplot\n", io::kFigureStrip);
}
}  // namespace

void WriteComparison(const Comparison& c, const Dataset& measured, const Dataset& simulated,
                     const std::vector<const DatasetDrop*>& partners, bool write_simulated, const io::OutputTarget& out) {
  const nlohmann::json summary = ComparisonJson(c);
  io::WriteOutputDirectory(out, io::OutputKind::kComparison, [&](const std::string& staging) {
    const fs::path dir = staging;
    io::WriteFileAtomically((dir / "summary.json").string(), [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
    io::WriteFileAtomically((dir / "per_drop.csv").string(), [&](std::ostream& out) {
      out << "drop_id,simulated_id,pad,soil,atmosphere,impact_speed_m_s,measured_final_penetration_m,"
             "simulated_final_penetration_m,final_penetration_rel_error,measured_peak_force_N,simulated_peak_force_N,"
             "peak_force_rel_error,force_nrmse_time,force_nrmse_penetration\n";
      for (const DropComparison& d : c.drops)
        out << d.drop_id << ',' << d.simulated_id << ',' << d.pad << ',' << d.soil << ',' << rft::AtmosphereName(d.atmosphere) << ','
            << io::FormatNumber(d.impact_speed_m_s) << ',' << io::FormatNumber(d.measured_final_penetration_m) << ','
            << io::FormatNumber(d.simulated_final_penetration_m) << ',' << io::FormatNumber(d.final_penetration_rel_error)
            << ',' << io::FormatNumber(d.measured_peak_force_N) << ',' << io::FormatNumber(d.simulated_peak_force_N) << ','
            << io::FormatNumber(d.peak_force_rel_error) << ',' << io::FormatNumber(d.force_nrmse_time.value) << ','
            << io::FormatNumber(d.force_nrmse_penetration.value) << '\n';
    });
    // Plot data: each pair's traces copied beside the script, so the plots re-render anywhere;
    // decimated (plot_decimation.h) so a long trace is drawn from a few thousand rows.
    fs::create_directories(dir / "plots" / "data");
    io::PlotScript script{"plots/compare.gp", ParityFigure(c, dir), {io::FigurePng("plots/parity")}};
    for (size_t i = 0; i < measured.drops.size(); ++i) {
      const DatasetDrop& m = measured.drops[i];
      for (const auto& [tag, drop] : {std::pair<const char*, const DatasetDrop*>{"measured", &m}, {"simulated", partners[i]}})
        io::WriteFileAtomically((dir / "plots" / "data" / (m.drop_id + "_" + tag + ".csv")).string(), [&, drop = drop](std::ostream& out) {
          const DatasetTrace& t = drop->trace;
          out << "t_s,penetration_m,force_N\n";
          for (const size_t k : io::PlotRowsToKeep(t.size(), {t.t_s, t.penetration_m, t.force_N}))
            out << io::FormatNumber(t.t_s[k]) << ',' << io::FormatNumber(t.penetration_m[k]) << ',' << io::FormatNumber(t.force_N[k])
                << '\n';
        });
      script.text += DropFigure(m, *partners[i]);
      script.outputs.push_back(io::FigurePng("plots/drops/" + m.drop_id));
    }
    fs::create_directories(dir / "plots" / "drops");
    if (write_simulated) {
      fs::create_directories(dir / "simulated");
      WriteDatasetFiles(simulated, (dir / "simulated").string());
    }
    io::RenderPlots(dir, script);
  });
}

Comparison RunComparison(const std::string& measured_dir, const std::string& simulated_dir,
                         const std::string& model_file, const io::OutputTarget& out, pad::SensorSampling sampling) {
  io::CheckOutputDirectory(out, io::OutputKind::kComparison);
  const Dataset measured = ReadDataset(measured_dir);
  Dataset simulated;
  std::vector<const DatasetDrop*> partners;
  std::string from;
  const bool simulate_here = simulated_dir.empty();
  if (simulate_here) {
    std::optional<model::ModelFile> model;
    if (!model_file.empty()) model = model::LoadModelFile(model_file);
    simulated = SimulateMeasuredDrops(measured, model, sampling);
    for (const DatasetDrop& d : simulated.drops) partners.push_back(&d);
    from = model ? "model " + model_file : "catalogue soils";
  } else {
    simulated = ReadDataset(simulated_dir);
    partners = JoinOnConditions(measured, simulated);
    from = "dataset " + simulated_dir;
  }
  Comparison c = CompareDrops(measured, partners);
  c.simulated_from = from;
  WriteComparison(c, measured, simulated, partners, simulate_here, out);
  return c;
}

}  // namespace touchdown::dataset

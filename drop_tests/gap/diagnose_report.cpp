// Outputs of `touchdown diagnose`: model.yaml, per_drop.csv, report.md, plots, and the directory
// that holds them with diagnosis.json (DiagnosisJson: diagnosis_json.cpp).
#include <array>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "drop_tests/gap/diagnose.h"
#include "drop_tests/gap/diagnose_plots.h"
#include "drop_tests/gap/diagnose_selection.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/json_number.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/plot_decimation.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/plot_runner.h"
#include "rft/units.h"

namespace touchdown::gap {

namespace fs = std::filesystem;

namespace {

std::string Num(double v, int digits = 4) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}


const CandidateScore* Shown(const Diagnosis& d) {
  if (d.winner >= 0) return &d.candidates[d.winner];
  const CandidateScore* best = nullptr;
  for (const CandidateScore& c : d.candidates)
    if (c.applies && !c.screened_out && (!best || c.fit.bic < best->fit.bic)) best = &c;
  return best;
}

bool IsSynthetic(const dataset::Dataset& ds) {
  for (size_t k = 0; k < ds.extra_columns.size(); ++k)
    if (ds.extra_columns[k] == "data_origin")
      for (const dataset::DatasetDrop& d : ds.drops)
        if (k < d.extra.size() && d.extra[k] == "synthetic") return true;
  return fs::exists(fs::path(ds.directory) / "synthetic.yaml");
}

}  // namespace

namespace {

// model.yaml: zeta per soil of the named effect's fit (the base's when none is named), with the
// 95 % intervals and each soil's training residual, and the named effect's fitted terms.
model::ModelFile DiagnosedModel(const Diagnosis& d, const dataset::Dataset& ds, const CandidateScore& after) {
  model::ModelFile model;
  model.name = "diagnosed_" + fs::path(ds.directory).filename().string();
  model.description = std::string(d.problem.bekker_base
                                      ? "touchdown diagnose: base Bekker (n, k_c, k_phi per soil, fitted; in "
                                        "diagnosis.json base.bekker_soils, not in this file)"
                                      : "touchdown diagnose: base quasi-static RFT (zeta per soil, fitted)") +
                      (d.winner >= 0 ? " plus " + d.candidates[d.winner].name : std::string(" (no effect named)"));
  for (size_t s = 0; s < d.problem.soils.size() && !d.problem.bekker_base; ++s) {
    const ParameterEstimate& e = after.fit.estimates[s];
    model::SoilOverride o;
    o.zeta_N_m3 = e.value;
    o.reference_gravity_m_s2 = d.problem.soils[s].reference_gravity_m_s2;
    o.zeta_low_N_m3 = e.low;
    o.zeta_high_N_m3 = e.high;
    model::SoilFit fit;
    fit.method = "touchdown diagnose: Levenberg-Marquardt on force and penetration against time, training drops; "
                 "residual_rms_N: force residual over the soil's training samples";
    fit.drops = 0;
    for (const FitDrop& f : d.problem.drops) fit.drops += f.train && f.soil == static_cast<int>(s);
    // The fitted model's own residual on this soil's training drops (force against time, N).
    fit.samples = after.fit.force_samples[s];
    fit.residual_rms_N = after.fit.residual_rms_N[s];
    fit.dataset = ds.directory;
    o.fit = fit;
    model.soils[d.problem.soils[s].name] = o;
  }
  if (d.winner >= 0) {
    std::vector<std::vector<std::pair<double, double>>> intervals;
    size_t k = d.problem.soils.size();
    for (const model::Effect& e : after.fit.effects) {
      intervals.emplace_back();
      for (size_t i = 0; i < e.values.size(); ++i, ++k)
        intervals.back().emplace_back(after.fit.estimates[k].low, after.fit.estimates[k].high);
    }
    model.effects = after.fit.effects;
    model.effect_intervals = intervals;
  }
  YAML::Node provenance(YAML::NodeType::Map);
  provenance["diagnose"] = d.decision;
  provenance["intervals"] = "95 %, cluster-robust over training drops (docs/model_gap.md)";
  model.provenance_yaml = YAML::Dump(provenance);
  return model;
}

void WritePerDropCsv(const Diagnosis& d, const dataset::Dataset& ds, const CandidateScore& after,
                     const fs::path& file) {
  io::WriteFileAtomically(file.string(), [&](std::ostream& out) {
    out << "drop_id,held_out,pad,soil,atmosphere,impact_speed_m_s,force_nrmse_before,force_nrmse_after,"
           "final_penetration_rel_error_before,final_penetration_rel_error_after,noise_floor_nrmse\n";
    for (size_t i = 0; i < d.problem.drops.size(); ++i) {
      const dataset::DatasetDrop& m = ds.drops[d.problem.drops[i].dataset_index];
      out << m.drop_id << ',' << (d.problem.drops[i].train ? 0 : 1) << ',' << m.pad << ',' << m.soil << ','
          << rft::AtmosphereName(m.atmosphere) << ',' << io::FormatNumber(m.impact_speed_m_s) << ',' << io::FormatNumber(d.base.gaps[i].force_nrmse)
          << ',' << io::FormatNumber(after.gaps[i].force_nrmse) << ','
          << io::FormatNumber(d.base.gaps[i].final_penetration_rel_error) << ','
          << io::FormatNumber(after.gaps[i].final_penetration_rel_error) << ',' << io::FormatNumber(d.base.gaps[i].noise_nrmse)
          << '\n';
    }
  });
}

// The held-out drops with the largest base gap (up to 6): the ones the overlays show.
std::vector<size_t> OverlaidDrops(const Diagnosis& d) {
  std::vector<size_t> held;
  for (size_t i = 0; i < d.problem.drops.size(); ++i)
    if (!d.problem.drops[i].train) held.push_back(i);
  std::sort(held.begin(), held.end(), [&](size_t a, size_t b) { return d.base.gaps[a].force_nrmse > d.base.gaps[b].force_nrmse; });
  if (held.size() > 6) held.resize(6);
  return held;
}

// data/<drop>.csv of each overlaid drop: measured, base and `shown` traces, decimated.
void WriteOverlayData(const Diagnosis& d, const dataset::Dataset& ds, const CandidateScore* shown,
                      const std::vector<size_t>& held, const fs::path& dir) {
  for (size_t i : held) {
    const FitDrop& f = d.problem.drops[i];
    const dataset::DatasetDrop& m = ds.drops[f.dataset_index];
    const std::optional<dataset::DatasetTrace> b = SimulateRecorded(d.problem, f, d.base.fit);
    const std::optional<dataset::DatasetTrace> a = shown ? SimulateRecorded(d.problem, f, shown->fit) : b;
    // Decimated (plot_decimation.h) on the six plotted columns: a long trace plots from a few
    // thousand rows.
    const auto plotted = [&](size_t k, size_t column) {
      const std::optional<dataset::DatasetTrace>& sim = column % 3 == 1 ? b : a;
      if (column % 3 == 0) return column == 0 ? m.trace.force_N[k] : m.trace.penetration_m[k];
      if (!sim) return std::nan("");
      return column < 3 ? sim->force_N[k] : sim->penetration_m[k];
    };
    io::WriteFileAtomically((dir / "data" / (m.drop_id + ".csv")).string(), [&](std::ostream& out) {
      out << "t_s,force_measured_N,force_base_N,force_augmented_N,penetration_measured_m,penetration_base_m,"
             "penetration_augmented_m\n";
      for (const size_t k : io::PlotRowsToKeep(m.trace.size(), 6, plotted))
        out << io::FormatNumber(m.trace.t_s[k]) << ',' << io::FormatNumber(m.trace.force_N[k]) << ','
            << (b ? io::FormatNumber(b->force_N[k]) : "nan") << ',' << (a ? io::FormatNumber(a->force_N[k]) : "nan") << ','
            << io::FormatNumber(m.trace.penetration_m[k]) << ',' << (b ? io::FormatNumber(b->penetration_m[k]) : "nan") << ','
            << (a ? io::FormatNumber(a->penetration_m[k]) : "nan") << '\n';
    });
  }
}

// The held-out drops' force residuals, base and `shown`: data/residuals_held_out.csv (every
// plotted sample, one block per drop) for an atmosphere of at most kMaxResidualDropsDrawn drops,
// data/residual_bands_<atmosphere>.csv past that; and what each panel draws, on one scale.
ResidualPanels WriteResiduals(const Diagnosis& d, const dataset::Dataset& ds, const CandidateScore* shown, const fs::path& dir) {
  ResidualPanels panels;
  std::array<size_t, 2> planned{0, 0};
  for (const FitDrop& f : d.problem.drops)
    if (!f.train) ++planned[f.atmosphere == rft::Atmosphere::kAir ? 1 : 0];
  std::ostringstream residual_rows;
  std::array<std::vector<ResidualSample>, 2> banded;
  double t_lo = INFINITY, t_hi = -INFINITY, r_lo = INFINITY, r_hi = -INFINITY;
  const auto extend = [&](double t_ms, double r) {
    t_lo = std::min(t_lo, t_ms), t_hi = std::max(t_hi, t_ms), r_lo = std::min(r_lo, r), r_hi = std::max(r_hi, r);
  };
  for (size_t i = 0; i < d.problem.drops.size(); ++i) {
    const FitDrop& f = d.problem.drops[i];
    if (f.train) continue;
    const int panel = f.atmosphere == rft::Atmosphere::kAir ? 1 : 0;
    const dataset::DatasetDrop& m = ds.drops[f.dataset_index];
    const std::optional<dataset::DatasetTrace> b = SimulateRecorded(d.problem, f, d.base.fit);
    const std::optional<dataset::DatasetTrace> a = shown ? SimulateRecorded(d.problem, f, shown->fit) : b;
    if (!a || !b) continue;
    ++panels.drops[panel];
    const auto residual = [&](const dataset::DatasetTrace& sim, size_t k) {
      return (sim.force_N[k] - m.trace.force_N[k]) / f.force_scale_N;
    };
    if (planned[panel] > kMaxResidualDropsDrawn) {
      // Every sample of a drop up to 2,000, then a uniform stride: the bands weigh each drop
      // alike and a campaign of long traces stays in memory.
      const size_t stride = (m.trace.size() + 1999) / 2000;
      for (size_t k = 0; k < m.trace.size(); k += std::max<size_t>(stride, 1))
        banded[panel].push_back({m.trace.t_s[k], residual(*b, k), residual(*a, k)});
      continue;
    }
    const auto plotted = [&](size_t k, size_t column) { return residual(column == 0 ? *b : *a, k); };
    for (const size_t k : io::PlotRowsToKeep(m.trace.size(), 2, plotted)) {
      residual_rows << io::FormatNumber(m.trace.t_s[k]) << ',' << io::FormatNumber(residual(*b, k)) << ','
                    << io::FormatNumber(residual(*a, k)) << ',' << rft::AtmosphereName(m.atmosphere) << '\n';
      extend(m.trace.t_s[k] * units::kMsPerS, residual(*b, k));
      extend(m.trace.t_s[k] * units::kMsPerS, residual(*a, k));
    }
    residual_rows << '\n';
  }
  for (int panel = 0; panel < 2; ++panel) {
    if (panels.drops[panel] == 0) continue;
    if (planned[panel] <= kMaxResidualDropsDrawn) {
      panels.layout[panel] = ResidualLayout::kSamples;
      continue;
    }
    const std::vector<ResidualBand> bands = ResidualBands(banded[panel]);
    if (bands.empty()) continue;
    panels.layout[panel] = ResidualLayout::kBands;
    for (const ResidualBand& band : bands)
      for (const std::array<double, 3>& p : {band.base, band.augmented}) extend(band.t_ms, p[0]), extend(band.t_ms, p[2]);
    WriteResidualBands(bands, rft::AtmosphereName(panel == 1 ? rft::Atmosphere::kAir : rft::Atmosphere::kVacuum), dir);
  }
  if (!residual_rows.str().empty())
    io::WriteFileAtomically((dir / "data" / "residuals_held_out.csv").string(), [&](std::ostream& out) {
      out << "t_s,residual_base,residual_augmented,atmosphere\n" << residual_rows.str();
    });
  if (std::isfinite(r_lo)) panels.t_lo_ms = t_lo, panels.t_hi_ms = std::max(t_hi, t_lo + 1e-3), panels.r_lo = r_lo, panels.r_hi = r_hi;
  return panels;
}

// plots/diagnose.gp: overlays (force against time and against penetration), residuals, gap per
// drop, each a Figure (PNG + SVG). Measured: black points; base model: grey, dashed; the model
// with the effect: one accent colour that no pad uses elsewhere.
constexpr const char* kBaseLine = io::kBaseLine;
const std::string kAugmentedLine = std::string("lw 2.5 lc rgb '") + io::kAugmentedColour + "'";
// Six panels on a grid, room between them for their titles and labels.
constexpr const char* kSixPanels = " margins 0.07, 0.98, 0.1, 0.9 spacing 0.07, 0.15";

// A measured trace of more samples than this is drawn as a thin line: its points, at the size that
// reads on a short trace, merge into a band that hides the simulated lines.
constexpr size_t kMeasuredPointsUpTo = 300;

std::string OverlayFigure(const Diagnosis& d, const dataset::Dataset& ds, const std::vector<size_t>& held,
                          const std::string& aug_title, bool against_penetration) {
  size_t held_out = 0;
  for (const FitDrop& f : d.problem.drops) held_out += f.train ? 0 : 1;
  std::ostringstream body;
  // The styles named in the title, no key: a key inside a panel covers its peak.
  const std::string which = held.size() < held_out ? "the " + std::to_string(held.size()) + " worst of " +
                                                         std::to_string(held_out) + " held-out drops (base force NRMSE)"
                                                   : "the held-out drops";
  body << "set multiplot layout 2,3" << kSixPanels << " title "
       << io::GnuplotQuote(std::string(against_penetration ? "Force against penetration" : "Force against time") + " of " +
                           which + ": measured (black), base (grey, dashed), " + aug_title + " (purple)")
       << "\nunset key\n";
  for (size_t i : held) {
    const dataset::DatasetDrop& m = ds.drops[d.problem.drops[i].dataset_index];
    const std::string columns = against_penetration ? "($5*1000):2" : "($1*1000):2";
    const std::string measured = m.trace.size() <= kMeasuredPointsUpTo ? "with points pt 7 ps 0.8 lc rgb '#000000'"
                                                                       : "with lines lw 1 lc rgb '#000000'";
    body << "set title " << io::GnuplotQuote(m.drop_id + " (" + rft::AtmosphereName(m.atmosphere) + ")") << "\nset xlabel "
         << (against_penetration ? "'penetration [mm]'" : "'t [ms]'") << "\nset ylabel 'force [N]'\nplot "
         << io::GnuplotQuote("data/" + m.drop_id + ".csv") << " using " << columns << ' ' << measured << " title 'measured', "
         << "'' using " << (against_penetration ? "($6*1000):3" : "($1*1000):3") << " with lines " << kBaseLine << " title 'base', "
         << "'' using " << (against_penetration ? "($7*1000):4" : "($1*1000):4") << " with lines " << kAugmentedLine
         << " title 'with effect'\n";
  }
  if (held.empty()) body << io::PlaceholderPlot("no held-out drop could be simulated");
  body << "unset multiplot\n";
  return io::Figure(against_penetration ? "plots/overlays_force_penetration" : "plots/overlays_force_time", body.str());
}

// A drop id for a tic under a panel that already names the atmosphere: "_<atmosphere>" and a
// trailing "_t0" (the one trial of most conditions) left out; the full ids are in the report.
std::string ShortId(std::string id, const std::string& atmosphere) {
  if (const size_t at = id.find("_" + atmosphere); at != std::string::npos) id.erase(at, atmosphere.size() + 1);
  if (id.ends_with("_t0")) id.resize(id.size() - 3);
  return id;
}

// A condition as a tic reads it: pad, soil and speed ("flat FJS-1 LP 1.2 m/s"; a pad or soil
// given by path by its file's stem).
std::string ConditionLabel(const dataset::DatasetDrop& m) {
  std::ostringstream label;
  label << fs::path(m.pad).stem().string() << ' ' << io::SoilDisplayName(fs::path(m.soil).stem().string()) << ' '
        << std::setprecision(3) << m.impact_speed_m_s << " m/s";
  return label.str();
}

// The drops in one atmosphere, in the dataset's order, for the gap-per-drop figure.
std::vector<GapRow> GapRows(const Diagnosis& d, const dataset::Dataset& ds, const CandidateScore& after,
                            rft::Atmosphere atmosphere) {
  std::vector<GapRow> rows;
  for (size_t i = 0; i < d.problem.drops.size(); ++i) {
    const FitDrop& f = d.problem.drops[i];
    const dataset::DatasetDrop& m = ds.drops[f.dataset_index];
    if (m.atmosphere != atmosphere) continue;
    rows.push_back({ShortId(m.drop_id, rft::AtmosphereName(atmosphere)), ConditionLabel(m), ConditionKey(f), !f.train,
                    d.base.gaps[i].force_nrmse, after.gaps[i].force_nrmse, d.base.gaps[i].noise_nrmse});
  }
  return rows;
}

// True when the effect raised any drop's force NRMSE: only then does the figure's key explain the
// mark that flags such drops.
bool AnyDropMadeWorse(const Diagnosis& d, const CandidateScore& after) {
  for (size_t i = 0; i < d.base.gaps.size() && i < after.gaps.size(); ++i)
    if (after.gaps[i].force_nrmse > d.base.gaps[i].force_nrmse) return true;
  return false;
}

void WriteReport(const Diagnosis& d, const dataset::Dataset& ds, const CandidateScore& after, const fs::path& file) {
  io::WriteFileAtomically(file.string(), [&](std::ostream& out) {
    out << "# Model-gap diagnosis: " << fs::path(ds.directory).filename().string() << "\n\n";
    if (IsSynthetic(ds))
      out << "> **The dataset is SYNTHETIC** (made by `touchdown synth`), not measured: this run rehearses the "
             "workflow on data whose missing effect is known.\n\n";
    if (d.named_effects.empty()) out << "**Named effect: `none`.**";
    else {
      out << "**Named effects, in the order selected:";
      for (size_t i = 0; i < d.named_effects.size(); ++i) out << (i ? ", `" : " `") << d.named_effects[i] << "`";
      out << ".**";
    }
    for (const std::string& n : d.named_nuisances)
      out << " **The rig's `" << n << "` (a nuisance of the measurement, not of the soil) is part of the named model.**";
    if (!d.dynamic_term_statement.empty()) out << " **" << d.dynamic_term_statement << "**";
    out << " " << d.decision << ".\n\n";
    out << "**Sensor:** " << (d.sensor.given ? "as given, " : "inferred: ") << dataset::DescribeSensor(d.sensor.chosen)
        << (d.sensor.given ? "" : " (" + d.sensor.evidence + ")") << ". **Drop-to-drop scatter allowed for:** strength "
        << Num(100 * d.problem.spreads.log_zeta, 3) << " %, speed " << Num(100 * d.problem.spreads.log_speed, 3)
        << " %, touchdown time " << Num(1e3 * d.problem.spreads.time_s, 3) << " ms (per-drop nuisances"
        << (d.problem.drop_nuisances ? ""
            : d.nuisances_without_replicates ? ": off, the drops do not repeat their conditions (fewer than 3 "
                                               "degrees of freedom of replicates)"
                                             : ": off") << ")."
        << (d.problem.stop_samples_skipped ? " The two samples either side of each drop's measured stop are not "
                                             "counted in its force residual (their residual is a step in the stop's "
                                             "time within one sample)."
                                           : "")
        << "\n\n";
    const GapFloor& fl = d.floor;
    out << "**Floor** (what no model of the conditions goes below): force NRMSE " << Num(std::sqrt(fl.ms))
        << (fl.from_replicates ? " from the replicates' pure error on " + std::to_string(fl.replicate_df) +
                                     " degrees of freedom, read from the residuals of " + fl.model +
                                     " (95 % upper bound " + Num(std::sqrt(fl.ms_upper)) + ")"
                               : std::string(" from the sensor's noise at rest (too few replicates)"))
        << "; sensor noise " << Num(std::sqrt(fl.noise_ms)) << "; the base's held-out excess above it "
        << Num(std::sqrt(std::max(d.base.held_out.mean_square - fl.ms, 0.0))) << ".\n\n";
    if (!d.residual_description.empty()) out << d.residual_description << "\n\n";
    size_t n_train = 0;
    for (const FitDrop& f : d.problem.drops) n_train += f.train;
    out << "## 1. Split and calibration\n\n" << d.problem.drops.size() << " drops: " << n_train << " training, "
        << d.problem.drops.size() - n_train
        << " held out (" << SplitRule(d) << ").\n\n";
    if (d.problem.bekker_base) {
      out << "**Base model: Bekker** (`--base bekker`, docs/bekker_soil.md): n, k_c, k_phi per soil fitted on the "
             "training drops as `calibrate --law bekker` does; the effects are fitted on top with a scale of the "
             "soil's moduli.\n\n| soil | n | k_c [kN/m^(n+1)] | k_phi [kN/m^(n+2)] | modulus scale, base | 95 % "
             "interval | with effect |\n| --- | --- | --- | --- | --- | --- | --- |\n";
      for (size_t s = 0; s < d.problem.soils.size(); ++s) {
        const ParameterEstimate& b = d.base.fit.estimates[s];
        const rft::BekkerParameters& k = d.bekker_base[s].bekker;
        out << "| " << d.problem.soils[s].name << " | " << Num(k.n) << " | " << Num(k.k_c_N_m_n1 / units::kKilo) << " | "
            << Num(k.k_phi_N_m_n2 / units::kKilo) << " | " << Num(b.value) << " | [" << Num(b.low) << ", " << Num(b.high)
            << "] | " << Num(after.fit.estimates[s].value) << " |\n";
      }
    } else {
      out << "| soil | zeta base [N/cm^3] | 95 % interval | zeta with effect [N/cm^3] |\n| --- | --- | --- | --- |\n";
    }
    for (size_t s = 0; s < d.problem.soils.size() && !d.problem.bekker_base; ++s) {
      const ParameterEstimate& b = d.base.fit.estimates[s];
      out << "| " << d.problem.soils[s].name << " | " << Num(units::ZetaToN_cm3(b.value)) << " | [" << Num(units::ZetaToN_cm3(b.low)) << ", "
          << Num(units::ZetaToN_cm3(b.high)) << "] | " << Num(units::ZetaToN_cm3(after.fit.estimates[s].value)) << " |\n";
    }
    out << "\n## 2. The gap and where it is (base model)\n\n"
        << "Held-out means: force NRMSE " << Num(d.base.held_out.force_nrmse) << " (sensor-noise floor about "
        << Num(d.base.held_out.noise_nrmse) << "), force NRMSE against penetration "
        << Num(d.base.held_out.force_nrmse_penetration) << ", |final penetration error| "
        << Num(100 * d.base.held_out.final_penetration_rel_error, 3) << " %, |peak force error| "
        << Num(100 * d.base.held_out.peak_force_rel_error, 3) << " %.\n\n"
        << "| kind | factor | finding | p | significant |\n| --- | --- | --- | --- | --- |\n";
    for (const Finding& f : d.where)
      out << "| " << FindingKindName(f.kind) << " | " << f.factor << " | " << f.summary << " | " << Num(f.p_value, 3) << " | "
          << (f.significant ? "yes" : "no") << " |\n";
    out << "\nPermutation tests (" << 2000 << " permutations); significant means p below 0.05 / number of tests "
           "(Bonferroni).\n\n## 3. Candidates\n\n"
        << "Forward selection: each step fits every remaining term on top of the model so far and adds the best one "
           "when it beats that model by Delta BIC >= 10, is the only simplest one the data cannot tell from the best, "
           "cuts the held-out force NRMSE, explains at least half of that model's held-out mean-square excess over "
           "the noise floor, and has its parameters identified by the training drops (no 95 % interval over a "
           "parameter's whole range).\n\n"
        << "| step | model | parameters (95 % interval) | held-out force NRMSE | reduction vs base | explained | "
           "Delta BIC vs base | Delta BIC vs the step's start |\n"
        << "| --- | --- | --- | --- | --- | --- | --- | --- |\n"
        << "| 0 | base | zeta per soil | " << Num(d.base.held_out.force_nrmse) << " | - | - | 0 | - |\n";
    for (const CandidateScore& c : d.candidates) {
      if (!c.applies) {
        out << "| " << c.step << " | " << c.name << " | not tried: " << c.why_not << " | | | | | |\n";
        continue;
      }
      if (c.screened_out) {
        out << "| " << c.step << " | " << c.name << " | screened out: BIC after " << c.fit.iterations
            << " iterations ranks below the step's " << kFullyScored << " best | | | | " << Num(c.delta_bic, 5) << " | "
            << Num(c.delta_bic_step, 5) << " |\n";
        continue;
      }
      std::ostringstream params;
      for (const ParameterEstimate& e : c.fit.estimates)
        if (!e.effect.empty())
          params << e.key << " = " << Num(e.value / e.file_to_si) << " [" << Num(e.low / e.file_to_si) << ", "
                 << Num(e.high / e.file_to_si) << "]; ";
      const bool selected = std::find(d.selection.begin(), d.selection.end(), &c - d.candidates.data()) != d.selection.end();
      out << "| " << c.step << " | " << c.name << (selected ? " **(selected)**" : "") << " | " << params.str() << " | "
          << Num(c.held_out.force_nrmse) << " | " << Num(100 * c.gap_reduction, 3) << " % | " << Num(100 * c.explained, 3)
          << " % | " << Num(c.delta_bic, 5) << " | " << Num(c.delta_bic_step, 5) << " |\n";
    }
    out << "\n**The selected terms in order** (held-out gap after each step):\n\n"
           "| step | added | parameters (95 % interval) | Delta BIC vs the step before | held-out force NRMSE after |\n"
           "| --- | --- | --- | --- | --- |\n| 0 | (base) | | | " << Num(d.base.held_out.force_nrmse) << " |\n";
    for (size_t k = 0; k < d.selection.size(); ++k) {
      const CandidateScore& c = d.candidates[d.selection[k]];
      std::ostringstream params;
      for (const ParameterEstimate& e : c.fit.estimates)
        if (!e.effect.empty())
          params << e.effect << "." << e.key << " = " << Num(e.value / e.file_to_si) << " [" << Num(e.low / e.file_to_si)
                 << ", " << Num(e.high / e.file_to_si) << "]; ";
      out << "| " << k + 1 << " | " << c.effect_ids.back() << " | " << params.str() << " | " << Num(c.delta_bic_step, 5)
          << " | " << Num(c.held_out.force_nrmse) << " |\n";
    }
    if (d.selection.empty()) out << "| - | nothing selected | | | |\n";
    if (d.law_candidate) {  // --law-candidate: "the gap is the law" (law_candidate.h)
      const LawCandidate& l = *d.law_candidate;
      out << "\nThe law as a candidate (" << l.law << ", fitted per soil on the training drops): ";
      if (!l.applies) out << "does not apply (" << l.why_not << ").\n";
      else
        out << "held-out force NRMSE " << Num(l.held_out_force_nrmse) << " against RFT's " << Num(l.base_held_out_force_nrmse)
            << " (" << Num(100 * l.gap_reduction, 3) << " % of the gap; reported, not part of the decision).\n";
    }
    out << "\n## 4. Model\n\n`model.yaml`: "
        << (d.problem.bekker_base ? "(Bekker base: its soils are in `diagnosis.json`, `base.bekker_soils`)"
                                  : "the base model's zeta per soil")
        << (d.winner >= 0 ? " plus `" + d.candidates[d.winner].name + "` with its fitted parameters and 95 % intervals" +
                                 (d.dynamic_term_statement.empty() ? "" : " (the weakened dynamic term as `inertial_drag`, which replaces the soil's own)")
                           : "")
        << ". Intervals are cluster-robust over the training drops.\n\n## 5. Before and after (held-out drops)\n\n"
        << "| drop | force NRMSE before | after | final penetration error before | after |\n| --- | --- | --- | --- | --- |\n";
    for (size_t i = 0; i < d.problem.drops.size(); ++i) {
      if (d.problem.drops[i].train) continue;
      out << "| " << d.problem.drops[i].drop_id << " | " << Num(d.base.gaps[i].force_nrmse) << " | "
          << Num(after.gaps[i].force_nrmse) << " | " << Num(100 * d.base.gaps[i].final_penetration_rel_error, 3)
          << " % | " << Num(100 * after.gaps[i].final_penetration_rel_error, 3) << " % |\n";
    }
    out << "| **mean** | " << Num(d.base.held_out.force_nrmse) << " | " << Num(after.held_out.force_nrmse) << " | "
        << Num(100 * d.base.held_out.final_penetration_rel_error, 3) << " % | "
        << Num(100 * after.held_out.final_penetration_rel_error, 3) << " % |\n\n";
    if (!d.where_after.empty()) {
      out << "After the named effect:\n\n| kind | factor | finding | p | significant |\n| --- | --- | --- | --- | --- |\n";
      for (const Finding& f : d.where_after)
        out << "| " << FindingKindName(f.kind) << " | " << f.factor << " | " << f.summary << " | " << Num(f.p_value, 3) << " | "
            << (f.significant ? "yes" : "no") << " |\n";
      out << "\n";
    }
    out << "![force against time](plots/overlays_force_time.png)\n\n![force against penetration]"
           "(plots/overlays_force_penetration.png)\n\n![residuals](plots/residuals.png)\n\n![gap per drop]"
           "(plots/gap_per_drop.png)\n\n";
    out << "Run: " << d.simulations << " simulated drops in " << Num(d.seconds, 3) << " s.\n";
  });
}

}  // namespace

void WriteDiagnosis(const Diagnosis& d, const dataset::Dataset& ds, const io::OutputTarget& out) {
  const CandidateScore* shown = Shown(d);
  const CandidateScore& after = d.winner >= 0 ? d.candidates[d.winner] : d.base;
  io::WriteOutputDirectory(out, io::OutputKind::kDiagnosis, [&](const std::string& staging) {
    const fs::path dir = staging;
    fs::create_directories(dir / "data");
    fs::create_directories(dir / "plots");
    model::WriteModelFile(DiagnosedModel(d, ds, after), (dir / "model.yaml").string(), out.path);
    io::WriteFileAtomically((dir / "diagnosis.json").string(), [&](std::ostream& out) { out << DiagnosisJson(d).dump(2) << '\n'; });
    WritePerDropCsv(d, ds, after, dir / "per_drop.csv");
    const std::vector<size_t> held = OverlaidDrops(d);
    WriteOverlayData(d, ds, shown, held, dir);
    const ResidualPanels residuals = WriteResiduals(d, ds, shown, dir);
    const std::string aug_title = shown ? (d.winner >= 0 ? "base + " + shown->name : "best candidate " + shown->name + " (not named)")
                                        : std::string("base");
    const std::string gp = OverlayFigure(d, ds, held, aug_title, false) + OverlayFigure(d, ds, held, aug_title, true) +
                           ResidualFigure(aug_title, residuals) +
                           GapPerDropFigure(aug_title,
                                            {WriteGapPanelData(GapRows(d, ds, after, rft::Atmosphere::kVacuum), "vacuum", dir),
                                             WriteGapPanelData(GapRows(d, ds, after, rft::Atmosphere::kAir), "air", dir)},
                                            AnyDropMadeWorse(d, after));
    io::RenderPlots(dir, {"plots/diagnose.gp", gp,
                          {io::FigurePng("plots/overlays_force_time"), io::FigurePng("plots/overlays_force_penetration"),
                           io::FigurePng("plots/residuals"), io::FigurePng("plots/gap_per_drop")}});
    WriteReport(d, ds, after, dir / "report.md");
  });
}

Diagnosis DiagnoseToDirectory(const std::string& measured_dir, const DiagnoseOptions& options,
                              const io::OutputTarget& out) {
  io::CheckOutputDirectory(out, io::OutputKind::kDiagnosis);
  const dataset::Dataset measured = dataset::ReadDataset(measured_dir);
  Diagnosis d = RunDiagnosis(measured, options);
  WriteDiagnosis(d, measured, out);
  return d;
}

}  // namespace touchdown::gap

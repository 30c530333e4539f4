// diagnosis.json (DiagnosisJson, diagnose.h): the base, every candidate, the selection, the
// sensor, the nuisances, the floor and the lack of fit, as numbers a script reads.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drop_tests/gap/diagnose.h"
#include "drop_tests/gap/diagnose_selection.h"
#include "drop_tests/formats/json_number.h"
#include "rft/units.h"

namespace touchdown::gap {

std::string SplitRule(const Diagnosis& d) {
  if (!d.fit_on.empty())
    return "--fit-on: every model is fitted on the designated drops and predicts every other drop";
  return "per (pad, soil, atmosphere) cell, ordered by speed then drop id: ranks 1, 4, 7, ... held out";
}

namespace {

nlohmann::json GapJson(const GapSummary& g) {
  return {{"force_nrmse", io::FiniteOrNull(g.force_nrmse)},
          {"force_nrmse_penetration", io::FiniteOrNull(g.force_nrmse_penetration)},
          {"final_penetration_rel_error", io::FiniteOrNull(g.final_penetration_rel_error)},
          {"peak_force_rel_error", io::FiniteOrNull(g.peak_force_rel_error)},
          {"noise_floor_force_nrmse", io::FiniteOrNull(g.noise_nrmse)},
          {"averaged_over", "held-out drops (mean; relative errors as mean |.|)"}};
}

// One fitted parameter: its value and 95 % interval in its file unit, and that unit.
nlohmann::json EstimateJson(const ParameterEstimate& e) {
  return {{"value", io::FiniteOrNull(e.value / e.file_to_si)},
          {"interval_95", {io::FiniteOrNull(e.low / e.file_to_si), io::FiniteOrNull(e.high / e.file_to_si)}},
          {"unit", e.unit}};
}

nlohmann::json ParametersJson(const FitResult& f, bool zeta) {
  nlohmann::json out = nlohmann::json::object();
  for (const ParameterEstimate& e : f.estimates) {
    if (e.effect.empty() != zeta) continue;
    out[zeta ? e.key.substr(e.key.find(':') + 1) : e.effect + "." + e.key] = EstimateJson(e);
  }
  return out;
}

nlohmann::json FindingsJson(const std::vector<Finding>& fs) {
  nlohmann::json out = nlohmann::json::array();
  for (const Finding& f : fs)
    out.push_back({{"kind", FindingKindName(f.kind)}, {"factor", f.factor}, {"summary", f.summary}, {"statistic", f.statistic},
                   {"p_value", f.p_value}, {"significant", f.significant}});
  return out;
}

// The accepted steps in order: the term each added, the model's parameters with their intervals,
// its Delta BIC against the model before, and the held-out gap after it.
nlohmann::json SelectionJson(const Diagnosis& d) {
  nlohmann::json out = nlohmann::json::array();
  for (size_t k = 0; k < d.selection.size(); ++k) {
    const CandidateScore& c = d.candidates[d.selection[k]];
    out.push_back({{"step", k + 1},
                   {"added", c.effect_ids.back()},
                   {"model", c.name},
                   {"parameters", ParametersJson(c.fit, false)},
                   {"delta_bic_vs_previous", c.delta_bic_step},
                   {"held_out_force_nrmse", c.held_out.force_nrmse},
                   {"gap_reduction_vs_previous", c.step_gap_reduction},
                   {"explained_fraction_vs_previous", c.step_explained},
                   {"gap_reduction_vs_base", c.gap_reduction}});
  }
  return out;
}

// In file units, as the key's suffix says (dz_mm in mm), like every other parameter written.
nlohmann::json EstimatesJson(const std::vector<ParameterEstimate>& estimates) {
  nlohmann::json j = nlohmann::json::object();
  for (const ParameterEstimate& e : estimates) j[e.key] = EstimateJson(e);
  return j;
}

// The sensor model: inferred (every sampling fitted, with its BIC: the evidence) or given.
nlohmann::json SensorJson(const Diagnosis& d) {
  nlohmann::json j{{"inferred", !d.sensor.given}, {"model", dataset::DescribeSensor(d.sensor.chosen)}};
  if (d.sensor.given) return j;
  j["evidence"] = d.sensor.evidence;
  nlohmann::json fits = nlohmann::json::array();
  for (const SensorCandidate& c : d.sensor.candidates)
    fits.push_back({{"name", c.name}, {"bic", c.bic}, {"parameter_count", c.parameters}, {"chosen", c.chosen},
                    {"screening_fit", c.screened}, {"model", dataset::DescribeSensor(c.sensor)},
                    {"parameters", EstimatesJson(c.estimates)}});
  j["candidates"] = fits;
  return j;
}

// The drops' nuisances: their spreads (the replicate scatter the fits allowed for).
nlohmann::json NuisancesJson(const Diagnosis& d) {
  const NuisanceSpreads& s = d.problem.spreads;
  return {{"on", d.problem.drop_nuisances},
          {"off_without_replicates", d.nuisances_without_replicates},
          {"strength_spread_percent", 100 * s.log_zeta},
          {"speed_spread_percent", 100 * s.log_speed},
          {"touchdown_time_spread_ms", 1e3 * s.time_s},
          {"residual_sigma", d.problem.residual_sigma}};
}

// The floor's parts, in force NRMSE (the root of the mean squares): the sensor's noise, the
// replicates' pure error (noise and the scatter the nuisances leave), and the base's excess above
// the floor (what a model of the conditions must explain).
nlohmann::json FloorJson(const Diagnosis& d) {
  const GapFloor& f = d.floor;
  nlohmann::json j{{"source", f.from_replicates ? "replicates (pure error)" : "sensor noise at rest"},
                   {"force_nrmse", std::sqrt(f.ms)},
                   {"force_nrmse_upper_95", std::sqrt(f.ms_upper)},
                   {"read_from_model", f.model},
                   {"sensor_noise_force_nrmse", std::sqrt(f.noise_ms)},
                   {"replicate_conditions", f.conditions},
                   {"replicate_degrees_of_freedom", f.replicate_df},
                   {"base_excess_force_nrmse", std::sqrt(std::max(d.base.held_out.mean_square - f.ms, 0.0))}};
  j["replicate_pure_error_force_nrmse"] = std::isfinite(f.replicate_ms) ? nlohmann::json(std::sqrt(f.replicate_ms)) : nlohmann::json();
  return j;
}

nlohmann::json LackOfFitJson(const std::vector<CellLackOfFit>& cells) {
  nlohmann::json j = nlohmann::json::array();
  for (const CellLackOfFit& c : cells)
    j.push_back({{"cell", c.cell}, {"conditions", c.conditions}, {"drops", c.drops},
                 {"lack_of_fit_force_nrmse", std::sqrt(c.lack_of_fit_ms)},
                 {"pure_error_force_nrmse", std::sqrt(c.pure_error_ms)}, {"F", c.F}, {"p_value", c.p_value}});
  return j;
}

}  // namespace

nlohmann::json DiagnosisJson(const Diagnosis& d) {
  nlohmann::json j;
  const CandidateScore* after = d.winner >= 0 ? &d.candidates[d.winner] : &d.base;
  j["named_effect"] = d.named_effect;
  j["named_effects"] = d.named_effects;
  j["named_nuisances"] = d.named_nuisances;
  j["sensor"] = SensorJson(d);
  j["drop_nuisances"] = NuisancesJson(d);
  j["floor"] = FloorJson(d);
  j["stop_samples_skipped"] = d.problem.stop_samples_skipped;
  j["lack_of_fit"] = {{"before", LackOfFitJson(d.lack_of_fit_before)}, {"after", LackOfFitJson(d.lack_of_fit_after)}};
  j["selected_terms"] = d.winner >= 0 ? nlohmann::json(d.candidates[d.winner].effect_ids) : nlohmann::json::array();
  if (!d.dynamic_term_statement.empty()) j["dynamic_term_statement"] = d.dynamic_term_statement;
  j["decision"] = d.decision;
  j["selection"] = SelectionJson(d);
  if (!d.residual_description.empty()) j["residual_description"] = d.residual_description;
  j["effect_parameters"] = d.winner >= 0 ? ParametersJson(after->fit, false) : nlohmann::json::object();
  j["zeta_N_cm3"] = ParametersJson(after->fit, true);
  // The rig's fitted parameters in the final model (its common offsets; a fitted low-pass cutoff or
  // load cell): measurement, reported apart from the soil's effects, whether the sensor was
  // inferred or given.
  nlohmann::json rig = nlohmann::json::object();
  for (const ParameterEstimate& e : after->fit.sensor_estimates)
    rig[e.effect + "." + e.key] = EstimateJson(e);
  j["rig_parameters"] = rig;
  j["gap_before"] = GapJson(d.base.held_out);
  j["gap_after"] = GapJson(after->held_out);
  j["gap_reduction"] = d.winner >= 0 ? after->gap_reduction : 0.0;
  j["where"] = {{"before", FindingsJson(d.where)}, {"after", FindingsJson(d.where_after)}};
  nlohmann::json cands = nlohmann::json::array();
  for (const CandidateScore& c : d.candidates) {
    nlohmann::json e{{"effect", c.name}, {"applies", c.applies}, {"step", c.step},
                     {"extends", c.extends < 0 ? std::string("base") : d.candidates[c.extends].name}};
    if (!c.applies) {
      e["why_not"] = c.why_not;
    } else if (c.screened_out) {
      e["screened_out"] = true;
      e["bic"] = c.fit.bic;
      e["delta_bic_vs_base"] = c.delta_bic;
      e["delta_bic_vs_extended"] = c.delta_bic_step;
      e["parameter_count"] = c.fit.parameters;
      e["iterations"] = c.fit.iterations;
      e["simulations"] = c.fit.simulations;
    } else {
      e["parameters"] = ParametersJson(c.fit, false);
      e["held_out_force_nrmse"] = c.held_out.force_nrmse;
      e["held_out_final_penetration_rel_error"] = c.held_out.final_penetration_rel_error;
      e["gap_reduction"] = c.gap_reduction;
      e["explained_fraction"] = c.explained;
      e["bic"] = c.fit.bic;
      e["delta_bic_vs_base"] = c.delta_bic;
      e["delta_bic_vs_extended"] = c.delta_bic_step;
      e["gap_reduction_vs_extended"] = c.step_gap_reduction;
      e["explained_fraction_vs_extended"] = c.step_explained;
      e["parameter_count"] = c.fit.parameters;
      e["converged"] = c.fit.converged;
      e["iterations"] = c.fit.iterations;
      e["simulations"] = c.fit.simulations;
      e["score"] = {{"held_out_force_nrmse", c.held_out.force_nrmse}, {"bic", c.fit.bic}};
    }
    cands.push_back(e);
  }
  j["candidates"] = cands;
  j["base"] = {{"bic", d.base.fit.bic}, {"parameter_count", d.base.fit.parameters}};
  if (d.problem.bekker_base) {  // the RFT base's JSON is unchanged (golden outputs)
    j["base"]["law"] = "bekker";
    nlohmann::json soils = nlohmann::json::array();
    for (size_t s = 0; s < d.bekker_base.size(); ++s) {
      const dataset::BekkerFit& f = d.bekker_base[s];
      soils.push_back({{"soil", d.problem.soils[s].name},
                       {"n", f.bekker.n},
                       {"k_c_kN_m_n1", f.bekker.k_c_N_m_n1 / units::kKilo},
                       {"k_phi_kN_m_n2", f.bekker.k_phi_N_m_n2 / units::kKilo},
                       {"modulus_scale_fitted", d.base.fit.zeta_N_m3[s]},
                       {"training_drops", f.drops},
                       {"method", f.method}});
    }
    j["base"]["bekker_soils"] = soils;
  }
  nlohmann::json split = {{"rule", SplitRule(d)},
                          {"train", nlohmann::json::array()}, {"held_out", nlohmann::json::array()}};
  for (const FitDrop& f : d.problem.drops) split[f.train ? "train" : "held_out"].push_back(f.drop_id);
  j["split"] = split;
  if (d.law_candidate) j["law_candidate"] = LawCandidateJson(*d.law_candidate);
  j["dataset"] = d.dataset_dir;
  j["simulations"] = d.simulations;
  j["seconds"] = d.seconds;
  return j;
}

}  // namespace touchdown::gap

#pragma once
// Fitting a model (zeta per soil, plus zero or more library effects) to measured drops, the
// engine of `touchdown diagnose`.
//
// Residuals: for every sample i of a drop's measured trace, at the recorded time t_i,
//   force:       (F_sim(t_i) - F_i) / max F         (compare.h's force NRMSE normalisation)
//   penetration: (d_sim(t_i) - d_i) / max d
// each divided by sqrt(samples of the drop), so every drop weighs the same and the cost is the
// mean over drops of the squared NRMSEs. F_sim, d_sim are what the rig would record
// (lander/pad/effect_soil_response.h RecordedAt, sensor_offset included).
//
// Solver: Levenberg-Marquardt (Marquardt's diagonal scaling) on scaled parameters (zeta /
// zeta_catalogue, effect values / their typical scale), box bounds by projection, forward-
// difference Jacobian; drops are simulated in parallel, the sums are in drop order, so results
// do not depend on the thread count.
// Intervals: cluster-robust (sandwich) covariance with the drops as clusters, since samples
// within one drop are not independent; 95 % with Student's t on (drops - 1) degrees of freedom.
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/model/effects.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "lander/pad/effect_soil_response.h"
#include "lander/pad/rig_drop.h"

namespace touchdown::gap {

struct FitDrop {
  size_t dataset_index = 0;
  std::string drop_id;
  int pad = 0, soil = 0;
  rft::Atmosphere atmosphere = rft::Atmosphere::kVacuum;  // the dataset row's
  bool train = true;
  double speed_m_s = 0.0, mass_kg = 0.0, gravity_m_s2 = 0.0;
  const dataset::DatasetTrace* trace = nullptr;
  double force_scale_N = 1.0;        // max measured force
  double penetration_scale_m = 1.0;  // max measured penetration
  double noise_force_N = 0.0;        // estimated sensor noise (at rest, pooled over the drops; diagnose_fit.cpp)
  double sample_period_s = 0.0;      // of its trace (dataset::SamplePeriod): what a sample averages over
};

// A term a fit can add to the base: a library effect with the range its parameters are fitted
// in. Usually the library's own range; but when every soil carries the same dynamic term (the
// shipped soils' dynamic RFT, lambda rho (v.n)^2), that term is split in two: `weaker_dynamic_term`
// is inertial_drag with lambda in [0, the shipped lambda] (the base's own term weakened or absent)
// and `inertial_drag` is lambda from the shipped value up (more of it). Both replace the soil's term,
// so they never enter one model together.
struct CandidateTerm {
  std::string name;       // in reports and diagnosis.json; the library id unless narrowed
  model::EffectId effect;  // the library effect it sets (model files carry its id)
  std::vector<model::EffectParameterInfo> parameters;  // the library's, with the fitted range
};
inline constexpr const char* kWeakerDynamicTerm = "weaker_dynamic_term";

struct FitProblem {
  std::vector<io::PadSpec> pads;
  std::vector<std::unique_ptr<geom::AxisymmetricIntrusion>> intrusions;
  std::vector<rft::SoilParameters> soils;  // catalogue values: the starting zeta
  std::vector<FitDrop> drops;
  pad::RigDropOptions rig;
  // How the simulated drops are recorded for the comparison with the measured samples.
  pad::SensorSampling sensor_sampling = pad::SensorSampling::kPeriodMean;
  int threads = 2;
  bool has_air = false, has_vacuum = false;
  // The soils' own dynamic term as an inertial_drag lambda (rft::WithSoilDynamicTerm) when every
  // soil has the same one, else 0; and the candidate terms (library order, the weaker dynamic term
  // first) that follow from it.
  double shipped_lambda = 0.0;
  std::vector<CandidateTerm> terms;  // The Bekker base (diagnose --base bekker, law_candidate.h UseBekkerBase): every soil is a Bekker
  // soil fitted on its training drops (n, k_c, k_phi as calibrate --law bekker), the drops run on
  // the pads' Bekker integrals, and the per-soil parameter fitted with the effects is a scale of
  // the soil's moduli k_c and k_phi (its zeta_N_m3 is then 1, so the fitted "zeta" is the scale).
  bool bekker_base = false;
  std::vector<std::unique_ptr<geom::AxisymmetricIntrusion>> bekker_intrusions;  // per pad
};

// Prepares every dataset drop; `held_out` marks the drops not used for fitting.
FitProblem MakeFitProblem(const dataset::Dataset& dataset, const std::vector<bool>& held_out, int threads);
// The candidate terms of `problem` (from its soils' dynamic term, above); sets problem.terms.
void SetCandidateTerms(FitProblem& problem);
// The candidate term called `name`; throws std::logic_error if there is none.
const CandidateTerm& FindTerm(const FitProblem& problem, const std::string& name);

struct ParameterEstimate {
  std::string effect;  // "" for zeta, else the candidate term's name
  std::string key;     // file key ("chi", "d_c_mm") or "zeta_N_cm3:<soil>"
  double value = 0.0, low = 0.0, high = 0.0;  // SI
  double file_to_si = 1.0;
  std::string unit;
  // The range the fit may take (SI); an interval that covers (nearly) all of it is not identified.
  double bound_low = -std::numeric_limits<double>::infinity(), bound_high = std::numeric_limits<double>::infinity();
};

struct FitResult {
  std::vector<std::string> effect_ids;  // candidate term names, in the order added; empty: the base
  std::vector<double> zeta_N_m3;        // per soil, at the soil's reference gravity
  std::vector<model::Effect> effects;          // fitted values, as library effects (ids: effect_id)
  std::vector<ParameterEstimate> estimates;
  double cost = 0.0;       // weighted, as minimised
  double rss = 0.0;        // unweighted sum of squared normalised residuals
  long samples = 0;        // residual count (training)
  int parameters = 0;
  double bic = 0.0;        // samples ln(rss / samples) + parameters ln(samples)
  // Per soil (index as FitProblem::soils): the RMS force residual of the fitted model,
  // sqrt(mean_i (F_sim(t_i) - F_i)^2) [N] over every measured sample i of the soil's training
  // drops (F_sim as recorded, sensor_offset included), and how many samples that is. What a model
  // file's fit.residual_rms_N and fit.samples record.
  std::vector<double> residual_rms_N;
  std::vector<long> force_samples;
  int iterations = 0;
  long simulations = 0;
  bool converged = false;
  rft::EffectTerms terms() const;
};

// Whether the candidate can be fitted on this problem; if not, `why` says why.
bool CandidateApplies(const FitProblem& problem, const std::vector<std::string>& effect_ids, std::string* why);
// Fits zeta per soil and the effects' parameters on the training drops. `start` (a fit of a
// sub-model, e.g. the base, or the model a forward-selection step extends) seeds zeta and the
// parameters of the terms it shares with this one.
FitResult FitCandidate(const FitProblem& problem, const std::vector<std::string>& effect_ids,
                       const FitResult* start = nullptr);

// What the rig would record for drop `d` under a fitted model, at the measured times; nullopt if
// the simulation failed (the pad never stopped, ...).
std::optional<dataset::DatasetTrace> SimulateRecorded(const FitProblem& problem, const FitDrop& d, const FitResult& model);

}  // namespace touchdown::gap

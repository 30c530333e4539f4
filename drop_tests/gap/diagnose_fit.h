#pragma once
// Fitting a model (zeta per soil, plus zero or more library effects) to measured drops, the
// engine of `touchdown diagnose`.
//
// Residuals: for every sample i of a drop's measured trace, at the recorded time t_i,
//   force:       (F_sim(t_i) - F_i) / max F         (compare.h's force NRMSE normalisation)
//   penetration: (d_sim(t_i) - d_i) / max d
// each divided by sqrt(samples of the drop), so every drop weighs the same and the cost is the
// mean over drops of the squared NRMSEs. F_sim, d_sim are what the rig would record through the
// problem's sensor model (drop_tests/dataset/sensor_model.h; sensor_offset included).
//
// Per-drop nuisances (random effects, FitProblem::drop_nuisances): a drop's soil strength and
// impact speed differ from their nominal values by a few per cent (bed preparation, release
// height), and its recorded t = 0 from the true touchdown (the detector). Each training drop gets
// its own log zeta factor, log speed factor and time offset, drawn from N(0, spread^2): fitted
// with the model, each with the penalty row (sigma / sqrt(n)) b / spread beside its drop's data
// rows (sigma the residual's per-sample scale), so the fit is the penalised likelihood of the
// mixed model. The spreads are estimated from the base's fitted nuisances (EstimateNuisanceSpreads).
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
#include "drop_tests/dataset/sensor_model.h"
#include "drop_tests/model/effects.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "lander/pad/effect_soil_response.h"
#include "lander/pad/rig_drop.h"

namespace touchdown::gap {

// A drop's nuisances (random effects): what its own bed, release and detector did.
struct DropNuisance {
  double log_zeta = 0.0;   // its soil's strength, as ln(zeta_drop / zeta)
  double log_speed = 0.0;  // its impact speed, as ln(v_drop / v_nominal)
  double time_s = 0.0;     // its recorded t = 0 after the true touchdown (as sensor_offset's dt)
  bool operator==(const DropNuisance&) const = default;
};
inline constexpr int kDropNuisances = 3;

// The spreads (standard deviations) of the nuisances over the drops.
struct NuisanceSpreads {
  double log_zeta = 0.03, log_speed = 0.01, time_s = 2e-4;
};

// Which of the rig's nuisance parameters a fit estimates beside the model's: the anti-alias
// low-pass's cutoff, the load cell's frequency and damping, and the record's common offsets in
// time and depth (sensor_offset's dt and dz: the detector's and the displacement sensor's zero).
struct SensorFit {
  bool cutoff = false;
  bool load_cell = false;
  bool offsets = false;
  int count() const { return int(cutoff) + 2 * int(load_cell) + 2 * int(offsets); }
};

struct FitDrop {
  size_t dataset_index = 0;
  std::string drop_id;
  int pad = 0, soil = 0;
  rft::Atmosphere atmosphere = rft::Atmosphere::kVacuum;  // the dataset row's
  bool train = true;
  double speed_m_s = 0.0, mass_kg = 0.0, gravity_m_s2 = 0.0;
  dataset::PenetrationZero penetration_zero = dataset::PenetrationZero::kSurface;  // the dataset row's
  const dataset::DatasetTrace* trace = nullptr;
  double force_scale_N = 1.0;        // max measured force
  double penetration_scale_m = 1.0;  // max measured penetration
  double noise_force_N = 0.0;        // estimated sensor noise (at rest, pooled over the drops; diagnose_fit.cpp)
  double sample_period_s = 0.0;      // of its trace (dataset::SamplePeriod): what a sample averages over
  // The samples either side of the measured stop, [stop_skip_begin, stop_skip_end): their force
  // residuals are not counted (StopSamples; empty when MakeFitProblem is told to count them, and
  // after CountStopSamples).
  size_t stop_skip_begin = 0, stop_skip_end = 0;
  bool ForceCounted(size_t i) const { return i < stop_skip_begin || i >= stop_skip_end; }
};

// The two samples of a measured force record either side of its stop, the steepest fall past its
// peak, as a half-open index range: sampled at instants, the rigid-plastic stop is a step, and
// which side of it those two samples fall on turns on where the stop lies within one sample
// period. Their residual is then 0 or the whole peak force by a shift of a fraction of a sample,
// a step in every parameter that moves the stop: it carries no more than the neighbouring samples
// and the penetration record say of the stop's time, and it outweighed the rest of a drop
// (docs/model_gap.md, "The stop's two samples").
struct SampleRange {
  size_t begin = 0, end = 0;
};
SampleRange StopSamples(const std::vector<double>& force_N);

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
  // How the simulated drops are recorded for the comparison with the measured samples (inferred
  // from the data by diagnose, or given), and which of its parameters a fit estimates.
  dataset::SensorModel sensor;
  SensorFit sensor_fit;
  // Per-drop nuisances in every fit (above), with their spreads and the residual's per-sample scale
  // (normalised units) that weighs their penalties.
  bool drop_nuisances = false;
  bool stop_samples_skipped = false;  // MakeFitProblem's skip_stop_samples (FitDrop::ForceCounted)
  // After each full fit, every training drop's nuisances fitted again alone from a fresh scan of
  // its trigger time (the model held, as a held-out drop's), kept where that lowers the drop's
  // cost, and the fit resumed (twice at most): a drop whose joint descent settled a sample or a
  // load cell's period off in time is a local minimum the joint fit cannot leave.
  bool refit_drop_nuisances = true;
  NuisanceSpreads spreads;
  double residual_sigma = 0.01;
  // Levenberg-Marquardt's iterations per fit at most (a screening fit may take fewer).
  int max_iterations = 20;
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

// Prepares every dataset drop; `held_out` marks the drops not used for fitting. `skip_stop_samples`:
// each drop's StopSamples are left out of its force residuals (false: every sample counts).
FitProblem MakeFitProblem(const dataset::Dataset& dataset, const std::vector<bool>& held_out, int threads,
                          bool skip_stop_samples = true);
// The candidate terms of `problem` (from its soils' dynamic term, above); sets problem.terms.
void SetCandidateTerms(FitProblem& problem);
// The candidate term called `name`; throws std::logic_error if there is none.
const CandidateTerm& FindTerm(const FitProblem& problem, const std::string& name);

struct ParameterEstimate {
  std::string effect;  // "" for zeta, else the candidate term's name
  std::string key;     // file key ("chi", "d_c_mm") or "zeta_N_cm3:<soil>"
  double value = 0.0, low = 0.0, high = 0.0;  // SI
  double file_to_si = 1.0;
  std::string unit;  // of value / file_to_si, the file's (the key's suffix: "mm", "N/cm^3")
  // The range the fit may take (SI); an interval that covers (nearly) all of it is not identified.
  double bound_low = -std::numeric_limits<double>::infinity(), bound_high = std::numeric_limits<double>::infinity();
};

struct FitResult {
  std::vector<std::string> effect_ids;  // candidate term names, in the order added; empty: the base
  std::vector<double> zeta_N_m3;        // per soil, at the soil's reference gravity
  std::vector<model::Effect> effects;          // fitted values, as library effects (ids: effect_id)
  std::vector<ParameterEstimate> estimates;    // zeta per soil, then the terms' parameters
  dataset::SensorModel sensor;                 // as fitted (the problem's, with its free parameters)
  std::vector<ParameterEstimate> sensor_estimates;  // the sensor's fitted parameters (nuisances)
  double offset_dt_s = 0.0, offset_dz_m = 0.0;      // the common offsets, with SensorFit::offsets
  // Per problem drop (FitProblem::drops' order): the training drops' fitted nuisances; zero for
  // the held-out ones (SimulateRecorded fits theirs when it predicts them).
  std::vector<DropNuisance> nuisances;
  double penalty = 0.0;    // the nuisances' penalty rows' sum of squares (part of cost)
  double cost = 0.0;       // weighted, as minimised
  double rss = 0.0;        // unweighted sum of squared normalised residuals
  long samples = 0;        // residual count (training)
  int parameters = 0;
  // samples ln((rss + penalty) / samples) + parameters ln(samples), the nuisances' penalty in the
  // residual sum (their prior as observations), their count not among the parameters.
  double bic = 0.0;
  // Per soil (index as FitProblem::soils): the RMS force residual of the fitted model,
  // sqrt(mean_i (F_sim(t_i) - F_i)^2) [N] over every measured sample i of the soil's training
  // drops (F_sim as recorded, sensor_offset included), and how many samples that is. What a model
  // file's fit.residual_rms_N and fit.samples record.
  std::vector<double> residual_rms_N;
  std::vector<long> force_samples;
  int iterations = 0;
  long simulations = 0;
  bool converged = false;
  bool screening = false;  // a screening fit (FitCandidate's screen_iterations): no intervals
  rft::EffectTerms terms() const;
};

// Whether the candidate can be fitted on this problem; if not, `why` says why.
bool CandidateApplies(const FitProblem& problem, const std::vector<std::string>& effect_ids, std::string* why);
// Fits zeta per soil and the effects' parameters on the training drops. `start` (a fit of a
// sub-model, e.g. the base, or the model a forward-selection step extends) seeds zeta and the
// parameters of the terms it shares with this one.
// `screen_iterations` > 0: a screening fit, at most that many iterations and no intervals
// (estimates empty), to rank candidates before the best few are fitted in full from it.
FitResult FitCandidate(const FitProblem& problem, const std::vector<std::string>& effect_ids,
                       const FitResult* start = nullptr, int screen_iterations = 0);

// What the rig would record for drop `d` under a fitted model, at the measured times; nullopt if
// the simulation failed (the pad never stopped, ...). With the problem's drop nuisances, a training
// drop's are the fitted ones and a held-out drop's are fitted here to its own record (the model's
// parameters held, the spreads as the prior): the prediction of a new drop of that condition.
std::optional<dataset::DatasetTrace> SimulateRecorded(const FitProblem& problem, const FitDrop& d, const FitResult& model);
// A way of recording a simulation: a sensor, and a time offset added to the model's.
struct Recording {
  dataset::SensorModel sensor;
  double extra_dt_s = 0.0;
};
// The weighted data cost (penalty rows apart) of `model` (its values and training nuisances as
// they are, nothing fitted) on the problem's training drops, recorded in each of `recordings`:
// each drop simulated once.
std::vector<double> TrainingCostsUnder(const FitProblem& problem, const FitResult& model,
                                       const std::vector<Recording>& recordings);
// A held-out drop's nuisances under `model` (the penalised fit above); zero without them.
DropNuisance FitDropNuisance(const FitProblem& problem, const FitDrop& d, const FitResult& model);
// The spreads of the nuisances fitted in `fit` (their root mean square within conditions, over
// the training drops that repeat one, each at least a floor: half a per cent in strength, a fifth
// in speed, 2 ms or 2 samples in time), and the residual's per-sample scale from its data rows.
// Returns the degrees of freedom they were read from (sum over conditions of replicates - 1).
int EstimateNuisanceSpreads(FitProblem& problem, const FitResult& fit);
// Fewer degrees of freedom of replicates, and the drops are fitted at their nominal conditions:
// where every condition is one drop, nothing tells a drop's scatter from the model's misfit at that
// condition, and the nuisances take up the effect (a hidden plug, an impulse at contact, was absorbed
// by the drops' speeds and time shifts on the 12 unreplicated drops of the unit tests).
inline constexpr int kMinNuisanceDf = 3;
// Replicates share a condition: pad, soil, atmosphere, nominal speed, mass and gravity.
std::string ConditionKey(const FitDrop& d);
// The training drops' degrees of freedom of replicates: the sum over conditions of drops - 1 (what
// EstimateNuisanceSpreads reads the spreads from).
int TrainingReplicateDf(const FitProblem& problem);
// Every drop's stop samples counted again (FitDrop::ForceCounted true everywhere). Diagnose leaves
// them out only where each drop's touchdown time is its own nuisance (replicates, kMinNuisanceDf):
// then a drop's stop alone times it, a step within a sample. Where the drops share the record's
// common offsets only, the stops of all drops, at their several phases within a sample, time the
// record together, and left out there the common dt and dz and then a hidden gas cushion's fit
// went astray (6 unreplicated drops at 1 kHz, tests/python/test_commands.py).
void CountStopSamples(FitProblem& problem);

}  // namespace touchdown::gap

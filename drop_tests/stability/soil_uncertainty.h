#pragma once
// A stability study's soil uncertainty: each named soil's parameters that a calibration holds (its
// zeta, its dynamic term's dynamic_lambda, a Bekker soil's n, k_c and k_phi; any of them) drawn,
// landing by landing, from the joint normal
// distribution the calibration reports (`touchdown calibrate --targets ... --report
// R.json`: the best values and their covariance, drop_tests/targets/targets_fit.h), instead of
// the fixed number of its soil file:
//
//   study:
//     soil_uncertainty:
//       fjs1_cp: {calibration: ../soils/calibrations/sutoh2017_r1z.json}   # relative to the study file
//
// Soils taken from one calibration file are drawn jointly (their covariance, correlations
// included); soils from different files independently. Draws are counter-based, keyed by (the
// study's seed, the landing's index, the parameter, the attempt), so a landing's soil follows from
// its index alone, on any thread, rank or shard. A draw outside a parameter's box is drawn again
// (rejection: the normal truncated to the box); after kMaxDrawAttempts rejected draws the landing
// takes the best values. The box is the calibration's fit bounds (the report's `lower`, `upper`)
// within the physical range (rft/physical_limits.h: zeta in (0, 1e4] N/cm^3, dynamic_lambda in
// [0, 100], Bekker's n in (0, 5], k_c and k_phi in [0, 1e6] in the soil file's kN units), or the
// physical range alone (a report without bounds, or `truncate: physical_limits`).
//
// The summary's split of the outcome's variance into the soil's share and the conditions' share,
// and P(tip) at the soil's interval ends, are SoilSplit below (docs/stability_studies.md, "The
// soil's uncertainty").
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json_fwd.hpp>

#include "drop_tests/model/model_file.h"
#include "drop_tests/sweep/results_db.h"

namespace touchdown::io {
class YamlFields;
}
namespace touchdown::sweep {
struct SweepPlan;
}

namespace touchdown::stability {

inline constexpr int kMaxDrawAttempts = 64;
// The counter streams of the draws: far above the sweep's (parameters 0-17, per-pad 0x100-0x4ff).
inline constexpr uint64_t kSoilDrawStream = 0x50000;
inline constexpr uint64_t kSoilAttemptStride = 0x1000;  // parameters per study, at most
inline constexpr int kMaxUncertainParameters = 64;

// Which of a soil's numbers a parameter is (the calibration report's `kind`).
enum class SoilField {
  kZeta,           // zeta_N_cm3 [N/cm^3] at reference_gravity_m_s2 (kind soil_zeta)
  kDynamicLambda,  // dynamic_lambda [-] (kind soil_dynamic_lambda)
  kBekkerN,        // bekker.n [-] (kind soil_bekker_n)
  kBekkerKc,       // bekker.k_c_kN_m_n1 [kN/m^(n+1)] (kind soil_bekker_k_c)
  kBekkerKphi,     // bekker.k_phi_kN_m_n2 [kN/m^(n+2)] (kind soil_bekker_k_phi)
};
inline constexpr SoilField kSoilFields[] = {SoilField::kZeta, SoilField::kDynamicLambda, SoilField::kBekkerN,
                                            SoilField::kBekkerKc, SoilField::kBekkerKphi};
// How a field is named and bounded: the calibration report's kind, the outputs' column after
// "<soil>_", the unit of its values and its physical range (rft/physical_limits.h).
struct SoilFieldInfo {
  std::string kind, column_suffix, unit;
  const limits::Range* range;
  const model::BekkerOverrideField* bekker;  // the Bekker fields': the model override's entry
};
const SoilFieldInfo& InfoOf(SoilField f);

struct UncertainParameter {
  std::string soil;         // the soil's name, as the lander's ground names it
  std::string name;         // the calibration's parameter name, e.g. zeta_cp
  SoilField field = SoilField::kZeta;
  std::string column;       // its column in the outputs: "<soil>_zeta_N_cm3", "<soil>_bekker_n"...
  double mean = 0.0;        // in the field's unit (the calibration's best value)
  double sigma = 0.0;       // one standard deviation, same unit
  double reference_gravity_m_s2 = 0.0;  // zeta's; for lambda the soil file's
  double soil_zeta_N_m3 = 0.0;  // the soil file's zeta: what a soil whose zeta is not drawn keeps
  // Where a draw must lie (same unit): the physical range (rft/physical_limits.h), narrowed to the
  // calibration's fit bounds unless the study says `truncate: physical_limits`.
  double low = 0.0, high = 0.0;
  bool low_open = false;  // low itself excluded
  bool fit_bounded = false;  // the box is narrowed to the calibration's bounds
};

struct CalibrationGroup {  // the parameters taken from one calibration file, drawn jointly
  std::string file;
  std::vector<size_t> parameters;  // indices into SoilUncertainty::parameters
  Eigen::MatrixXd covariance;      // N/cm^3 squared
  Eigen::MatrixXd lower;           // its Cholesky factor L (L L^T = covariance)
};

struct SoilUncertainty {
  std::vector<UncertainParameter> parameters;
  std::vector<CalibrationGroup> groups;
  uint64_t seed = 0;  // the study's
};

// How a soil's draws are truncated (`truncate:` of its soil_uncertainty entry).
enum class SoilTruncation {
  kFitBounds,      // to the calibration's fit bounds within the physical range (the default)
  kPhysicalLimits  // to the physical range only
};

// Reads the study block's `soil_uncertainty` (the mapping soil name -> {calibration: FILE}) against
// the study's plan: every soil one its landings' ground holds, every file a calibration report with
// a covariance holding that soil's zeta, dynamic_lambda or Bekker fields (positive definite over
// those drawn), a drawn zeta only where the ground's law uses zeta, a drawn lambda only on a soil
// whose dynamic term is on, a drawn Bekker field only where the soil runs on the bekker law.
// InputError naming the file and field.
SoilUncertainty ReadSoilUncertainty(const io::YamlFields& study_block, const sweep::SweepPlan& plan);
// The keys of one soil's entry under `study.soil_uncertainty`.
const std::vector<std::string>& SoilUncertaintyEntryKeys();

// The parameters landing `index` runs with, in file units (N/cm^3, -, kN/m^(n+1), kN/m^(n+2)), in
// `parameters` order.
std::vector<double> DrawSoilParameters(const SoilUncertainty& u, int64_t index);
// The same as the soil overrides a lander run takes (sweep::SweepPlan::soil_overrides_at): zeta, and
// dynamic_lambda and the Bekker fields where drawn (a soil whose zeta is not drawn keeps its file's).
std::map<std::string, model::SoilOverride> SoilOverrides(const SoilUncertainty& u, const std::vector<double>& drawn);
// What the draws depend on, for the plan's variant (and so its digest): soils, best values, covariances.
std::string SoilUncertaintyDigestText(const SoilUncertainty& u);
// Sets the plan's soil_overrides_at and variant to the draws.
void AttachSoilUncertainty(sweep::SweepPlan& plan, const SoilUncertainty& u);

// How much of an outcome's variance the soil's parameters explain (first order), from the study's
// landings: the adjusted R^2 of the least-squares fit of the outcome on the drawn parameters (a
// linear conditional expectation, what a first-order Sobol index is when the outcome is locally
// linear in the parameters), with a 95 % interval from Fisher's z of the multiple correlation.
struct ShareEstimate {
  std::string outcome;  // tipped_over, or a metric's name
  int64_t landings = 0;
  double variance = 0.0;                    // of the outcome over those landings
  double soil_share = 0.0;                  // adjusted R^2, clipped to [0, 1]
  double soil_share_low = 0.0, soil_share_high = 0.0;
  std::vector<double> slope;                // per parameter [outcome per parameter unit]
};

struct SoilSplit {
  std::vector<ShareEstimate> shares;  // tipped_over first, then the metrics
  // P(tip) from the linear fit of the tip-over indicator: at each parameter's 95 % interval ends
  // (the others at their best values), and at the ends of the 95 % range of the soil's combined
  // effect (+-1.96 sqrt(b^T C b), b the slopes, C the covariance); clipped to [0, 1].
  double p_tip = 0.0;
  std::vector<std::pair<double, double>> p_tip_at_parameter_ends;
  double p_tip_soil_sd = 0.0;  // sqrt(b^T C b)
  std::pair<double, double> p_tip_at_soil_ends{0.0, 0.0};
};

// The split over completed landings (tipped_over) and over the landings that stayed up (the
// metrics, as their percentiles are). nullopt with fewer than parameters + 3 landings.
std::optional<SoilSplit> SplitBySoil(const SoilUncertainty& u, const std::vector<sweep::DropRecord>& records);
nlohmann::json SoilSplitJson(const SoilUncertainty& u, const std::optional<SoilSplit>& split);
// The drawn parameters of landing `index`, by column, for summary.json's listed landings.
nlohmann::json DrawnParametersJson(const SoilUncertainty& u, int64_t index);

}  // namespace touchdown::stability

#pragma once
// `touchdown validate`: every measured point and trend of every source simulated with the
// project's drop path (the rig drop of drop/pad_drop.h: a vertical, axisymmetric impact), under
// each model variant, and compared:
//  - quasi-static RFT (the project's default) and dynamic RFT (the effect library's
//    inertial_drag, lambda rho (v.n)^2, lambda from data/validation/dynamic_rft.yaml);
//  - for low-gravity sources, each with zeta scaled with g (lithostatic: the soil's reference
//    gravity, today's default) and with zeta fixed at its reference-gravity value.
// Zeta follows the source's route: the soil's (derived) or fitted on the one designated point,
// per variant; every other point is then a prediction.
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/validation/static_bearing.h"
#include "drop_tests/validation/validation_source.h"

namespace touchdown::validation {

struct Variant {
  bool dynamic = false;     // inertial_drag on
  bool zeta_fixed = false;  // zeta not scaled with gravity
  std::string Name() const;  // "quasi_static", "dynamic", "quasi_static_zeta_fixed", ...
};

struct PointResult {
  const MeasuredPoint* point = nullptr;
  std::vector<double> simulated;       // per variant (SI)
  std::vector<double> relative_error;  // (simulated - measured) / measured, per variant
};

struct TrendResult {
  const MeasuredTrend* trend = nullptr;
  // Per variant, per value (SI): the abscissa of the fit (the trend's values, or for
  // kTotalDropDistance h + d) and the simulated quantity.
  std::vector<std::vector<double>> x;
  std::vector<std::vector<double>> simulated;
  std::vector<double> exponent;                // per variant: log-log least squares
  std::vector<bool> reproduced;                // per variant
};

// A static bearing measurement against the model: per variant the pressure [Pa] at the corners
// of the depth and diameter ranges (depth low/high x diameter low/high, in that order), their range
// and how it stands against the measured range. The dynamic variants equal the quasi-static ones
// (a static test: zero speed).
struct BearingResult {
  const MeasuredBearing* bearing = nullptr;
  std::vector<std::vector<double>> corners_Pa;
  std::vector<Range> simulated_Pa;
  std::vector<RangeComparison> comparison;
};

// A simulated curve for the plots: quantity against impact speed over the measured range.
struct Curve {
  Quantity quantity = Quantity::kFinalDepth;
  std::vector<double> speed_m_s;
  std::vector<std::vector<double>> simulated;  // per variant
};

struct SourceResult {
  const ValidationSource* source = nullptr;
  std::vector<Variant> variants;
  std::vector<double> zeta_N_m3;  // per variant, at the reference gravity (fitted or the soil's)
  std::vector<PointResult> points;
  std::vector<TrendResult> trends;
  std::vector<BearingResult> bearings;
  std::vector<Curve> curves;
  // Per variant: mean |relative error| over the predicted points (the calibration point
  // excluded), NaN without points; trends reproduced; static bearings met (inside or overlapping).
  std::vector<double> mean_abs_error;
  std::vector<int> trends_reproduced;
  std::vector<int> bearings_met;
  std::vector<double> bearing_distance;  // sum of |relative distance| of the bearings met by none
  int best_variant = 0;  // most trends reproduced and bearings met, then the smallest mean
                         // error, then (without points) the smallest bearing distance
};

struct ValidationResult {
  const ValidationSet* set = nullptr;
  std::shared_ptr<const ValidationSet> owned_set;  // `set`, when the result owns it (ValidateSources)
  std::vector<SourceResult> sources;
};

// Runs every source (rig drops; a few hundred, about a millisecond each). Throws InputError on a
// source the drop path refuses, integ::IntegrationFailure when a drop fails.
ValidationResult RunValidation(const ValidationSet& set);

// The simulated quantity of one drop (SI): exposed for the tests.
// `mass_kg`: the projectile's mass when not the pad's.
double SimulateQuantity(const ValidationSource& source, const Variant& variant, double zeta_N_m3, double lambda,
                        Quantity quantity, double impact_speed_m_s, double gravity_m_s2,
                        std::optional<double> mass_kg = std::nullopt);

// Whether a simulated exponent reproduces a measured trend.
bool TrendReproduced(const MeasuredTrend& trend, double simulated_exponent);

// validation.json, as the command writes it.
nlohmann::json ValidationJson(const ValidationResult& result);
// The report's tables (Markdown): per source measured, simulated, error; per trend the exponents.
std::string ValidationMarkdown(const ValidationResult& result);
// The console summary the command prints.
std::string ValidationSummary(const ValidationResult& result);
// Writes DIR/validation.json, DIR/validation.md and DIR/plots/ (measured points vs simulated
// curves per source, PNG + SVG) as one whole output (io::OutputKind::kValidation).
void WriteValidationOutputs(const ValidationResult& result, const std::string& out_dir);
// `touchdown validate` as one call (the command line and the Python module): the sources of
// `sources_dir` (empty: the data's validation/) loaded, the output directory `out_dir` (empty: none)
// checked before anything runs, every source run, the outputs written.
ValidationResult ValidateSources(const std::string& sources_dir, const std::string& out_dir);

}  // namespace touchdown::validation

#include "drop_tests/validation/validate.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

#include <boost/math/tools/roots.hpp>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/model/effects.h"
#include "drop_tests/validation/power_law_fit.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "lander/integ/cvode_integrator.h"
#include "lander/pad/release.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::validation {

std::string Variant::Name() const {
  return std::string(dynamic ? "dynamic" : "quasi_static") + (zeta_fixed ? "_zeta_fixed" : "");
}

namespace {

constexpr int kCurveSamples = 25;

// The rig's options for validation drops: a short rest phase (only the stroke is compared).
drop::DropRunOptions RunOptions(const geom::AxisymmetricIntrusion* intrusion) {
  drop::DropRunOptions o;
  o.rig.rest_duration_s = 0.01;
  o.intrusion = intrusion;
  return o;
}

double Pick(const drop::PadDrop& d, Quantity q) {
  return q == Quantity::kFinalDepth ? d.result.final_penetration_m : d.result.time_to_rest_s;
}

// One source's drops: the pad's profile integral built once.
class SourceRunner {
 public:
  SourceRunner(const ValidationSource& source, double lambda)
      : source_(source), lambda_(lambda), intrusion_(drop::MakeRigIntrusion(source.pad.profile)) {}

  double Run(const Variant& v, double zeta_N_m3, Quantity q, double speed_m_s, double gravity_m_s2,
             std::optional<double> mass_kg = std::nullopt) const {
    rft::SoilParameters soil = source_.soil;
    // zeta fixed: the soil's zeta holds at every gravity (its reference gravity is the drop's).
    if (v.zeta_fixed) soil.reference_gravity_m_s2 = gravity_m_s2;
    drop::DropConditions c;
    c.impact_speed_m_s = speed_m_s;
    c.gravity_m_s2 = gravity_m_s2;
    c.zeta_N_m3 = zeta_N_m3;
    c.mass_kg = mass_kg;
    if (v.dynamic)
      c.effects = model::MakeEffectTerms({{model::FindEffect(model::EffectId::kInertialDrag).id, {lambda_}}}, source_.file);
    c.effects_source = source_.file;
    drop::ValidateConditions(c, source_.file);
    try {
      return Pick(drop::RunDrop(drop::ResolveDrop(source_.pad, soil, c, RunOptions(intrusion_.get()))), q);
    } catch (const integ::IntegrationFailure& e) {
      // Name the drop: the source, the variant and its conditions.
      throw integ::IntegrationFailure(source_.id + ", " + v.Name() + ", impact speed " + std::to_string(speed_m_s) +
                                      " m/s, gravity " + std::to_string(gravity_m_s2) + " m/s^2, zeta " +
                                      std::to_string(zeta_N_m3 * units::kN_cm3_per_N_m3) + " N/cm^3: " + e.what());
    }
  }

 private:
  const ValidationSource& source_;
  double lambda_;
  std::unique_ptr<geom::AxisymmetricIntrusion> intrusion_;
};

// zeta [N/m^3, at the soil's reference gravity] for which the variant reproduces the designated
// point's depth (TOMS 748 on log zeta; the depth falls as zeta grows).
double CalibrateZeta(const SourceRunner& runner, const ValidationSource& s, const Variant& v) {
  const MeasuredPoint& p = *std::find_if(s.points.begin(), s.points.end(),
                                         [&](const MeasuredPoint& q) { return q.id == s.calibrated_on; });
  const auto misfit = [&](double log_zeta) {
    try {
      return std::log(runner.Run(v, std::exp(log_zeta), p.quantity, p.impact_speed_m_s, s.gravity_m_s2) / p.value);
    } catch (const integ::IntegrationFailure&) {
      return 10.0;  // a soil too soft to stop the pad: far too deep
    }
  };
  double lo = std::log(1e3), hi = std::log(1e9);
  if (misfit(lo) < 0.0 || misfit(hi) > 0.0)
    throw MakeInputError(s.file, "medium.calibrated_on",
                         "no zeta in [1e-3, 1e3] N/cm^3 reproduces point '" + p.id + "' (" + v.Name() + ")");
  std::uintmax_t iterations = 100;
  const auto root = boost::math::tools::toms748_solve(misfit, lo, hi, boost::math::tools::eps_tolerance<double>(40),
                                                      iterations);
  return std::exp(0.5 * (root.first + root.second));
}

std::vector<Variant> VariantsOf(const ValidationSource& s) {
  std::vector<Variant> v{{false, false}, {true, false}};
  if (s.low_gravity) v.insert(v.end(), {{false, true}, {true, true}});
  return v;
}

void RunPoints(const SourceRunner& runner, SourceResult& r) {
  const ValidationSource& s = *r.source;
  for (const MeasuredPoint& p : s.points) {
    PointResult pr{&p, {}, {}};
    for (size_t k = 0; k < r.variants.size(); ++k) {
      const double sim = runner.Run(r.variants[k], r.zeta_N_m3[k], p.quantity, p.impact_speed_m_s, s.gravity_m_s2);
      pr.simulated.push_back(sim);
      pr.relative_error.push_back((sim - p.value) / p.value);
    }
    r.points.push_back(std::move(pr));
  }
}

// The sphere of the pad's radius at density rho [kg].
double SphereMass(const ValidationSource& s, double rho_kg_m3) {
  const double radius = s.pad.profile.points.back().x_m;
  return rho_kg_m3 * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

// One trend point of one variant: (abscissa of the fit, simulated quantity).
std::pair<double, double> TrendPoint(const SourceRunner& runner, const SourceResult& r, size_t k,
                                     const MeasuredTrend& t, double value) {
  const Variant& v = r.variants[k];
  switch (t.vary) {
    case Variable::kImpactSpeed:
      return {value, runner.Run(v, r.zeta_N_m3[k], t.quantity, value, t.at_gravity_m_s2)};
    case Variable::kGravity:
      return {value, runner.Run(v, r.zeta_N_m3[k], t.quantity, t.at_impact_speed_m_s, value)};
    case Variable::kTotalDropDistance: {
      const double speed = pad::TouchdownSpeed(0.0, t.at_gravity_m_s2, value);
      const double y = runner.Run(v, r.zeta_N_m3[k], t.quantity, speed, t.at_gravity_m_s2);
      const double depth = t.quantity == Quantity::kFinalDepth
                               ? y
                               : runner.Run(v, r.zeta_N_m3[k], Quantity::kFinalDepth, speed, t.at_gravity_m_s2);
      return {value + depth, y};
    }
    case Variable::kProjectileDensity:
      return {value, runner.Run(v, r.zeta_N_m3[k], t.quantity, t.at_impact_speed_m_s, t.at_gravity_m_s2,
                                SphereMass(*r.source, value))};
  }
  return {0.0, 0.0};
}

void RunTrends(const SourceRunner& runner, SourceResult& r) {
  for (const MeasuredTrend& t : r.source->trends) {
    TrendResult tr{&t, {}, {}, {}, {}};
    for (size_t k = 0; k < r.variants.size(); ++k) {
      std::vector<double> x, y;
      for (const double value : t.values) {
        const auto [xi, yi] = TrendPoint(runner, r, k, t, value);
        x.push_back(xi);
        y.push_back(yi);
      }
      const double exponent = FitPowerLaw(x, y).exponent;
      tr.x.push_back(std::move(x));
      tr.simulated.push_back(std::move(y));
      tr.exponent.push_back(exponent);
      tr.reproduced.push_back(TrendReproduced(t, exponent));
    }
    r.trends.push_back(std::move(tr));
  }
}

// Each static bearing at the corners of its depth and diameter ranges, per variant: zeta the
// variant's, scaled with g from the soil's reference gravity or (zeta fixed) not.
void RunBearings(SourceResult& r) {
  const ValidationSource& s = *r.source;
  for (const MeasuredBearing& b : s.bearings) {
    BearingResult br{&b, {}, {}, {}};
    for (size_t k = 0; k < r.variants.size(); ++k) {
      rft::SoilParameters soil = s.soil;
      soil.zeta_N_m3 = r.zeta_N_m3[k];
      if (r.variants[k].zeta_fixed) soil.reference_gravity_m_s2 = s.gravity_m_s2;
      std::vector<double> corners;
      for (const double depth : {b.depth_m.low, b.depth_m.high})
        for (const double diameter : {b.diameter_m.low, b.diameter_m.high})
          corners.push_back(StaticBearingPressure(s.pad, soil, s.gravity_m_s2, depth, diameter));
      const Range range{*std::min_element(corners.begin(), corners.end()),
                        *std::max_element(corners.begin(), corners.end())};
      br.corners_Pa.push_back(std::move(corners));
      br.simulated_Pa.push_back(range);
      br.comparison.push_back(CompareRanges(range, b.pressure_Pa));
    }
    r.bearings.push_back(std::move(br));
  }
}

// Per quantity with measured points: the simulated curve over the points' speed range.
void RunCurves(const SourceRunner& runner, SourceResult& r) {
  const ValidationSource& s = *r.source;
  for (const Quantity q : {Quantity::kFinalDepth, Quantity::kStopTime}) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const MeasuredPoint& p : s.points)
      if (p.quantity == q) lo = std::min(lo, p.impact_speed_m_s), hi = std::max(hi, p.impact_speed_m_s);
    if (!(hi > lo)) continue;
    Curve c{q, {}, std::vector<std::vector<double>>(r.variants.size())};
    for (int i = 0; i < kCurveSamples; ++i) c.speed_m_s.push_back(lo + (hi - lo) * i / (kCurveSamples - 1));
    for (size_t k = 0; k < r.variants.size(); ++k)
      for (const double v : c.speed_m_s)
        c.simulated[k].push_back(runner.Run(r.variants[k], r.zeta_N_m3[k], q, v, s.gravity_m_s2));
    r.curves.push_back(std::move(c));
  }
}

void Score(SourceResult& r) {
  const ValidationSource& s = *r.source;
  for (size_t k = 0; k < r.variants.size(); ++k) {
    double sum = 0.0;
    int n = 0;
    for (const PointResult& p : r.points) {
      if (s.zeta_route == ZetaRoute::kCalibratedOn && p.point->id == s.calibrated_on) continue;
      sum += std::abs(p.relative_error[k]);
      ++n;
    }
    r.mean_abs_error.push_back(n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN());
    int reproduced = 0;
    for (const TrendResult& t : r.trends) reproduced += t.reproduced[k] ? 1 : 0;
    r.trends_reproduced.push_back(reproduced);
    int met = 0;
    double distance = 0.0;
    for (const BearingResult& b : r.bearings) {
      met += b.comparison[k].agreement != RangeAgreement::kOutside ? 1 : 0;
      distance += std::abs(b.comparison[k].relative_distance);
    }
    r.bearings_met.push_back(met);
    r.bearing_distance.push_back(distance);
  }
  for (size_t k = 1; k < r.variants.size(); ++k) {
    const size_t b = static_cast<size_t>(r.best_variant);
    const int score_k = r.trends_reproduced[k] + r.bearings_met[k], score_b = r.trends_reproduced[b] + r.bearings_met[b];
    const bool more = score_k > score_b;
    const bool tie = score_k == score_b;
    const bool no_points = std::isnan(r.mean_abs_error[k]) && std::isnan(r.mean_abs_error[b]);
    const bool closer = r.mean_abs_error[k] < r.mean_abs_error[b] ||
                        (no_points && r.bearing_distance[k] < r.bearing_distance[b]);
    if (more || (tie && closer)) r.best_variant = static_cast<int>(k);
  }
}

}  // namespace

double SimulateQuantity(const ValidationSource& source, const Variant& variant, double zeta_N_m3, double lambda,
                        Quantity quantity, double impact_speed_m_s, double gravity_m_s2, std::optional<double> mass_kg) {
  return SourceRunner(source, lambda).Run(variant, zeta_N_m3, quantity, impact_speed_m_s, gravity_m_s2, mass_kg);
}

bool TrendReproduced(const MeasuredTrend& trend, double simulated_exponent) {
  switch (trend.direction) {
    case Direction::kIncreasing: return simulated_exponent > 0.0;
    case Direction::kDecreasing: return simulated_exponent < 0.0;
    case Direction::kExponent: return std::abs(simulated_exponent - trend.exponent) <= trend.tolerance;
  }
  return false;
}

ValidationResult RunValidation(const ValidationSet& set) {
  ValidationResult result{&set, nullptr, {}};
  for (const ValidationSource& s : set.sources) {
    SourceResult r;
    r.source = &s;
    r.variants = VariantsOf(s);
    const SourceRunner runner(s, set.dynamic.lambda);
    for (const Variant& v : r.variants)
      r.zeta_N_m3.push_back(s.zeta_route == ZetaRoute::kCalibratedOn ? CalibrateZeta(runner, s, v) : s.soil.zeta_N_m3);
    RunPoints(runner, r);
    RunTrends(runner, r);
    RunBearings(r);
    RunCurves(runner, r);
    Score(r);
    result.sources.push_back(std::move(r));
  }
  return result;
}

}  // namespace touchdown::validation

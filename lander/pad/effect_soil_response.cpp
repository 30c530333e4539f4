#include "lander/pad/effect_soil_response.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rft/input_error.h"

namespace touchdown::pad {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

EffectSoilResponse::EffectSoilResponse(const geom::AxisymmetricIntrusion& pad, const SoilResponseInputs& inputs)
    : pad_(pad), in_(inputs) {
  if (in_.terms.NeedsDensity() && !(in_.bulk_density_kg_m3 > 0.0))
    throw MakeInputError("", "bulk_density_kg_m3",
                         "the soil must state its bulk density for inertial_drag and added_mass");
  zeta_qs_ = in_.zeta_N_m3 * (in_.in_air ? 1.0 - in_.terms.gas_chi : 1.0);
  i2_coefficient_ = in_.terms.damping_c_N_s_m3 + (in_.in_air ? in_.terms.gas_c_N_s_m3 : 0.0);
}

double EffectSoilResponse::QuasiStaticForce(double d) const {
  // p = 1 is the linear law itself: computed as such, so a neutral depth_exponent changes nothing.
  if (in_.terms.HasDepthExponent())
    return pad_.PowerLawVerticalForce(d, zeta_qs_, in_.terms.depth_exponent, in_.terms.depth_reference_m);
  return pad_.VerticalForce(d, zeta_qs_);
}

double EffectSoilResponse::Force(double d, double v) const {
  double f = QuasiStaticForce(d);
  if (!(v > 0.0) || !(d > 0.0)) return f;
  const rft::EffectTerms& t = in_.terms;
  const double quadratic =
      t.inertial_lambda * in_.bulk_density_kg_m3 +
      (t.compaction_k_kg_m3 != 0.0 ? t.compaction_k_kg_m3 * std::exp(-d / t.compaction_depth_m) : 0.0);
  if (quadratic != 0.0) f += quadratic * v * v * pad_.CosinePowerIntegral(d, 3);
  if (i2_coefficient_ != 0.0) f += i2_coefficient_ * v * pad_.CosinePowerIntegral(d, 2);
  return f;
}

double EffectSoilResponse::AddedMass(double d) const {
  if (in_.terms.added_mass_ca == 0.0 || !(d > 0.0)) return 0.0;
  const double a = pad_.FootprintRadius(d);
  return in_.terms.added_mass_ca * in_.bulk_density_kg_m3 * kPi / 3 * a * a * std::min(d, a);
}

double EffectSoilResponse::AddedMassSlope(double d) const {
  if (in_.terms.added_mass_ca == 0.0 || !(d > 0.0)) return 0.0;
  const double a = pad_.FootprintRadius(d), a_slope = pad_.FootprintRadiusSlope(d);
  const double dv = d < a ? 2 * a * a_slope * d + a * a : 3 * a * a * a_slope;
  return in_.terms.added_mass_ca * in_.bulk_density_kg_m3 * kPi / 3 * dv;
}

RecordedSample RecordedAt(const RigDropResult& r, double gravity_m_s2, const rft::EffectTerms& terms,
                          double t_rec) {
  const double t = t_rec + terms.sensor_dt_s;
  RecordedSample s;
  const std::vector<DropSample>& tr = r.trace;
  if (tr.empty()) return s;
  if (t <= tr.front().t_s) {
    const double dt = t - tr.front().t_s;  // free fall before touchdown
    s.penetration_m = tr.front().penetration_m + tr.front().velocity_m_s * dt + 0.5 * gravity_m_s2 * dt * dt;
    s.force_N = 0.0;
  } else if (t >= tr.back().t_s) {
    s.penetration_m = tr.back().penetration_m;
    s.force_N = tr.back().force_N;
  } else {
    const auto it = std::upper_bound(tr.begin(), tr.end(), t, [](double x, const DropSample& a) { return x < a.t_s; });
    const DropSample& b = *it;
    const DropSample& a = *(it - 1);
    const double w = (t - a.t_s) / (b.t_s - a.t_s);
    s.penetration_m = a.penetration_m + w * (b.penetration_m - a.penetration_m);
    s.force_N = a.force_N + w * (b.force_N - a.force_N);
  }
  s.penetration_m += terms.sensor_dz_m;
  return s;
}

}  // namespace touchdown::pad

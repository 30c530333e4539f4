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
                         "the soil must state its bulk density for inertial_drag, added_mass and added_mass_plug");
  zeta_qs_ = in_.zeta_N_m3 * (in_.in_air ? 1.0 - in_.terms.gas_chi : 1.0);
  i2_coefficient_ = in_.terms.damping_c_N_s_m3 + (in_.in_air ? in_.terms.gas_c_N_s_m3 : 0.0);
  for (size_t i = 0; i < rft::RegisteredEffects().size(); ++i) {
    const rft::EffectDefinition& e = rft::RegisteredEffects()[i];
    if (!in_.terms.registered[i].active || (e.air_only && !in_.in_air)) continue;
    registered_.push_back(static_cast<int>(i));
  }
}

double EffectSoilResponse::RegisteredForce(double d, double v) const {
  if (registered_.empty() || !(d > 0.0)) return 0.0;
  const rft::RigPoint p{d, std::max(v, 0.0), pad_.CosinePowerIntegral(d, 1), pad_.CosinePowerIntegral(d, 2),
                        pad_.CosinePowerIntegral(d, 3), in_.bulk_density_kg_m3};
  double f = 0.0;
  for (const int i : registered_)
    f += rft::RegisteredEffects()[i].rig_force_N(in_.terms.registered[i].values.data(), p);
  return f;
}

double EffectSoilResponse::QuasiStaticForce(double d) const { return BaseQuasiStaticForce(d) + RegisteredForce(d, 0.0); }

double EffectSoilResponse::BaseQuasiStaticForce(double d) const {
  // p = 1 is the linear law itself: computed as such, so a neutral depth_exponent changes nothing.
  if (in_.terms.HasDepthExponent())
    return pad_.PowerLawVerticalForce(d, zeta_qs_, in_.terms.depth_exponent, in_.terms.depth_reference_m);
  return pad_.VerticalForce(d, zeta_qs_);
}

double EffectSoilResponse::Force(double d, double v) const {
  double f = BaseQuasiStaticForce(d) + RegisteredForce(d, v);
  if (!(v > 0.0) || !(d > 0.0)) return f;
  const rft::EffectTerms& t = in_.terms;
  const double quadratic =
      t.inertial_lambda * in_.bulk_density_kg_m3 +
      (t.compaction_k_kg_m3 != 0.0 ? t.compaction_k_kg_m3 * std::exp(-d / t.compaction_depth_m) : 0.0);
  if (quadratic != 0.0) f += quadratic * v * v * pad_.CosinePowerIntegral(d, 3);
  if (i2_coefficient_ != 0.0) f += i2_coefficient_ * v * pad_.CosinePowerIntegral(d, 2);
  return f;
}

// The plug (rft/entrained_mass.h) on the footprint pi a(d)^2; its rate per unit velocity is the
// slope dm_p/dd.
rft::EntrainedMass EffectSoilResponse::Plug(double d) const {
  const double a = pad_.FootprintRadius(d), a_slope = pad_.FootprintRadiusSlope(d);
  return rft::EntrainedPlug(in_.terms.added_mass_plug_cp * in_.bulk_density_kg_m3, rft::kPlugFormationDepthM, d, 1.0,
                            kPi * a * a, 2 * kPi * a * a_slope);
}

double EffectSoilResponse::AddedMass(double d) const {
  if (!(d > 0.0)) return 0.0;
  double m = 0.0;
  if (in_.terms.added_mass_ca != 0.0) {
    const double a = pad_.FootprintRadius(d);
    m = in_.terms.added_mass_ca * in_.bulk_density_kg_m3 * kPi / 3 * a * a * std::min(d, a);
  }
  if (in_.terms.added_mass_plug_cp != 0.0) m += Plug(d).mass_kg;
  return m;
}

double EffectSoilResponse::AddedMassSlope(double d) const {
  if (!(d > 0.0)) return 0.0;
  double slope = 0.0;
  if (in_.terms.added_mass_ca != 0.0) {
    const double a = pad_.FootprintRadius(d), a_slope = pad_.FootprintRadiusSlope(d);
    const double dv = d < a ? 2 * a * a_slope * d + a * a : 3 * a * a * a_slope;
    slope = in_.terms.added_mass_ca * in_.bulk_density_kg_m3 * kPi / 3 * dv;
  }
  if (in_.terms.added_mass_plug_cp != 0.0) slope += Plug(d).rate_kg_s;
  return slope;
}

RecordedSample RecordedAt(const RigDropResult& r, double gravity_m_s2, const rft::EffectTerms& terms,
                          double t_rec) {
  const double t = t_rec + terms.sensor_dt_s;
  RecordedSample s;
  const std::vector<DropSample>& tr = r.trace;
  if (tr.empty()) return s;
  if (t < tr.front().t_s) {  // right-continuous at touchdown: t = 0 reads the contact's first force
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

namespace {
// Integral of RecordedAt's (unshifted) force and penetration over [t0, t1] of the simulated time.
RecordedSample IntegralOver(const RigDropResult& r, double g, double t0, double t1) {
  RecordedSample sum;
  const std::vector<DropSample>& tr = r.trace;
  const DropSample& first = tr.front();
  // Free fall before touchdown: penetration p0 + v0 tau + g tau^2 / 2 (tau < 0), force 0.
  if (t0 < first.t_s) {
    const double a = t0 - first.t_s, b = std::min(t1, first.t_s) - first.t_s;
    auto antiderivative = [&](double tau) {
      return first.penetration_m * tau + first.velocity_m_s * tau * tau / 2 + g * tau * tau * tau / 6;
    };
    sum.penetration_m += antiderivative(b) - antiderivative(a);
  }
  // The stroke's samples linearly interpolated; from the stop on, the rest's values as steps (the
  // force falls to the weight at the stop itself: interpolating from the stop to the next grid
  // sample would smear the fall over a time that jumps as the stop crosses a grid point).
  // Only the segments that overlap [t0, t1]: from the last sample at or before t0 (a long record
  // sampled finely must not cost a pass over it per sample).
  const auto after_t0 = std::upper_bound(tr.begin(), tr.end(), t0, [](double x, const DropSample& a) { return x < a.t_s; });
  const size_t first_segment = after_t0 == tr.begin() ? 0 : static_cast<size_t>(after_t0 - tr.begin()) - 1;
  for (size_t i = first_segment; i + 1 < tr.size() && tr[i].t_s < t1; ++i) {
    const DropSample &a = tr[i], &b = tr[i + 1];
    const double lo = std::max(t0, a.t_s), hi = std::min(t1, b.t_s);
    if (!(hi > lo)) continue;
    if (a.t_s >= r.time_to_rest_s) {
      sum.force_N += (hi - lo) * b.force_N;
      sum.penetration_m += (hi - lo) * b.penetration_m;
      continue;
    }
    const double span = b.t_s - a.t_s;
    auto at = [&](double t, double fa, double fb) { return fa + (t - a.t_s) / span * (fb - fa); };
    sum.force_N += (hi - lo) * 0.5 * (at(lo, a.force_N, b.force_N) + at(hi, a.force_N, b.force_N));
    sum.penetration_m += (hi - lo) * 0.5 * (at(lo, a.penetration_m, b.penetration_m) + at(hi, a.penetration_m, b.penetration_m));
  }
  // After the trace: its last sample held.
  if (t1 > tr.back().t_s) {
    const double len = t1 - std::max(t0, tr.back().t_s);
    sum.force_N += len * tr.back().force_N;
    sum.penetration_m += len * tr.back().penetration_m;
  }
  return sum;
}
}  // namespace

RecordedSample RecordedSampleOf(const RigDropResult& r, double gravity_m_s2, const rft::EffectTerms& terms,
                                double t_rec, SensorSampling sampling, double window_s) {
  if (sampling == SensorSampling::kInstantaneous || r.trace.empty() || !(window_s > 0.0))
    return RecordedAt(r, gravity_m_s2, terms, t_rec);
  const double t = t_rec + terms.sensor_dt_s;
  RecordedSample s = IntegralOver(r, gravity_m_s2, t - 0.5 * window_s, t + 0.5 * window_s);
  s.force_N /= window_s;
  s.penetration_m = s.penetration_m / window_s + terms.sensor_dz_m;
  return s;
}

}  // namespace touchdown::pad

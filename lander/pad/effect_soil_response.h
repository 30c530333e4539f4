#pragma once
// The rig's soil response (pad::VerticalSoilResponse, lander/pad/rig_drop.h) with the effect terms
// (rft/effect_terms.h) in their axisymmetric form, and what the rig's sensors record of a drop.
//
// For straight-down motion an element of attack angle beta has v.n = v cos(beta) (n outward,
// v the downward speed); a normal stress s on it pushes up with s cos(beta) dA. With
// I_k(d) = integral of cos^k(beta) dA over the submerged leading surface
// (AxisymmetricIntrusion::CosinePowerIntegral), the terms add to the soil reaction:
//
//   inertial_drag    F += lambda rho v^2 I_3(d)
//   rate_damping     F += c v I_2(d)
//   added_mass       m_a(d) = c_a rho V(d), d(m_a v)/dt, V(d) = (pi/3) a(d)^2 min(d, a(d)): the
//                    45-degree cone of grains under the submerged footprint (radius a), grown to
//                    the penetration depth until whole; continuous from m_a(0) = 0, so touchdown
//                    never sees an infinite force
//   added_mass_plug  m_p(d) = c_p rho (pi/3) a(d)^3 min(1, d/d_f), d(m_p v)/dt: the dead zone
//                    under a flat pad, the whole cone attached over the first d_f of the stroke
//                    (rft/entrained_mass.h, EntrainedPlug), so it hands over the momentum m_p v
//                    with a finite force
//   compaction_peak  F += k_c v^2 exp(-d/d_c) I_3(d)
//   depth_exponent   zeta alpha z_ref (z/z_ref)^p instead of zeta alpha z
//   gas_cushion      only drops in air: zeta -> (1 - chi) zeta, and F += c_g v I_2(d)
//   sensor_offset    not physics: RecordedAt below
//   registered       each active effect of rft/effects/ adds its rig form
//                    (EffectDefinition::rig_force_N, from I_1..I_3), at rest too
//
// Every velocity term vanishes at rest, so the static capacity is the quasi-static force (with
// the depth law and the gas cushion applied, and the registered effects at v = 0).
#include <vector>

#include "footpad_geom/axisymmetric_intrusion.h"
#include "lander/pad/rig_drop.h"
#include "rft/effect_terms.h"
#include "rft/entrained_mass.h"

namespace touchdown::pad {

// The rig's soil response with effect terms, for one pad, soil and atmosphere.
struct SoilResponseInputs {
  double zeta_N_m3 = 0.0;           // at the drop's gravity
  double bulk_density_kg_m3 = 0.0;  // needed by inertial_drag, added_mass and added_mass_plug
  bool in_air = false;
  rft::EffectTerms terms;
};

class EffectSoilResponse final : public VerticalSoilResponse {
 public:
  // Throws InputError if an effect needs the bulk density and it is 0.
  EffectSoilResponse(const geom::AxisymmetricIntrusion& pad, const SoilResponseInputs& inputs);
  double Force(double depth_m, double speed_down_m_s) const override;
  double AddedMass(double depth_m) const override;
  double AddedMassSlope(double depth_m) const override;
  double StaticCapacity(double depth_m) const override { return QuasiStaticForce(depth_m); }
  double QuasiStaticForce(double depth_m) const;

 private:
  rft::EntrainedMass Plug(double depth_m) const;  // rate_kg_s: the slope dm_p/dd
  double BaseQuasiStaticForce(double depth_m) const;  // without the registered effects
  double RegisteredForce(double depth_m, double speed_down_m_s) const;

  const geom::AxisymmetricIntrusion& pad_;
  SoilResponseInputs in_;
  double zeta_qs_;  // with the gas cushion applied
  double i2_coefficient_;  // c (+ c_g in air)
  std::vector<int> registered_;  // the active registered effects, by index in rft::RegisteredEffects()
};

// What the rig's sensors record at recorded time t_rec [s] for a simulated drop, with the
// sensor_offset applied: the true state at t_rec + dt, penetration + dz. Before touchdown the
// pad is in free fall (penetration v0 t + g t^2 / 2 < 0, force 0); after the trace ends it stays
// at the last sample. Linear interpolation between samples.
struct RecordedSample {
  double penetration_m = 0.0;
  double force_N = 0.0;
};
RecordedSample RecordedAt(const RigDropResult& result, double gravity_m_s2, const rft::EffectTerms& terms,
                          double t_rec);

// How the rig's sensors turn the continuous force and penetration into samples.
enum class SensorSampling {
  kInstantaneous,  // each sample is the value at its time (RecordedAt)
  // Each sample is the mean over one sample period centred on its time (a load cell and its ADC
  // averaging over the period): continuous in the simulated stop time, where the force falls from
  // the stroke's to the weight, so a fit's cost is continuous in the parameters (docs/model_gap.md).
  kPeriodMean,
};

// What the rig records at t_rec with `sampling`: RecordedAt itself (kInstantaneous, or a
// sample_period_s that is not positive), or the mean over [t_rec - T/2, t_rec + T/2] (T =
// sample_period_s) of the free fall before touchdown, the stroke's samples linearly interpolated
// and, from the stop (result.time_to_rest_s) on, the rest's values as steps, integrated exactly.
RecordedSample RecordedSampleOf(const RigDropResult& result, double gravity_m_s2, const rft::EffectTerms& terms,
                                double t_rec, SensorSampling sampling, double sample_period_s);

}  // namespace touchdown::pad

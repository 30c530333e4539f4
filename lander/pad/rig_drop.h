#pragma once
// The single-footpad drop test as in the paper's rig: the pad rides on a vertical rod, so
// it moves vertically only, m a = m g - F. RFT resists only motion into the soil: there is
// no rebound. Once the pad stops, it stays as long as the soil can carry its weight
// (F(d) >= m g, the quasi-static capacity at that depth), and the reaction is then m g.
//
// With grains carried along (added mass m_a(d), see drop_tests/model/effects.h) the pad and its
// entrained grains obey d/dt((m + m_a) v) = m g - F, that is
//   (m + m_a) dv/dt = m g - F(d, v) - v^2 dm_a/dd,
// the grains' own weight being carried by the bed. The load cell between pad and soil then
// reads F_c = m (g - dv/dt) = F + m_a dv/dt + v^2 dm_a/dd, which is what the trace records.
// Energy: d/dt(KE_pad + KE_grains) = m g v - F v - v^3 m_a' / 2, so the dissipated energy is
// the work of F plus the inelastic accretion loss v^3 m_a' / 2 (grains picked up at rest);
// at the stop it equals the impact energy plus the weight's work, as without added mass.
//
// Phases, each a CVODE run whose end is found by root-finding, not by step-size luck:
//   approach   free flight from a small clearance to touchdown (root: penetration = 0);
//   stroke     penetration until the pad stops (root: velocity = 0, falling);
//   rest       the pad at rest on the soil (sinks further only if the capacity is lost).
// Time t = 0 is the touchdown; output is sampled at `sample_rate_hz` plus the exact stop.
#include <functional>
#include <string>
#include <vector>

#include "lander/integ/cvode_integrator.h"
#include "lander/pad/release.h"
#include "rft/gravity_constants.h"

namespace touchdown::pad {

// Soil reaction on the pad [N, upward] at lowest-point depth d [m] while the pad moves
// down at speed v [m/s] (v > 0). Quasi-static RFT ignores v.
using VerticalResistance = std::function<double(double depth_m, double speed_down_m_s)>;

// A vertical soil response for the rig: the soil's reaction and the grains it entrains.
class VerticalSoilResponse {
 public:
  virtual ~VerticalSoilResponse() = default;
  // Soil reaction on the pad [N, upward] at lowest-point depth d > 0 [m], moving down at v >= 0.
  virtual double Force(double depth_m, double speed_down_m_s) const = 0;
  // Mass of grains moving with the pad [kg]; must be continuous with m_a(0) = 0, so a pad
  // touching down never sees an infinite force.
  virtual double AddedMass(double /*depth_m*/) const { return 0.0; }
  // dm_a/dd [kg/m], finite.
  virtual double AddedMassSlope(double /*depth_m*/) const { return 0.0; }
  // Quasi-static capacity at rest [N]: the largest weight the soil carries at depth d.
  virtual double StaticCapacity(double depth_m) const { return Force(depth_m, 0.0); }
};

// Adapts a VerticalResistance (no added mass) to the interface: a soil given as a closed form.
class FunctionSoilResponse final : public VerticalSoilResponse {
 public:
  explicit FunctionSoilResponse(VerticalResistance f) : f_(std::move(f)) {}
  double Force(double depth_m, double speed_down_m_s) const override { return f_(depth_m, speed_down_m_s); }

 private:
  VerticalResistance f_;
};

struct RigDropOptions {
  double sample_rate_hz = 1000.0;       // the rig's 1 kHz
  double rest_duration_s = 0.1;         // time simulated (and traced) after the stop
  double max_stroke_duration_s = 10.0;  // a pad still moving after this is a failure
  double approach_clearance_m = kDefaultApproachClearance_m;  // release point above the surface
  integ::IntegratorOptions integrator{};
  // The peak force and deceleration read between samples too (VerticalPeaks); a caller that reads
  // only the trace (a fit's recorder) saves the dense output's evaluations (a fifth of a fit).
  bool peaks_between_samples = true;
};

// The rig's moving mass: the pad and whatever rides the rod with it. The pad's shape reaches the rig
// through its soil response (the intrusion integral it was built on), so the mass is all the rig's
// body needs.
struct RigBody {
  double mass_kg = 0.0;
};

// Gravity and the pad's speed at touchdown.
struct RigDropInput {
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
  double impact_speed_m_s = 0.0;  // at touchdown, downward
};

// Everything a rig drop runs on, named as the free pad's and the lander's setups are: the body, the
// terrain (for the rig a level bed seen along the rod: its vertical response), the initial state and
// the options. The response is not owned: it is polymorphic and often wraps what its caller keeps for
// many drops (a sweep's intrusion integral, synth's floor); it must outlive the run.
struct RigDropSetup {
  RigBody body;
  const VerticalSoilResponse* terrain = nullptr;
  RigDropInput initial;
  RigDropOptions options;
};

struct DropSample {
  double t_s = 0.0;            // since touchdown
  double penetration_m = 0.0;  // downward from the undisturbed surface
  double velocity_m_s = 0.0;   // downward
  double force_N = 0.0;        // soil reaction on the pad, upward
};

struct RigDropResult {
  double final_penetration_m = 0.0;
  double peak_force_N = 0.0;
  double time_to_rest_s = 0.0;           // touchdown to stop
  double max_deceleration_m_s2 = 0.0;    // max of (F - m g) / m
  double impact_energy_J = 0.0;          // kinetic energy at touchdown, 0.5 m v^2
  double gravity_work_J = 0.0;           // m g d_final, released during the stroke
  double dissipated_energy_J = 0.0;      // integral of F v dt over the stroke
  double mean_conversion_rate_W = 0.0;   // impact energy / time to rest (paper's dE/dt)
  double rest_creep_m = 0.0;             // sinkage during the rest phase
  double accretion_loss_J = 0.0;         // part of dissipated_energy_J: grains picked up (added mass)
  std::vector<DropSample> trace;
  integ::IntegratorSummary solver;
};

// Index layout of the rig's state vector, in the lander's idiom (lander::StateLayout): the pad's
// depth below the surface and its downward speed (the rig's one axis), the work done against the
// soil and, of it, the kinetic energy lost to accreted grains.
struct RigStateLayout {
  static constexpr int depth() { return 0; }
  static constexpr int velocity_down() { return 1; }
  static constexpr int work() { return 2; }
  static constexpr int accretion() { return 3; }
  static constexpr int size = 4;
};

// What one evaluation of the rig's right-hand side found at its state (the rig's Data: the
// three right-hand sides take one shape, Derivative(model, data, y, ydot), as Pinocchio's
// algorithms do; the rig's model is its RigDropSetup).
struct RigData {
  double soil_force_N = 0.0;   // the soil's resistance, upward
  double added_mass_kg = 0.0;  // the grains moving with the pad
  double accretion_N = 0.0;    // momentum given per unit time to grains picked up
};

// Pure model: the state derivative of the rig during the stroke, y as RigStateLayout (its first
// three states when the caller keeps no accretion loss).
void Derivative(const RigDropSetup& model, RigData& data, const Eigen::Ref<const Eigen::VectorXd>& y,
                Eigen::Ref<Eigen::VectorXd> ydot);
// The load-cell force F_c = m (g - dv/dt) at a stroke state [N].
double RigContactForce(const RigDropSetup& setup, double depth_m, double speed_down_m_s);

// Throws std::invalid_argument for a missing terrain, a bad body, initial state or options.
RigDropResult RunRigDrop(const RigDropSetup& setup);

}  // namespace touchdown::pad

#pragma once
// The single-footpad drop test as in the paper's rig: the pad rides on a vertical rod, so
// it moves vertically only, m a = m g - F. RFT resists only motion into the soil: there is
// no rebound. Once the pad stops, it stays as long as the soil can carry its weight
// (F(d) >= m g, the quasi-static capacity at that depth), and the reaction is then m g.
//
// Phases, each a CVODE run whose end is found by root-finding, not by step-size luck:
//   approach   free flight from a small clearance to touchdown (root: penetration = 0);
//   stroke     penetration until the pad stops (root: velocity = 0, falling);
//   rest       the pad at rest on the soil (sinks further only if the capacity is lost).
// Time t = 0 is the touchdown; output is sampled at `sample_rate_hz` plus the exact stop.
#include <functional>
#include <string>
#include <vector>

#include "lander/cvode_integrator.h"

namespace touchdown::drop {

// Soil reaction on the pad [N, upward] at lowest-point depth d [m] while the pad moves
// down at speed v [m/s] (v > 0). Quasi-static RFT ignores v.
using VerticalResistance = std::function<double(double depth_m, double speed_down_m_s)>;

struct RigDropOptions {
  double sample_rate_hz = 1000.0;       // the rig's 1 kHz
  double rest_duration_s = 0.1;         // time simulated (and traced) after the stop
  double max_stroke_duration_s = 10.0;  // a pad still moving after this is a failure
  double approach_clearance_m = 0.005;  // release point above the surface
  integ::IntegratorOptions integrator{};
};

struct RigDropInput {
  double mass_kg = 0.0;
  double gravity_m_s2 = 9.81;
  double impact_speed_m_s = 0.0;  // at touchdown, downward
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
  std::vector<DropSample> trace;
  integ::IntegratorSummary solver;
};

// Pure model: the state derivative of the rig during the stroke, y = [d, v, W].
void RigStrokeDerivative(const RigDropInput& in, const VerticalResistance& resistance,
                         const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> ydot);

RigDropResult RunRigDrop(const RigDropInput& input, const VerticalResistance& resistance,
                         const RigDropOptions& options = {});

}  // namespace touchdown::drop

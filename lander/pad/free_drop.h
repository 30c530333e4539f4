#pragma once
// A free footpad: one rigid body with 6 degrees of freedom (quaternion attitude) dropped on
// the soil with any tilt, horizontal velocity and spin - the motions the paper leaves to future
// work. The soil wrench is the 3D RFT contact (rft/contact_wrench.h) about the pad's reference
// point; gravity acts at the centre of mass. Newton-Euler about the centre of mass.
//
// Phases as in the rig drop, each ended by a CVODE root:
//   approach  free flight from `approach_clearance_m` above the surface (lowest point) to touchdown;
//   stroke    until the pad's speed (centre of mass, plus spin times the pad's size) falls below
//             `rest_speed_m_s`; the pad then rests if the soil's quasi-static capacity for
//             further downward motion carries its weight, else the stroke goes on.
// RFT forces do not vanish as the speed does (they depend on its direction only), so the pad
// reaches rest in finite time; the threshold only stops the integrator from chasing the
// direction of a vanishing velocity.
//
// A soil with added mass (PadLevelTerms::has_added_mass, rft/entrained_mass.h) adds the
// entrained cone to the vertical inertia of the centre of mass (see free_drop.cpp); its
// accretion loss counts in dissipated_energy_J, so the energy balance closes as without it.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "footpad_geom/pad_body.h"
#include "lander/integ/cvode_integrator.h"
#include "lander/pad/pad_pose.h"
#include "lander/pad/release.h"
#include "rft/gravity_constants.h"
#include "rft/soil_map.h"

namespace touchdown::pad {

struct FreeDropInput {
  double impact_speed_m_s = 0.0;      // vertical speed of the centre of mass at touchdown, downward
  double horizontal_speed_m_s = 0.0;  // along +x of W
  double tilt_rad = 0.0;              // at release, about tilt_axis
  TiltAxis tilt_axis = TiltAxis::kX;
  Eigen::Vector3d omega_W = Eigen::Vector3d::Zero();  // angular velocity at release [rad/s]
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
};

struct FreeDropOptions {
  double sample_rate_hz = 1000.0;
  double approach_clearance_m = kDefaultApproachClearance_m;
  double rest_speed_m_s = 1e-3;
  double max_duration_s = 5.0;
  // rtol 1e-6: the final depth to 2e-5 relative and the tilt to 2.4e-4 deg of a run at rtol 1e-10 on
  // the 5k-triangle bench drops (tilted, sliding, spinning; docs/lander_dynamics.md, "Free
  // single-pad drops"), 5 and 40 times inside the
  // accuracy the studies ask of a landing (1e-4 relative in depth, 0.01 deg); at 1e-5 a sliding drop is
  // 2.5e-4 off. The energy balance then closes to 2e-5 there, 1.2e-4 at most over the shipped pads'
  // tilts and speeds (it measures the integration's global error in energy units: 4e-7 at rtol
  // 1e-8, 3e-6 at 1e-7; rtol 1e-8 for a balance to 1e-6). The absolute tolerances are rtol times each
  // state's scale (free_drop.cpp, WithScaledTolerances), so `atol` is not used; component_atol,
  // when given (14 states: p_WC, q_WB, v_WC, w_B, work), replaces them.
  // A Jacobian only when Newton fails to converge, not every 51 steps: on the 5k-triangle bench
  // drops 12-18 % fewer right-hand sides, same results to 1e-7.
  // The Newton iteration's Jacobian from the pad's structure (FreePadDynamics::Jacobian: 10 soil
  // evaluations over a plane, where CVODE's difference quotients take 14); false: CVODE's.
  bool structured_jacobian = true;
  integ::IntegratorOptions integrator{.rtol = 1e-6,
                                      .atol = 1e-11,
                                      .max_num_steps = 20000,
                                      .stiff = true,
                                      .max_steps_between_jacobians = 1000,
                                      .component_atol = {}};
};

struct FreeDropSample {
  double t_s = 0.0;              // since touchdown
  double penetration_m = 0.0;    // depth of the lowest surface point
  double velocity_m_s = 0.0;     // centre of mass, downward
  double force_N = 0.0;          // vertical soil force on the pad, upward (with the soil's added mass: the
                                 // force from below, soil and entrained grains, m (a_z + g), as the rig's
                                 // load cell records it)
  double force_x_N = 0.0;        // horizontal soil force along x
  double horizontal_m = 0.0;     // centre-of-mass travel along x since touchdown
  double tilt_deg = 0.0;         // pad z axis from the vertical
  // The full pose, so that outputs can draw the pad (ParaView) and anything can be animated: the
  // pad frame's origin (its reference point) and attitude (unit quaternion w, x, y, z, B to W, as
  // integrated), the reference point's velocity and the angular velocity, both in W.
  Eigen::Vector3d p_WB = Eigen::Vector3d::Zero();
  Eigen::Vector4d q_WB{1.0, 0.0, 0.0, 0.0};
  Eigen::Vector3d v_WB_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_W = Eigen::Vector3d::Zero();
  double shear_displacement_m = 0.0;  // Janosi's j (FreePadDynamics::has_shear_state), else 0
};

struct FreeDropResult {
  double final_penetration_m = 0.0;
  double peak_force_N = 0.0;  // vertical
  double time_to_rest_s = 0.0;
  double max_deceleration_m_s2 = 0.0;  // of the centre of mass, vertical
  double impact_energy_J = 0.0;        // kinetic energy (translation + rotation) at touchdown
  double gravity_work_J = 0.0;         // m g times the centre of mass's drop from touchdown to rest
  double dissipated_energy_J = 0.0;    // work done against the soil wrench
  double touchdown_tilt_deg = 0.0;
  double final_tilt_deg = 0.0;
  double horizontal_travel_m = 0.0;    // centre of mass, in the horizontal plane, touchdown to rest
  // Only on a terrain with Janosi's shear (FreePadDynamics::has_shear_state): j at rest [m] and the
  // lift-offs that reset it.
  double final_shear_displacement_m = 0.0;
  int lift_offs = 0;
  double final_kinetic_energy_J = 0.0;  // at the rest event (below the threshold)
  std::vector<FreeDropSample> trace;
  // jacobian_rhs_evaluations: with the structured Jacobian, the right-hand sides it spent
  // (FreePadDynamics::JacobianContacts per Jacobian), which CVODE does not count.
  integ::IntegratorSummary solver;
};

// Everything a free drop runs on, named as the rig's and the lander's setups are. The body is not
// owned: a meshed pad's is megabytes and one pad's drops (a sweep's, a fit's) share it; it must
// outlive the run. The pad lands on `terrain` (its surface and the soil under the pad:
// rft/soil_map.h); a uniform bed is rft::UniformTerrain.
struct FreeDropSetup {
  const geom::PadBody* body = nullptr;
  rft::Terrain terrain;
  FreeDropInput initial;
  FreeDropOptions options;
};

FreeDropResult RunFreeDrop(const FreeDropSetup& setup);

}  // namespace touchdown::pad

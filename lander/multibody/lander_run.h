#pragma once
// What a lander run takes and gives: its setup (initial state and options among it), the sampled
// trace, the events and the summary. Types only (the simulation is lander_simulation.h; the hybrid system's
// modes and events are lander_hybrid.h).
#include <Eigen/Core>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lander/integ/cvode_integrator.h"
#include "lander/multibody/lander_dynamics.h"
#include "rft/enum_names.h"

namespace touchdown::lander {

struct LanderInitialState {
  Eigen::Vector3d p_WB = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
  Eigen::Vector3d v_WB_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_WB_W = Eigen::Vector3d::Zero();
  std::array<Eigen::Matrix3d, kNumLegs> R_WP{Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity(),
                                             Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity()};
  std::array<double, kNumLegs> stroke_m{};  // absorber legs only
};


struct LanderRunOptions {
  double duration_s = 1.0;              // simulated time from release
  double sample_rate_hz = 1000.0;       // trace rate (plus every event)
  double capture_speed_m_s = 0.02;      // max horizontal joint speed for the soil to hold a pad
  // The soil's low-speed ramp (LanderModel::soil_ramp_speed_m_s); a scenario's setup copies it
  // into the model. Below capture_speed_m_s.
  double soil_ramp_speed_m_s = kDefaultSoilRampSpeed_m_s;
  SoilRamp soil_ramp = SoilRamp::kElement;
  bool stop_at_rest = true;             // rest is static: the remaining time is not integrated
  // With stop_at_rest: the lander is also at rest once every ball joint has moved slower than the
  // soil's ramp speed at every sample for a quarter of its time scale sqrt(L / g) (L: the largest
  // joint distance from the body's centre of mass). Why: below the ramp speed the soil's stress is a
  // regularisation (LanderModel::soil_ramp_speed_m_s), so a lander whose free pads carry their loads
  // while creeping there would stand in the rate-independent soil it models. Without this such
  // landings ran on to their end unsettled, and the reference model's Newton iteration could stall
  // on the creep (docs/lander_dynamics.md, "Rest at creep"). The dwell excludes a passage through
  // low speed at a turning point of a rocking lander. false: rest only by holds, as before 2026-12-06.
  bool rest_at_creep = true;
  int max_events = 20000;               // guard against Zeno behaviour
  // BDF with the lander's structured Jacobian (lander_jacobian.h), rtol 1e-7: a pad rocking on its
  // ball joint in the soil is stiff, so Adams' steps are limited by stability (2,000-12,000 per
  // asymmetric landing at rtol 1e-9). At 1e-7 the benchmark landings (cases A, B, C, attitude,
  // 10 deg slope) agree with a reference at rtol 1e-11 to 4.6e-5 in every pad's depth and 1e-5 deg
  // in roll and pitch; the asymmetric ones run 2.9-4.4 times faster than with Adams at 1e-9, case A
  // 1.5 times slower (docs/lander_dynamics.md, "Speed of asymmetric landings").
  // A Jacobian at most every 200 steps (and at every convergence failure) instead of CVODE's 51:
  // 10-28 % fewer Jacobians, 3-13 % less CPU on those landings.
  // The Jacobian differentiates each pad's contact with respect to its joint's position and
  // velocity and its spin (nine contacts per pad in the soil, seven over a plane: lander_jacobian.h);
  // true adds its attitude (twelve).
  bool jacobian_attitude_sensitivity = false;
  // Newton's convergence coefficient 0.03 instead of CVODE's 0.1: a free pad whose spin the soil
  // holds at 1-2 mrad/s (its elements about the soil ramp's speed, a time constant of about a
  // microsecond) with Newton stopped at 0.1 of the tolerance on a Jacobian up to 200 steps old
  // fell into a period-4 cycle at a fixed 1.5-2.6 us step, no test failing, for up to 0.6 s
  // (235,000-267,000 steps on three landings of the lunar study); at 0.03 those landings take
  // 1,450-2,000 steps, at 0.01 as few but the benchmark landings 18-47 % more contact evaluations
  // (docs/lander_dynamics.md, "Newton's tolerance and the fixed-step cycle").
  integ::IntegratorOptions integrator{.rtol = 1e-7,
                                      .atol = 1e-11,
                                      .max_step = 0.0,
                                      .max_num_steps = 500000,
                                      .stiff = true,
                                      .max_steps_between_jacobians = 200,
                                      .nonlinear_convergence_coefficient = 0.03,
                                      .component_atol = {}};
  // Absolute tolerances rtol times each state's scale (lander_simulation.cpp, ScaledTolerances),
  // unless integrator.component_atol is given; false: the scalar integrator.atol for every state
  // (a scenario that sets `atol` asks for that).
  bool scale_tolerances = true;
  // The pads' spins' absolute tolerance times this (with scale_tolerances). A pad's spin in the
  // soil is a stiff, nearly quasi-static state that the error test resolves at the scale of a rim
  // moving at the landing's speed; the attitude it integrates into is what the contact sees. 1 (the
  // default, and the reference model's): as every other state. The studies' fast model takes 10:
  // 35 % fewer steps and 18 % less CPU on the lunar study's landings; 30 takes 8 % fewer steps on
  // its first 1,000 landings but no less CPU (docs/lander_dynamics.md, "The pads' spin tolerance").
  double pad_spin_tolerance_factor = 1.0;
  // A ball joint's stop (ConeLimit) as a mode of the hybrid run: a root where the pad reaches the
  // cone and one where it has left it (a band inside the rim, lander_hybrid.cpp's StopHysteresis),
  // the stop's torque on between the two, and a restart at each. The stop's damping acts the instant
  // the pad reaches the rim, a jump in the right-hand side that, found by the angle inside a step,
  // cost CVODE 30-40 steps of failed Newton iterations at each impact on a stop. false: the torque
  // wherever the pad is beyond the cone, switched on inside the steps (the same model, kept to
  // measure against; docs/lander_dynamics.md, "The joints' stops as modes").
  bool joint_stops_as_modes = true;
  // The root functions' slide checks of a held pad from its soil integrals at the pose it was held in
  // at the last event (HeldPadCapacity): its capacity in the load's direction without clipping its
  // elements again, the same force bit for bit at that pose. false: the contact evaluated at the
  // pose of every root-function call, which differs from the held pose by the integration's drift
  // only (kept to measure against; docs/lander_dynamics.md, "The held pads' capacity from their
  // integrals").
  bool held_capacity_from_integrals = true;
};

// Everything a landing runs on, named as the rig's and the free pad's setups are: the model (body,
// legs, pads, gravity), the terrain with its soils' contact models, the initial state and the options.
// Held by value: one is built per landing and kept with its result (outputs draw from it).
struct LanderSetup {
  LanderModel model;
  rft::Terrain terrain;
  LanderInitialState initial;
  LanderRunOptions options;
};

struct LanderSample {
  double t_s = 0.0;
  Eigen::Vector3d p_WB, v_WB_W, w_WB_W;
  Attitude attitude;
  Eigen::Vector3d a_WB_W;                        // body CoM acceleration
  std::array<double, kNumLegs> pad_depth_m{};    // lowest vertex below the free surface
  std::array<Eigen::Vector3d, kNumLegs> pad_force_W;  // soil on pad
  std::array<double, kNumLegs> stroke_m{};
  std::array<double, kNumLegs> leg_force_N{};
  std::array<int, kNumLegs> pad_held{};
  double kinetic_J = 0.0, potential_J = 0.0, dissipated_J = 0.0;
  // The poses, so that outputs can draw the lander (ParaView) and anything can be animated: unit
  // quaternions (w, x, y, z) of the body (B to W) and of each pad (P to W) as integrated, each
  // pad's joint centre, its velocity and the pad's angular velocity (W).
  Eigen::Vector4d q_WB{1.0, 0.0, 0.0, 0.0};
  std::array<Eigen::Vector4d, kNumLegs> q_WP;
  std::array<Eigen::Vector3d, kNumLegs> p_WJ, v_WJ_W, w_WP_W;
  std::array<double, kNumLegs> shear_displacement_m{};  // Janosi's j (0 without the state)
};

enum class LanderEventKind {
  kTouchdown,       // a pad reaches the surface
  kCapture,         // a pad is held by the soil
  kReleaseLiftoff,  // a held pad is released: the soil would have to pull it down
  kReleaseSink,     // ... the load exceeds what the soil carries
  kReleaseSlide,    // ... the sideways load exceeds the soil's friction
  kCrush,           // a crushable absorber starts to crush
  kLock,            // it stops crushing
  kBottom,          // it reaches the end of its stroke
  kStopReached,     // a pad reaches its ball joint's stop (ConeLimit; with joint_stops_as_modes)
  kStopLeft,        // ... and leaves it
  kTipOver,         // the lander tips over
  kRest,            // the lander is static: every pad held, or the holds fix the body (HoldsFixTheStance),
                    // or its joints crept below the soil's ramp speed (LanderRunOptions::rest_at_creep)
};
// The events' names in outputs (events.csv).
inline constexpr std::array<EnumName<LanderEventKind>, 12> kLanderEventNames{{
    {LanderEventKind::kTouchdown, "touchdown"},
    {LanderEventKind::kCapture, "capture"},
    {LanderEventKind::kReleaseLiftoff, "release_liftoff"},
    {LanderEventKind::kReleaseSink, "release_sink"},
    {LanderEventKind::kReleaseSlide, "release_slide"},
    {LanderEventKind::kCrush, "crush"},
    {LanderEventKind::kLock, "lock"},
    {LanderEventKind::kBottom, "bottom"},
    {LanderEventKind::kStopReached, "stop_reached"},
    {LanderEventKind::kStopLeft, "stop_left"},
    {LanderEventKind::kTipOver, "tip_over"},
    {LanderEventKind::kRest, "rest"},
}};
const char* LanderEventName(LanderEventKind kind);

struct LanderEvent {
  double t_s = 0.0;
  LanderEventKind kind = LanderEventKind::kTouchdown;
  int leg = -1;  // 0-based, -1 for the whole lander
};

struct LanderRunResult {
  std::vector<LanderSample> trace;
  std::vector<LanderEvent> events;
  std::array<double, kNumLegs> final_penetration_m{};
  std::array<double, kNumLegs> peak_pad_force_N{};
  std::array<std::optional<double>, kNumLegs> touchdown_time_s;
  Attitude final_attitude;
  double max_tilt_rad = 0.0;
  // Largest swing of any pad on its ball joint (JointSwingAngle: its axis from the body's z axis), at
  // the samples and events: past pi/2 a pad has turned beyond edge-on, which only a joint without a
  // range (no cone_limit) allows.
  double max_joint_swing_rad = 0.0;
  bool tipped_over = false;
  // The least StabilityMargin over the run (the samples and events, the tip-over event's state
  // included) [m]: the centre of mass's horizontal distance inside the support polygon of the
  // joint centres. It reaches 0 exactly where the tip-over event fires, so it is <= 0 when the
  // lander tipped over and > 0 when it stayed up: the limit state of a rare-event study.
  double min_stability_margin_m = std::numeric_limits<double>::infinity();
  // For a lander that tipped over, the support edge it went over (CriticalSupportEdge at the
  // tip-over event): from joint tip_over_edge to the next one clockwise (0-based; -1 when it did not
  // tip), and the azimuth of that edge's outward horizontal normal, the direction it fell [rad].
  int tip_over_edge = -1;
  double tip_over_azimuth_rad = std::numeric_limits<double>::quiet_NaN();
  std::optional<double> rest_time_s;          // since release
  std::optional<double> first_touchdown_s;
  double max_body_deceleration_m_s2 = 0.0;    // max upward body CoM acceleration
  double initial_energy_J = 0.0;              // kinetic + potential at release
  double final_kinetic_J = 0.0, final_potential_J = 0.0, dissipated_J = 0.0;
  double capture_loss_J = 0.0;                // part of dissipated_J removed at captures
  double max_held_drift_m = 0.0;              // largest motion of a held pad's joint centre
  double end_time_s = 0.0;
  Eigen::VectorXd final_state;
  integ::IntegratorSummary solver;
  // Pad contacts (rft::ComputeContactWrench calls, each a pass over a pad's triangles) evaluated
  // for Jacobians, right-hand sides and root functions (held pads' capacities included): where the
  // CPU goes.
  long jacobian_pad_contacts = 0;
  long rhs_pad_contacts = 0;
  long root_pad_contacts = 0;
};

}  // namespace touchdown::lander

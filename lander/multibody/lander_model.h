#pragma once
// Model data of a four-legged lander (constant during a run; house style: Pinocchio's Model).
//
// Frames, z up everywhere:
//   W  world; gravity is (0, 0, -g).
//   B  main body, origin at the main body's centre of mass (the legs' and pads' masses are
//      separate bodies), x forward, y left. Pads are numbered clockwise seen from above,
//      pad 1 front-left (the paper's numbering: pad 3 is diagonal to pad 1).
//   P_i  pad i, origin at the ball-joint centre (the pad's reference point, rft contract).
//
// Leg i runs from its hip h_i to the ball-joint centre; an optional axial shock absorber lets
// the joint slide along the leg axis e_i = (joint - hip) / |joint - hip| by a stroke s_i
// (compression positive): p_J = p_B + R_WB (joint_B - s_i e_i).
#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "footpad_geom/pad_body.h"
#include "rft/gravity_constants.h"
#include "rft/soil_map.h"

namespace touchdown::lander {

inline constexpr int kNumLegs = 4;

// Axial shock absorber. kSpringDamper: F = k s + c ds/dt (two-sided, about the free length).
// kCrushable: a crushable core (honeycomb) that strokes only in compression, at the constant
// force crush_force_N, and is rigid otherwise; at stroke_limit_m it bottoms out (rigid).
struct ShockAbsorber {
  enum class Kind { kSpringDamper, kCrushable };
  Kind kind = Kind::kSpringDamper;
  double stiffness_N_m = 0.0;
  double damping_N_s_m = 0.0;
  double crush_force_N = 0.0;
  double stroke_limit_m = 0.0;  // crushable: available stroke [m]
};

// Optional cone limit of the ball joint: the pad axis z_P may tilt from the leg's body axis
// z_B by at most half_angle. The stop is compliant (a stiff rotational spring-damper beyond
// the cone), which is how a rubber or elastomer stop behaves.
struct ConeLimit {
  double half_angle_rad = 0.0;
  double stiffness_N_m_rad = 0.0;
  double damping_N_m_s_rad = 0.0;
};

struct Leg {
  Eigen::Vector3d hip_B = Eigen::Vector3d::Zero();    // leg root on the body [m]
  Eigen::Vector3d joint_B = Eigen::Vector3d::Zero();  // ball-joint centre at zero stroke [m]
  std::optional<ShockAbsorber> absorber;
  std::optional<ConeLimit> cone;
  std::shared_ptr<const geom::PadBody> pad;           // pad frame origin = joint centre
  Eigen::Vector3d axis_B() const { return (joint_B - hip_B).normalized(); }
};

// Below this speed a free pad's soil stress is scaled by speed / soil_ramp_speed_m_s. Why:
// quasi-static RFT depends on the direction of motion only, so at v -> 0 the force keeps its full
// size while its direction follows rounding noise (a pad whose capture was undone sits at
// |v| ~ 1e-11 with a horizontal part that turns its support into sideways drag and back: a
// discontinuity no integrator steps through). The ramp makes the force continuous through v = 0;
// a pad that slows below it is offered a capture (lander_simulation.h), so no creep results.
inline constexpr double kDefaultSoilRampSpeed_m_s = 1e-4;

// Where the ramp acts. kElement (the default): on each element's stress, by that element's own
// speed (rft::PadKinematics::element_ramp_speed_m_s), so the wrench is continuous in the pad's
// spin as well as in its translation. kPad: on the pad's whole wrench, by the pad's speed (joint
// centre plus spin times radius): a pad creeping just above that ramp while it turns slowly feels
// a torque whose direction follows its spin, a Coulomb torque the integrator resolved at
// microsecond steps (1.1 million steps on one landing; docs/lander_dynamics.md, "The soil's
// low-speed ramp").
enum class SoilRamp { kPad, kElement };

struct LanderModel {
  double body_mass_kg = 0.0;
  Eigen::Matrix3d body_inertia_B = Eigen::Matrix3d::Zero();  // about the body CoM [kg m^2]
  std::array<Leg, kNumLegs> legs;
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
  double soil_ramp_speed_m_s = kDefaultSoilRampSpeed_m_s;  // see kDefaultSoilRampSpeed_m_s
  SoilRamp soil_ramp = SoilRamp::kElement;                  // see SoilRamp

  double TotalMass() const {
    double m = body_mass_kg;
    for (const Leg& leg : legs) m += leg.pad->mass_kg;
    return m;
  }
};

// Checks the model (throws std::invalid_argument on inconsistent data; the loader reports
// user errors first).
void FinishModel(LanderModel& model);

}  // namespace touchdown::lander

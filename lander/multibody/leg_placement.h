#pragma once
// Where a lander's legs sit on its body, from the pad it stands on: the body's mass and CoM follow
// from the whole lander's mass and CoG height once the four pads' share is taken off, and the
// ball joints and hips are placed on circles about the body axis, pads clockwise seen from above
// (lander_model.h: pad 1 front-left).
#include <Eigen/Core>
#include <array>
#include <string>
#include <variant>

#include "footpad_geom/pad_body.h"
#include "lander/multibody/lander_model.h"

namespace touchdown::lander {

// The legs' geometry as a lander is described: radii from the body axis and the hips' height,
// both heights above the pad bottoms when the lander stands level.
struct LegLayout {
  double joint_radius_m = 0.0;
  double hip_radius_m = 0.0;
  double hip_height_m = 0.0;
};

struct LegPlacement {
  double body_mass_kg = 0.0;  // total minus the four pads
  std::array<Eigen::Vector3d, kNumLegs> joint_B{};  // ball-joint centres from the body CoM [m]
  std::array<Eigen::Vector3d, kNumLegs> hip_B{};    // leg roots from the body CoM [m]
};

// Why the legs cannot be placed, naming the input that does not fit; the caller words it for its
// own file (a lander file's key, or the pad a study swaps in).
struct LegPlacementError {
  enum class Field {
    kTotalMass,  // the four pads weigh as much as the lander or more
    kCogHeight,  // the lander's CoG height puts the body's CoM at or below the joints
    kHipHeight,  // the hips at or below the joints
  };
  Field field = Field::kTotalMass;
  std::string reason;
};

// The stiffest ball-joint stop (ConeLimit) a landing can carry: a pad of inertia I about its joint
// on a stop of stiffness k rings at sqrt(k / I) each time it meets the rim, and the integrator takes
// several steps every period. A 0.5 s sliding landing of the paper's lander (pad 3.4e-5 kg m^2 about
// its joint, 5 deg cone) took 9 s at 200 N m/rad (386 Hz), 40 s at 1e6 (27 kHz) and 245 s at 1e8
// (274 kHz): past kMaxStopRingingHz a stop is refused. 20 kHz is 50 times the shipped stop's
// ringing, and a metal rim's (a few kHz) is below it.
inline constexpr double kMaxStopRingingHz = 20000.0;
// k at which `pad` rings at kMaxStopRingingHz about its joint (the pad frame's origin), tilting
// about its least inertia among the horizontal axes [N m/rad].
double MaxStopStiffness(const geom::PadBody& pad);

// Places the legs of a lander of `total_mass_kg` whose CoG stands `cog_height_m` above the pad
// bottoms on four copies of `pad`.
std::variant<LegPlacement, LegPlacementError> PlaceLegs(const geom::PadBody& pad, double total_mass_kg,
                                                        double cog_height_m, const LegLayout& layout);

}  // namespace touchdown::lander

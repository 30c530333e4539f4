#pragma once
// Tip-over criteria of a lander standing on (or landing on) a uniform slope: the static criterion
// (the centre of mass over the support polygon's downhill edge) and the energy criterion (the
// kinetic energy at touchdown against the potential barrier to tip over an edge). Pure functions
// of the model, the slope's geometry and a state; docs/tip_over_criteria.md derives them.
//
// Support points are the ball-joint centres, as in the simulation's tip-over event
// (StabilityMargin): a ball joint carries no moment, so the soil's resultant on a pad (plus the
// pad's weight) passes through its joint centre, and the body tips about the line through two
// joint centres while the pads stay in the soil. The pads' rims would be the pivots only for pads
// fixed to their legs (or pressed against a cone stop); the sinkage enters through the state at
// rest (an even sinkage moves every point down alike; an uneven one tilts the lander on the slope).
#include <Eigen/Core>
#include <array>

#include "lander/multibody/lander_dynamics.h"
#include "lander/multibody/lander_model.h"
#include "rft/ground.h"

namespace touchdown::lander {

// A uniform slope: its angle and the horizontal direction it descends towards (unit, world).
struct SlopeGeometry {
  double angle_rad = 0.0;
  Eigen::Vector3d downhill_W = Eigen::Vector3d::UnitX();
};
// The slope of a plane; a level plane descends along `downhill_if_level_W`.
SlopeGeometry SlopeOf(const rft::PlaneGround& plane, const Eigen::Vector3d& downhill_if_level_W = Eigen::Vector3d::UnitX());

// The state turned rigidly by R_W about `pivot_W` (positions, attitudes and velocities; strokes and
// the dissipated work unchanged): the same standing configuration on a tilted world.
Eigen::VectorXd RotateLanderState(const StateLayout& layout, const Eigen::Ref<const Eigen::VectorXd>& y,
                                  const Eigen::Matrix3d& R_W, const Eigen::Vector3d& pivot_W);

// Tipping about the support edge from joint centre `from_leg` to the next one clockwise, for the
// whole lander turning rigidly about that edge (k: the unit axis that tips it outward).
struct EdgeTipping {
  int from_leg = 0, to_leg = 1;
  Eigen::Vector3d tip_axis_W = Eigen::Vector3d::Zero();  // k, the rotation that carries the CoM outward
  double inside_m = 0.0;         // horizontal distance of the CoM inside the edge's vertical plane
  double height_m = 0.0;         // CoM above the edge, perpendicular to it in the plane normal to the edge
  double tip_angle_rad = 0.0;    // rotation about k until the CoM is above the edge: atan2(inside, height)
  double barrier_J = 0.0;        // M g times the rise of the CoM during that rotation (0 once outside)
  double inertia_kg_m2 = 0.0;    // the whole lander about the edge, rigid
  double angular_momentum_N_m_s = 0.0;  // about the edge, along k
  // Kinetic energy of the rigid rotation about the edge after a perfectly plastic capture of the
  // edge (omega = H / I, E = H^2 / (2 I)); 0 when the lander turns inward.
  double EdgeKineticEnergy() const {
    return angular_momentum_N_m_s > 0.0 ? 0.5 * angular_momentum_N_m_s * angular_momentum_N_m_s / inertia_kg_m2 : 0.0;
  }
};
// The four edges of the support polygon (edge i: joint i to joint i + 1 clockwise).
std::array<EdgeTipping, kNumLegs> EdgeTippings(const LanderModel& model, const StateLayout& layout,
                                               const Eigen::Ref<const Eigen::VectorXd>& y);

// The static criterion for a lander at rest on a uniform slope.
struct StaticTipOver {
  double margin_m = 0.0;             // StabilityMargin of the state at rest (> 0: stands)
  double extra_tilt_rad = 0.0;       // further steepening of the slope, lander and ground together, to tip
  double critical_slope_rad = 0.0;   // slope.angle_rad + extra_tilt_rad
  int edge_from_leg = -1;            // the edge the CoM crosses there (from this joint, clockwise)
};
// Steepens the slope (turns the standing configuration about the slope's horizontal contour line)
// until the CoM, seen along gravity, leaves the polygon of the joint centres. y_rest is the lander
// at rest on that slope (its sinkage and its tilt relative to the slope are in it).
StaticTipOver StaticTipOverOnSlope(const LanderModel& model, const StateLayout& layout,
                                   const Eigen::Ref<const Eigen::VectorXd>& y_rest, const SlopeGeometry& slope);

// The energy criterion at a touchdown state (docs/tip_over_criteria.md):
//   necessary  kinetic_J + released_potential_J > barrier_J: to tip, the lander must lift its CoM
//              over the edge, and between touchdown and that moment the soil only takes energy out
//              (a lower bound on the tipping speed, for a crossing about the edge where `standing`
//              has it; pads that sink deeper than that lower the crossing, and the bound with it);
//   estimate   edge_kinetic_J > barrier_J: the edge's pads stop at once (a plastic capture, the
//              angular momentum about the edge kept, omega = H / I) and the lander then turns
//              rigidly about the edge with nothing more dissipated.
struct EnergyTipOver {
  double barrier_J = 0.0;             // of `standing` about the edge
  double kinetic_J = 0.0;             // the whole lander's at touchdown
  double released_potential_J = 0.0;  // potential energy from touchdown down to `standing` (the sinking)
  double edge_kinetic_J = 0.0;        // the part of kinetic_J that drives the rotation about the edge
  bool NecessaryConditionMet() const { return kinetic_J + released_potential_J > barrier_J; }
  bool EstimateTips() const { return edge_kinetic_J > barrier_J; }
};
// `standing`: the lander at rest where the landing leaves it (the edge and the sinkage);
// `touchdown`: the state as the pads touch down.
EnergyTipOver EnergyTipOverAtEdge(const LanderModel& model, const StateLayout& layout,
                                  const Eigen::Ref<const Eigen::VectorXd>& standing,
                                  const Eigen::Ref<const Eigen::VectorXd>& touchdown, int edge_from_leg);

}  // namespace touchdown::lander

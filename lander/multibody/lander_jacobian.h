#pragma once
// The Jacobian d(ydot)/dy of the lander's equations of motion, for BDF's Newton iteration.
//
// Why the lander needs its own: a pad rocking on its ball joint in the soil is stiff (a light
// pad against a soil moment that changes fast with its attitude and spin), so a non-stiff method
// takes thousands of tiny steps, and CVODE's difference-quotient Jacobian costs one right-hand
// side per state (42 for the paper's lander). Here the structure does most of the work:
//   - the position rows (dp/dt = v, the quaternion rates, ds/dt) are formed exactly;
//   - the speed rows' columns of a pad's own states (its attitude, its spin, its stroke) are
//     difference quotients in which only that pad's contact is evaluated again, the other pads'
//     contact wrenches being unchanged (a pad's contact depends on its own state and the body's);
//   - the body's states reach a pad's contact only through its joint's position and velocity:
//     six difference quotients of each pad's contact give d(wrench)/d(joint motion), and the
//     body's columns are then evaluations with the wrenches predicted to first order (no contact
//     evaluated again).
// A Jacobian costs 13 contact evaluations per pad in the soil, about 13 right-hand sides, where
// CVODE's difference quotients cost 42.
// A Jacobian only steers the Newton iteration; the error test decides the accuracy.
#include <Eigen/Core>
#include <array>

#include "lander/multibody/lander_dynamics.h"

namespace touchdown::lander {

// Scratch of LanderJacobian (allocated once per run, not per call).
struct LanderJacobianData {
  LanderEvaluation base, probe;
  Eigen::VectorXd y, ydot, f0;
  std::array<rft::ContactWrench, kNumLegs> predicted;
  long contact_evaluations = 0;  // pad contacts evaluated so far (right-hand sides count four)
};

// J (zeroed on entry) at state y; `scale` holds each state's typical size (the perturbation of
// column j is sqrt(eps) max(|y_j|, scale_j)).
void LanderJacobian(const LanderModel& model, const StateLayout& layout, const rft::Terrain& terrain,
                    const LanderModes& modes, const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::VectorXd& scale,
                    LanderData* data, LanderJacobianData* work, Eigen::Ref<Eigen::MatrixXd> J);

}  // namespace touchdown::lander

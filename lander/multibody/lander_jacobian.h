#pragma once
// The Jacobian d(ydot)/dy of the lander's equations of motion, for BDF's Newton iteration.
//
// Why the lander needs its own: a pad rocking on its ball joint in the soil is stiff (a light
// pad against a soil moment that changes fast with its attitude and spin), so a non-stiff method
// takes thousands of tiny steps, and CVODE's difference-quotient Jacobian costs one right-hand
// side per state (42 for the paper's lander). Here the structure does most of the work:
//   - the position rows (dp/dt = v, the quaternion rates, ds/dt) are formed exactly;
//   - a pad's contact depends on the state only through the pad's motion: its joint's position
//     and velocity, its attitude and its spin. Twelve one-sided difference quotients of each pad's
//     own contact give d(wrench)/d(that motion) (PadSensitivity), and every column of the speed
//     rows is then an evaluation of the equations of motion with the wrenches predicted to first
//     order from how the column moves each pad (chain rule): no contact is evaluated again
//     (except for Janosi's shear displacement j, which reaches only its own pad's contact).
// A Jacobian costs 12 contact evaluations per pad in the soil (about 12 right-hand sides), where
// CVODE's difference quotients cost 42 (and the earlier structured Jacobian, which evaluated a
// pad's contact again for each of its own seven attitude and spin columns, 13). Over a plane
// (rft::PlaneGround) 10: the contact sees the joint's position only through its depth, so one
// quotient along z gives the x and y columns too (times the plane's slopes; exact).
// SimulateLander leaves out the attitude derivatives (LanderRunOptions's
// jacobian_attitude_sensitivity): 9 contacts per pad, 7 over a plane. Why that is safe: the stiff
// part of a pad in the soil is its velocity and spin (RFT resists motion at a force nearly
// independent of speed, so the wrench's derivative with respect to the velocity is large at low
// speed: estimated, a time constant of order 1e-6 s for the spin of the paper's pad at 0.1 m/s); its
// moment against a change of attitude (a rotational stiffness of order F r^2 / depth, a period of
// milliseconds) is not stiff at the 10-100 us steps taken (measured: steps and Newton failures
// within a few per cent). Leaving out the position derivatives too (the soil's vertical stiffness)
// was tried: fewer contacts, but case A's energy balance error grew from 15 to 99 uJ (bench_lander;
// the Newton iteration stops at its tolerance, and a worse Jacobian leaves more of it there).
// A Jacobian only steers the Newton iteration; the error test decides the accuracy.
#include <Eigen/Core>
#include <array>

#include "lander/multibody/lander_dynamics.h"

namespace touchdown::lander {

// A pad's motion as its contact sees it: joint position, attitude (small rotation, world frame),
// joint velocity, spin; and d(force, moment about the joint)/d(that motion).
using PadMotion = Eigen::Matrix<double, 12, 1>;
using ContactSensitivity = Eigen::Matrix<double, 6, 12>;

// Scratch of LanderJacobian (allocated once per run, not per call).
struct LanderJacobianData {
  LanderEvaluation base, probe;
  Eigen::VectorXd y, ydot, f0;
  std::array<rft::ContactWrench, kNumLegs> predicted;
  std::array<ContactSensitivity, kNumLegs> sensitivity;
  // The wrench's derivatives with respect to the pads' attitudes too (twelve contacts per pad in the
  // soil instead of nine); false takes them as zero (SimulateLander's default, see above).
  bool attitude_sensitivity = true;
  long contact_evaluations = 0;  // pad contacts evaluated so far (right-hand sides count four)
};

// J (zeroed on entry) at state y; `scale` holds each state's typical size (the perturbation of
// column j is sqrt(eps) max(|y_j|, scale_j)). `at_y` (optional): the evaluation at y in these modes,
// if the caller has it (CVODE asks for a Jacobian at the state of the right-hand side it has just
// evaluated): its contacts are not evaluated again.
void LanderJacobian(const LanderModel& model, const StateLayout& layout, const rft::Terrain& terrain,
                    const LanderModes& modes, const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::VectorXd& scale,
                    LanderData* data, LanderJacobianData* work, Eigen::Ref<Eigen::MatrixXd> J,
                    const LanderEvaluation* at_y = nullptr);

}  // namespace touchdown::lander

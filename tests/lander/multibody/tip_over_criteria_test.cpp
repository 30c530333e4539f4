// Tip-over criteria (lander/multibody/static_stability.h) against closed forms and the lander's
// own tip-over event.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "lander/multibody/lander_simulation.h"
#include "lander/multibody/static_stability.h"
#include "rft/units.h"
#include "tests/lander/multibody/paper_lander.h"

namespace touchdown::lander {
namespace {

// A box-like lander: body CoM at the origin, joint centres at (+-a, +-a, -joint_depth) (pad 1
// front-left, clockwise), pads level (the paper's pad, its CoM below its joint centre).
struct BoxLander {
  LanderModel model;
  double a = 0.2, joint_depth = 0.3;
};

BoxLander MakeBoxLander() {
  BoxLander box;
  LanderModel& m = box.model;
  m.body_mass_kg = 4.0;
  m.body_inertia_B = Eigen::Vector3d(0.05, 0.07, 0.09).asDiagonal();
  const auto pad = std::make_shared<const geom::PadBody>(test::LanderPad());
  constexpr double kSign[kNumLegs][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
  for (int i = 0; i < kNumLegs; ++i) {
    m.legs[i].joint_B = Eigen::Vector3d(kSign[i][0] * box.a, kSign[i][1] * box.a, -box.joint_depth);
    m.legs[i].hip_B = Eigen::Vector3d(kSign[i][0] * 0.05, kSign[i][1] * 0.05, 0.0);
    m.legs[i].pad = pad;
  }
  FinishModel(m);
  return box;
}

// The state vector of a lander at rest pose (body at p_WB with attitude R_WB, pads parallel to the
// body, every body moving at v_W without rotation).
Eigen::VectorXd TipTestState(const LanderModel& model, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& v_W) {
  const StateLayout L(model);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(L.size);
  const Eigen::Quaterniond q(R_WB);
  y.segment<4>(L.quat_B()) << q.w(), q.x(), q.y(), q.z();
  for (int i = 0; i < kNumLegs; ++i) y.segment<4>(L.quat_P(i)) << q.w(), q.x(), q.y(), q.z();
  y.segment<3>(L.v_B()) = v_W;
  return y;
}

// The box's CoM height above its joint-centre plane and its horizontal offset along x (exact).
struct BoxCom {
  double height = 0.0, x = 0.0;
};
BoxCom BoxComAboveJoints(const BoxLander& box) {
  const LanderModel& m = box.model;
  const geom::PadBody& pad = *m.legs[0].pad;
  const double M = m.TotalMass();
  return {box.joint_depth + kNumLegs * pad.mass_kg * (pad.com_B.z() - box.joint_depth) / M,
          kNumLegs * pad.mass_kg * pad.com_B.x() / M};
}

TEST(TipOverCriteria, BoxLanderCriticalSlopeAndBarrierHaveTheirClosedForms) {
  const BoxLander box = MakeBoxLander();
  const StateLayout L(box.model);
  const BoxCom com = BoxComAboveJoints(box);
  const double h = com.height, d = box.a - com.x;  // to the front edge (pads 1-2), downhill +x
  const Eigen::VectorXd level = TipTestState(box.model, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  const StaticTipOver flat = StaticTipOverOnSlope(box.model, L, level, {0.0, Eigen::Vector3d::UnitX()});
  EXPECT_NEAR(flat.margin_m, d, 1e-12);
  EXPECT_NEAR(flat.margin_m, StabilityMargin(box.model, L, level), 1e-15);
  EXPECT_NEAR(std::tan(flat.critical_slope_rad), d / h, 1e-12);
  EXPECT_EQ(flat.edge_from_leg, 0);
  const EdgeTipping front = EdgeTippings(box.model, L, level)[0];
  EXPECT_NEAR(front.inside_m, d, 1e-12);
  EXPECT_NEAR(front.height_m, h, 1e-12);
  EXPECT_NEAR(front.tip_angle_rad, std::atan2(d, h), 1e-12);
  const double Mg = box.model.TotalMass() * box.model.gravity_m_s2;
  EXPECT_NEAR(front.barrier_J, Mg * (std::sqrt(h * h + d * d) - h), 1e-12);

  // The same lander standing aligned on a 10 deg slope: the same critical slope, 10 deg closer.
  const double slope = 10.0 * units::kDeg;
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(slope, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::VectorXd on_slope = RotateLanderState(L, level, tilt, Eigen::Vector3d(0.3, -0.1, 0.2));
  const StaticTipOver sloped = StaticTipOverOnSlope(box.model, L, on_slope, {slope, Eigen::Vector3d::UnitX()});
  EXPECT_NEAR(sloped.critical_slope_rad, flat.critical_slope_rad, 1e-12);
  EXPECT_NEAR(sloped.extra_tilt_rad, flat.critical_slope_rad - slope, 1e-12);
  // Turned 10 deg towards the front edge: the CoM's distance from it, hypot(d, h), is kept and its
  // height above it is h cos + d sin.
  EXPECT_NEAR(EdgeTippings(box.model, L, on_slope)[0].barrier_J,
              Mg * (std::hypot(d, h) - (h * std::cos(slope) + d * std::sin(slope))), 1e-12);
  std::printf("[ box ] d %.4f m, h %.4f m: critical slope %.4f deg, barrier %.5f J\n", d, h,
              flat.critical_slope_rad / units::kDeg, front.barrier_J);
}

TEST(TipOverCriteria, BoxLanderYawedTowardsAPadTipsOverTheCorner) {
  // Pad 1 pointing downhill (yaw -45 deg): the CoM leaves the polygon at that pad's corner, a = r.
  const BoxLander box = MakeBoxLander();
  const StateLayout L(box.model);
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(-45.0 * units::kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::VectorXd y = TipTestState(box.model, yaw, Eigen::Vector3d::Zero());
  const geom::PadBody& pad = *box.model.legs[0].pad;
  const double corner = std::sqrt(2.0) * box.a, offset = kNumLegs * pad.mass_kg * pad.com_B.x() / box.model.TotalMass();
  const StaticTipOver st = StaticTipOverOnSlope(box.model, L, y, {0.0, Eigen::Vector3d::UnitX()});
  EXPECT_NEAR(std::tan(st.critical_slope_rad), (corner - std::sqrt(2.0) * offset) / BoxComAboveJoints(box).height, 1e-12);
}

TEST(TipOverCriteria, EdgeKineticEnergyIsThePlasticCaptureAboutTheEdge) {
  // Every body moving at v towards the front edge, none rotating: H = M v h about the edge (k = +y).
  const BoxLander box = MakeBoxLander();
  const StateLayout L(box.model);
  const double v = 0.7;
  const Eigen::VectorXd y = TipTestState(box.model, Eigen::Matrix3d::Identity(), Eigen::Vector3d(v, 0.0, 0.0));
  const EdgeTipping front = EdgeTippings(box.model, L, y)[0];
  const geom::PadBody& pad = *box.model.legs[0].pad;
  const double M = box.model.TotalMass(), h = BoxComAboveJoints(box).height;
  const Eigen::Vector3d c = pad.com_B;
  const double inertia = box.model.body_inertia_B(1, 1) + box.model.body_mass_kg * (box.a * box.a + box.joint_depth * box.joint_depth) +
                         kNumLegs * pad.inertia_com_B(1, 1) + 2.0 * pad.mass_kg * (c.x() * c.x() + c.z() * c.z()) +
                         2.0 * pad.mass_kg * (std::pow(2.0 * box.a - c.x(), 2) + c.z() * c.z());
  EXPECT_NEAR(front.tip_axis_W.y(), 1.0, 1e-15);
  EXPECT_NEAR(front.inertia_kg_m2, inertia, 1e-12);
  EXPECT_NEAR(front.angular_momentum_N_m_s, M * v * h, 1e-12);
  EXPECT_NEAR(front.EdgeKineticEnergy(), 0.5 * std::pow(M * v * h, 2) / inertia, 1e-12);
  // Moving away from the edge: nothing drives the rotation about it.
  const Eigen::VectorXd back = TipTestState(box.model, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-v, 0.0, 0.0));
  EXPECT_EQ(EdgeTippings(box.model, L, back)[0].EdgeKineticEnergy(), 0.0);
  const EnergyTipOver energy = EnergyTipOverAtEdge(box.model, L, y, y, 0);
  EXPECT_NEAR(energy.kinetic_J, 0.5 * M * v * v, 1e-12);
  EXPECT_EQ(energy.barrier_J, front.barrier_J);
  EXPECT_LT(energy.edge_kinetic_J, energy.kinetic_J);  // the capture removes energy
}

}  // namespace
}  // namespace touchdown::lander

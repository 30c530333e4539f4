// Tip-over criteria (lander/multibody/static_stability.h, docs/tip_over_criteria.md): closed forms
// on a box-like lander, then against the lander's own tip-over event (LanderRunResult::tipped_over):
// slow landings on slopes around the static critical angle, and downhill speeds around the energy
// bounds. 13 landings of at most 1 s simulated, about 1 s in all (Release build).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "lander/multibody/lander_simulation.h"
#include "lander/multibody/static_stability.h"
#include "rft/units.h"
#include "fixtures/paper_lander.h"

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
  y.segment<4>(L.quat_WB()) << q.w(), q.x(), q.y(), q.z();
  for (int i = 0; i < kNumLegs; ++i) y.segment<4>(L.quat_WP(i)) << q.w(), q.x(), q.y(), q.z();
  y.segment<3>(L.v_WB_W()) = v_W;
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

TEST(TipOverCriteria, StabilityMarginIsTheLeastInsideEdgeDistanceOfTheCentreOfMass) {
  // Same arithmetic, so StabilityMargin can be written with these (bit for bit).
  const BoxLander box = MakeBoxLander();
  const StateLayout L(box.model);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.2, Eigen::Vector3d(1, 2, 0).normalized()))
                                .toRotationMatrix();
  const Eigen::VectorXd y = RotateLanderState(L, TipTestState(box.model, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()), R,
                                              Eigen::Vector3d(0.1, 0.2, 0.3));
  const LanderPose pose = ComputePose(box.model, L, y);
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kNumLegs; ++i) least = std::min(least, InsideEdgeDistance(pose, i, LanderCentreOfMass(box.model, pose)));
  EXPECT_EQ(least, StabilityMargin(box.model, L, y));
  const std::array<EdgeTipping, kNumLegs> edges = EdgeTippings(box.model, L, y);
  for (int i = 0; i < kNumLegs; ++i) EXPECT_EQ(edges[i].inside_m, InsideEdgeDistance(pose, i, LanderCentreOfMass(box.model, pose)));
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
  EXPECT_EQ(energy.released_potential_J, 0.0);
  EXPECT_LT(energy.edge_kinetic_J, energy.kinetic_J);  // the capture removes energy
}

// --- The criteria against the lander's own tip-over event -------------------------------------
//
// The paper's lander on legs 0.8 m longer (its body's CoM 0.8 m higher; masses, inertia, pads,
// footprint and soil unchanged). Why not the paper's lander itself: its static tip-over angle is
// 45 deg, and its slow landings on LP come to rest only below 14 deg (on 14 and 20 deg its pads are
// never held: it ploughs down the slope; on 40-44 deg it slides and tips), so its boundary is set by
// sliding, not by the static criterion (docs/tip_over_criteria.md). Raised, its static angle is
// 12.6 deg, where its landings come to rest or tip.
constexpr double kTipLegExtension_m = 0.8;
constexpr double kTipTouchdownSpeed = 0.1;  // vertical, at the first pad's touchdown [m/s]

struct TipLanding {
  double slope_rad = 0.0;
  double downhill_speed = 0.0;      // horizontal, towards the downhill direction (+x) [m/s]
  double short_of_slope_rad = 0.0;  // the lander released pitched this much less than the slope
};

// On LP, the ground descending towards +x, the lander aligned with it (body x downhill: pads 1
// and 2 downhill, the downhill edge is edge 0) less short_of_slope_rad, released just above the
// surface so that the first pad touches at kTipTouchdownSpeed.
test::PaperLander TallLanderOnSlope(const TipLanding& landing) {
  test::PaperLander out = test::MakePaperLander('A');
  for (Leg& leg : out.model.legs) {
    leg.joint_B.z() -= kTipLegExtension_m;
    leg.hip_B.z() -= kTipLegExtension_m;
  }
  const double g = out.model.gravity_m_s2;
  out.terrain.surface = std::make_shared<rft::PlaneGround>(0.0, -std::tan(landing.slope_rad), 0.0);
  LanderInitialState& s = out.initial;
  s.R_WB = Eigen::AngleAxisd(landing.slope_rad - landing.short_of_slope_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  for (int i = 0; i < kNumLegs; ++i) s.R_WP[i] = s.R_WB;
  // As the scenario's touchdown_speed_m_s: released at most 5 mm above, falling.
  const double v = kTipTouchdownSpeed, clearance = std::min(0.005, v * v / (4.0 * g));
  s.p_WB = Eigen::Vector3d::Zero();
  s.v_WB_W = Eigen::Vector3d(landing.downhill_speed, 0.0, -std::sqrt(v * v - 2.0 * g * clearance));
  s.p_WB.z() = BodyHeightForClearance(out.model, out.terrain, s, clearance);
  return out;
}

LanderRunResult LandTall(const TipLanding& landing, double duration_s) {
  test::PaperLander setup = TallLanderOnSlope(landing);
  setup.options.duration_s = duration_s;
  setup.options.sample_rate_hz = 100.0;  // the verdict and the final state are all these tests read
  return SimulateLander(setup);
}

// The tall lander after a slow landing on a 5 deg slope, at rest (shared by the tests below).
const LanderRunResult& TallLanderAtRestOn5Deg() {
  static const LanderRunResult rest = LandTall({5.0 * units::kDeg, 0.0, 0.0}, 1.0);
  return rest;
}

// The state at touchdown of a landing (the release state with the touchdown speed: the 0.25 mm
// of fall before the first contact changes nothing here).
Eigen::VectorXd TallTouchdownState(const TipLanding& landing) {
  const test::PaperLander setup = TallLanderOnSlope(landing);
  const StateLayout L(setup.model);
  const Eigen::Vector3d v(landing.downhill_speed, 0.0, -kTipTouchdownSpeed);
  Eigen::VectorXd y = TipTestState(setup.model, setup.initial.R_WB, v);
  y.segment<3>(L.p_WB()) = setup.initial.p_WB;
  return y;
}

TEST(TipOverCriteria, SlowLandingsTipWhereTheStaticCriterionSaysWithTheSettlingOvershoot) {
  const test::PaperLander tall = TallLanderOnSlope({});
  const StateLayout L(tall.model);
  const LanderRunResult& rest = TallLanderAtRestOn5Deg();
  ASSERT_TRUE(rest.rest_time_s);
  ASSERT_FALSE(rest.tipped_over);
  // The static criterion with the sinkage of a landing at rest.
  const StaticTipOver st = StaticTipOverOnSlope(tall.model, L, rest.final_state, {5.0 * units::kDeg, Eigen::Vector3d::UnitX()});
  const double critical = st.critical_slope_rad;
  EXPECT_EQ(st.edge_from_leg, 0);
  // The same without sinkage (standing level on the pad bottoms): the sinkage lowers the angle.
  const StaticTipOver rigid = StaticTipOverOnSlope(tall.model, L, TipTestState(tall.model, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
                                                   {0.0, Eigen::Vector3d::UnitX()});
  EXPECT_LT(critical, rigid.critical_slope_rad);
  std::printf("[ quasi-static ] static critical slope %.3f deg (with the sinkage at rest on 5 deg; %.3f deg without)\n",
              critical / units::kDeg, rigid.critical_slope_rad / units::kDeg);

  // Above it the lander cannot stand. (Released 1 deg short of the slope so that it starts inside
  // its polygon: the tip-over event fires on the way out, not for a lander placed outside.)
  const LanderRunResult over = LandTall({critical + 0.5 * units::kDeg, 0.0, 1.0 * units::kDeg}, 1.0);
  EXPECT_TRUE(over.tipped_over);
  // It goes over the edge the static criterion names, the downhill one (pads 1 and 2, symmetric
  // about the x-z plane the landing stays in), and falls straight downhill (+x); the lateral drift
  // it picks up is rounding and pad-mesh asymmetry grown through the integration (4e-8 rad measured).
  EXPECT_EQ(over.tip_over_edge, st.edge_from_leg);
  EXPECT_NEAR(over.tip_over_azimuth_rad, 0.0, 1e-6);
  EXPECT_EQ(rest.tip_over_edge, -1);
  EXPECT_TRUE(std::isnan(rest.tip_over_azimuth_rad));
  // Below it, a slow landing still tips within the settling overshoot: the pads must sink to carry
  // the lander (RFT has no bearing at zero depth), the downhill pads, carrying nearly all of it,
  // sink deeper and faster, and the lander turns about them while it settles. The slope band this
  // overshoot tips over is where the barrier about the downhill edge is below the kinetic energy
  // left when the downhill pads are captured (energy criterion):
  const double below = critical - 1.5 * units::kDeg;
  const LanderRunResult settled = LandTall({below, 0.0, 0.0}, 0.6);
  EXPECT_FALSE(settled.tipped_over);
  EXPECT_GT(settled.max_tilt_rad, settled.final_attitude.tilt_rad + 0.05 * units::kDeg) << "turning back by the end";
  double capture_kinetic = -1.0;
  for (const LanderEvent& e : settled.events)
    if (e.kind == LanderEventKind::kCapture && e.leg == 0 && capture_kinetic < 0.0)
      for (const LanderSample& x : settled.trace)
        if (x.t_s == e.t_s) capture_kinetic = x.kinetic_J;  // the last sample there: after the capture
  ASSERT_GT(capture_kinetic, 0.0);
  auto barrier_at = [&](double slope) {
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(slope - 5.0 * units::kDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
    return EdgeTippings(tall.model, L, RotateLanderState(L, rest.final_state, turn, Eigen::Vector3d::Zero()))[0].barrier_J;
  };
  std::uintmax_t iterations = 100;
  const auto root = boost::math::tools::toms748_solve([&](double slope) { return barrier_at(slope) - capture_kinetic; },
                                                      below - 2.0 * units::kDeg, critical,
                                                      boost::math::tools::eps_tolerance<double>(40), iterations);
  const double predicted = 0.5 * (root.first + root.second);
  // The dynamic boundary: two halvings between `below` (lands) and 0.5 deg under the static angle.
  double lands = below, tips = critical - 0.5 * units::kDeg;
  ASSERT_TRUE(LandTall({tips, 0.0, 0.0}, 1.0).tipped_over);
  for (int step = 0; step < 2; ++step) {
    const double mid = 0.5 * (lands + tips);
    (LandTall({mid, 0.0, 0.0}, 1.0).tipped_over ? tips : lands) = mid;
  }
  std::printf("[ quasi-static ] slow landings (%.2f m/s) tip between %.3f and %.3f deg; kinetic energy at the downhill "
              "capture %.4f J = barrier at %.3f deg\n",
              kTipTouchdownSpeed, lands / units::kDeg, tips / units::kDeg, capture_kinetic, predicted / units::kDeg);
  EXPECT_GT(predicted, lands - 0.25 * units::kDeg);
  EXPECT_LT(predicted, tips + 0.25 * units::kDeg);
}

TEST(TipOverCriteria, EnergyBoundsBracketTheDynamicTippingSpeed) {
  const test::PaperLander tall = TallLanderOnSlope({});
  const StateLayout L(tall.model);
  const double slope = 5.0 * units::kDeg, M = tall.model.TotalMass();
  const Eigen::VectorXd& standing = TallLanderAtRestOn5Deg().final_state;
  const EnergyTipOver at_rest = EnergyTipOverAtEdge(tall.model, L, standing, TallTouchdownState({slope, 0.0, 0.0}), 0);
  const double barrier = at_rest.barrier_J;
  // Lower bound: the kinetic energy at touchdown plus the potential energy the sinking releases
  // equals the barrier (every body moves at the touchdown velocity, so the kinetic energy is that at
  // zero horizontal speed plus M v^2 / 2).
  const double released = at_rest.released_potential_J;
  EXPECT_GT(released, 0.0);
  const double v_lower = std::sqrt(2.0 * (barrier - released - at_rest.kinetic_J) / M);
  const EnergyTipOver at_lower = EnergyTipOverAtEdge(tall.model, L, standing, TallTouchdownState({slope, v_lower, 0.0}), 0);
  EXPECT_NEAR(at_lower.kinetic_J + at_lower.released_potential_J, barrier, 1e-12 * barrier);
  // Estimate: the rotation energy about the edge after a plastic capture equals the barrier (its
  // angular momentum is linear in the horizontal speed).
  const EdgeTipping h0 = EdgeTippings(tall.model, L, TallTouchdownState({slope, 0.0, 0.0}))[0];
  const EdgeTipping h1 = EdgeTippings(tall.model, L, TallTouchdownState({slope, 1.0, 0.0}))[0];
  const double v_estimate =
      (std::sqrt(2.0 * h0.inertia_kg_m2 * barrier) - h0.angular_momentum_N_m_s) / (h1.angular_momentum_N_m_s - h0.angular_momentum_N_m_s);
  EXPECT_NEAR(EnergyTipOverAtEdge(tall.model, L, standing, TallTouchdownState({slope, v_estimate, 0.0}), 0).edge_kinetic_J,
              barrier, 1e-9 * barrier);
  EXPECT_GT(v_estimate, v_lower);
  std::printf("[ energy ] slope 5 deg: barrier %.4f J, sinking releases %.4f J, lower bound %.4f m/s, plastic-capture "
              "estimate %.4f m/s\n", barrier, released, v_lower, v_estimate);
  // Below the lower bound: the landing without horizontal speed stands (TallLanderAtRestOn5Deg); one
  // just below it (0.95 v_lower) is JustBelowTheEnergyLowerBoundNeverTips.
  ASSERT_FALSE(TallLanderAtRestOn5Deg().tipped_over);
  // The dynamic critical speed by halving, from 0.85 and 1.5 times the estimate.
  double no_tip = 0.85 * v_estimate, tips = 1.5 * v_estimate;
  ASSERT_FALSE(LandTall({slope, no_tip, 0.0}, 1.0).tipped_over);
  ASSERT_TRUE(LandTall({slope, tips, 0.0}, 1.0).tipped_over);
  for (int step = 0; step < 5; ++step) {
    const double mid = 0.5 * (no_tip + tips);
    (LandTall({slope, mid, 0.0}, 1.0).tipped_over ? tips : no_tip) = mid;
  }
  std::printf("[ energy ] dynamic critical downhill speed in [%.4f, %.4f] m/s\n", no_tip, tips);
  // The bracket: above the necessary bound, below the plastic-capture estimate (1-3 % here: the
  // settling turn about the downhill pads adds to the rotation the capture gives).
  EXPECT_GT(no_tip, v_lower);
  EXPECT_LT(tips, v_estimate);
}

// The sharpest form of the lower bound: a downhill speed just under it never tips. (The downhill
// pads plough at mm/s for a long time: Adams would need millions of steps, BDF with the lander's
// Jacobian takes a fraction of a second.)
TEST(TipOverCriteria, JustBelowTheEnergyLowerBoundNeverTips) {
  const test::PaperLander tall = TallLanderOnSlope({});
  const StateLayout L(tall.model);
  const double slope = 5.0 * units::kDeg;
  const EnergyTipOver e = EnergyTipOverAtEdge(tall.model, L, TallLanderAtRestOn5Deg().final_state,
                                              TallTouchdownState({slope, 0.0, 0.0}), 0);
  const double v_lower = std::sqrt(2.0 * (e.barrier_J - e.released_potential_J - e.kinetic_J) / tall.model.TotalMass());
  const LanderRunResult r = LandTall({slope, 0.95 * v_lower, 0.0}, 1.0);
  EXPECT_FALSE(r.tipped_over);
  std::printf("[ energy ] %.4f m/s (0.95 of the lower bound): max tilt %.2f deg, %ld steps\n", 0.95 * v_lower,
              r.max_tilt_rad / units::kDeg, long(r.solver.steps));
}

}  // namespace
}  // namespace touchdown::lander

namespace touchdown::lander {
namespace {

// A lander aligned to a slope steeper than its static angle (the tall lander's is 12.6 deg) has its
// centre of mass outside the support polygon before any pad touches: the margin never falls through
// zero, so the tip-over is declared at the first touchdown, or at release if a pad already touches.
TEST(TipOverCriteria, ALanderOutsideItsSupportPolygonAtTouchdownIsOver) {
  const double slope = 20.0 * units::kDeg;
  test::PaperLander falling = TallLanderOnSlope({slope, 0.0, 0.0});
  const StateLayout L(falling.model);
  falling.options.duration_s = 0.5;
  falling.options.sample_rate_hz = 100.0;
  const LanderRunResult r = SimulateLander(falling);
  ASSERT_TRUE(r.first_touchdown_s);
  EXPECT_TRUE(r.tipped_over);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind, LanderEventKind::kTipOver);
  EXPECT_EQ(r.events.back().t_s, *r.first_touchdown_s);
  EXPECT_LT(StabilityMargin(falling.model, L, r.final_state), 0.0);

  test::PaperLander standing = falling;
  standing.initial.v_WB_W.setZero();
  standing.initial.p_WB.z() = BodyHeightForClearance(standing.model, standing.terrain, standing.initial, 0.0);
  const LanderRunResult at_release = SimulateLander(standing);
  EXPECT_TRUE(at_release.tipped_over);
  EXPECT_EQ(at_release.end_time_s, 0.0);
  EXPECT_EQ(at_release.solver.steps, 0);
}

}  // namespace
}  // namespace touchdown::lander

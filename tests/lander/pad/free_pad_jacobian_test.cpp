// The free pad's structured Jacobian (FreePadDynamics::Jacobian) against plain central differences
// of the right-hand side over every state, at a tilted, sinking, sliding and spinning pad in the
// soil, on a level and a sloped plane; it allocates nothing; and a drop with it lands where one
// with CVODE's difference quotients does, for fewer right-hand sides per Jacobian.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "footpad_geom/axisymmetric_profile.h"
#include "footpad_geom/revolve.h"
#include "lander/pad/free_drop.h"
#include "lander/pad/free_pad_dynamics.h"
#include "rft/stress_law_3d_factory.h"
#include "fixtures/paper_soils.h"
#include "tests/malloc_counter.h"

namespace touchdown::pad {
namespace {

geom::PadBody JacobianTestPad() {
  const geom::AxisymmetricProfile profile = geom::MakeFlatProfile(0.05, 0.016);  // data/pads/flat.yaml
  return geom::RevolveProfileToBody(profile, 24, 1.6, Eigen::Vector3d(0.0, 0.0, 0.016));
}

// 10 degrees of tilt, 5 mm into the soil, sinking, sliding and spinning; the quaternion a little
// off unit norm, as the integrator carries it.
Eigen::VectorXd JacobianTestState(const FreePadDynamics& pad) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(FreePadStateLayout(false).size);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.17, Eigen::Vector3d(1.0, 0.3, 0.0).normalized()));
  y.segment<4>(FreePadStateLayout::quat_WB()) << q.w(), q.x(), q.y(), q.z();
  y.segment<4>(FreePadStateLayout::quat_WB()) *= 1.0 + 1e-7;
  y.segment<3>(FreePadStateLayout::v_WC_W()) << 0.3, 0.1, -0.8;
  y.segment<3>(FreePadStateLayout::w_WB_B()) << 0.5, -1.0, 2.0;
  y[FreePadStateLayout::p_WC() + 2] += pad.Depth(pad.PoseOf(y)) - 0.005;
  return y;
}

// Central differences over every state, with the step scaled to the state's size.
Eigen::MatrixXd CentralDifferenceJacobian(const FreePadDynamics& pad, const Eigen::VectorXd& y,
                                          const Eigen::VectorXd& scale) {
  const int n = pad.size();
  Eigen::MatrixXd J(n, n);
  Eigen::VectorXd fp(n), fm(n);
  FreePadData data;
  for (int i = 0; i < n; ++i) {
    const double h = 1e-6 * scale[i];
    Eigen::VectorXd yp = y, ym = y;
    yp[i] += h, ym[i] -= h;
    Derivative(pad, data, yp, fp);
    Derivative(pad, data, ym, fm);
    J.col(i) = (fp - fm) / (2.0 * h);
  }
  return J;
}

void ExpectStructuredJacobianMatches(const rft::Terrain& terrain) {
  const geom::PadBody body = JacobianTestPad();
  const FreePadDynamics pad(body, terrain, 9.81);
  FreePadData data;
  ASSERT_EQ(pad.JacobianContacts(), 10);  // over a plane: 1 depth + 3 rotations + 6 twist
  const Eigen::VectorXd y = JacobianTestState(pad);
  // Scales as the free drop's: length 0.05 m, speed 1 m/s, angle 1 rad, rate 20 rad/s, energy 1 J.
  Eigen::VectorXd scale(FreePadStateLayout(false).size);
  scale << 0.05, 0.05, 0.05, 1, 1, 1, 1, 1, 1, 1, 20, 20, 20, 1;
  Eigen::VectorXd f0(FreePadStateLayout(false).size);
  Derivative(pad, data, y, f0);
  Eigen::MatrixXd J = Eigen::MatrixXd::Constant(FreePadStateLayout(false).size, FreePadStateLayout(false).size, 7.0);  // Jacobian sets every entry
  pad.Jacobian(y, f0, scale, J);
  const Eigen::MatrixXd reference = CentralDifferenceJacobian(pad, y, scale);
  // Column by column, relative to the column's size (forward against central differences of a
  // right-hand side with kinks: the agreement is that of first-order differences, ~1e-5).
  for (int i = 0; i < FreePadStateLayout(false).size; ++i) {
    const double size = reference.col(i).norm();
    EXPECT_LE((J.col(i) - reference.col(i)).norm(), 1e-4 * size + 1e-9) << "column " << i;
  }
  EXPECT_GT(reference.col(FreePadStateLayout::p_WC() + 2).norm(), 1e3);  // the soil's stiffness is in it
  EXPECT_EQ(J.col(FreePadStateLayout::work()).norm(), 0.0);
}

TEST(FreePadJacobian, MatchesCentralDifferencesOnALevelPlane) {
  ExpectStructuredJacobianMatches(rft::UniformTerrain("lp", test::Fjs1Law(false)));
}

TEST(FreePadJacobian, MatchesCentralDifferencesOnASlope) {
  ExpectStructuredJacobianMatches(
      rft::UniformTerrain("lp", test::Fjs1Law(false), std::make_shared<const rft::PlaneGround>(0.01, 0.15, -0.08)));
}

TEST(FreePadJacobian, DoesNotAllocate) {
  if (!testing_alloc::kCountsMalloc) GTEST_SKIP() << "malloc is not counted under AddressSanitizer";
  const geom::PadBody body = JacobianTestPad();
  const rft::Terrain terrain = rft::UniformTerrain("lp", test::Fjs1Law(false));
  const FreePadDynamics pad(body, terrain, 9.81);
  FreePadData data;
  const Eigen::VectorXd y = JacobianTestState(pad), scale = Eigen::VectorXd::Ones(FreePadStateLayout(false).size);
  Eigen::VectorXd f0(FreePadStateLayout(false).size);
  Eigen::MatrixXd J(FreePadStateLayout(false).size, FreePadStateLayout(false).size);
  Derivative(pad, data, y, f0);
  pad.Jacobian(y, f0, scale, J);
  EXPECT_EQ(testing_alloc::CountAllocations([&] { pad.Jacobian(y, f0, scale, J); }), 0);
  EXPECT_TRUE(J.allFinite());
}

// The Jacobian drives Newton's iteration only: a tilted, sliding, spinning drop lands at the same
// depth and tilt with it as with CVODE's difference quotients (to the integration's accuracy),
// spending 10 right-hand sides per Jacobian instead of 14.
TEST(FreePadJacobian, DropMatchesCvodesDifferenceQuotients) {
  const geom::PadBody body = JacobianTestPad();
  const rft::Terrain bed = rft::UniformTerrain("lp", test::Fjs1Law(false));
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.tilt_rad = 0.09;
  in.horizontal_speed_m_s = 0.3;
  in.omega_W = Eigen::Vector3d(0.0, 0.0, 3.0);
  FreeDropOptions structured, dq;
  structured.integrator.rtol = dq.integrator.rtol = 1e-8;
  dq.structured_jacobian = false;
  const FreeDropResult a = RunFreeDrop({&body, bed, in, structured}), b = RunFreeDrop({&body, bed, in, dq});
  EXPECT_NEAR(a.final_penetration_m, b.final_penetration_m, 1e-6 * b.final_penetration_m);
  EXPECT_NEAR(a.final_tilt_deg, b.final_tilt_deg, 1e-4);
  ASSERT_GT(a.solver.jacobian_evaluations, 0);
  EXPECT_EQ(a.solver.jacobian_rhs_evaluations, 10 * a.solver.jacobian_evaluations);
  EXPECT_EQ(b.solver.jacobian_rhs_evaluations, 14 * b.solver.jacobian_evaluations);
}

}  // namespace
}  // namespace touchdown::pad

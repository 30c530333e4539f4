// The free pad's right-hand side allocates nothing (house style: no allocation in a right-hand
// side): FreePadDynamics::Derivative of a tilted, spinning pad in the soil, with and without the
// pad-level terms (added mass, compaction, depth law). malloc itself is counted, so Eigen's heap
// buffers count as well as operator new.
#include "lander/pad/free_pad_dynamics.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "footpad_geom/axisymmetric_profile.h"
#include "footpad_geom/revolve.h"
#include "rft/stress_law_3d_factory.h"
#include "fixtures/paper_soils.h"
#include "tests/malloc_counter.h"

namespace touchdown::pad {
namespace {

long AllocationsOfThreeDerivatives(const rft::SoilContactModel& soil) {
  const geom::AxisymmetricProfile profile = geom::MakeFlatProfile(0.05, 0.016);  // data/pads/flat.yaml
  const geom::PadBody body = geom::RevolveProfileToBody(profile, 24, 1.6, Eigen::Vector3d(0.0, 0.0, 0.016));
  rft::Terrain terrain = rft::UniformTerrain("default", soil);
  // A patch away from the pad: the soil lookup walks its polygon on every call.
  terrain.patches.push_back({"far", rft::RectanglePolygon(5.0, 5.0, 6.0, 6.0), 0});
  const FreePadDynamics pad(body, terrain, 9.81);
  FreePadData data;
  // 10 degrees of tilt, 5 mm into the soil, sinking, sliding and spinning.
  Eigen::VectorXd y = Eigen::VectorXd::Zero(FreePadStateLayout(false).size);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.17, Eigen::Vector3d::UnitX()));
  y.segment<4>(FreePadStateLayout::quat_WB()) << q.w(), q.x(), q.y(), q.z();
  y.segment<3>(FreePadStateLayout::v_WC_W()) << 0.3, 0.0, -0.8;
  y.segment<3>(FreePadStateLayout::w_WB_B()) << 0.5, -1.0, 2.0;
  y[FreePadStateLayout::p_WC() + 2] += pad.Depth(pad.PoseOf(y)) - 0.005;
  EXPECT_NEAR(pad.Depth(pad.PoseOf(y)), 0.005, 1e-12);
  Eigen::VectorXd ydot(FreePadStateLayout(false).size);
  Derivative(pad, data, y, ydot);  // any first-call setup outside the count
  const long allocations = testing_alloc::CountAllocations([&] {
    for (int k = 0; k < 3; ++k) Derivative(pad, data, y, ydot);
  });
  EXPECT_GT(-ydot[FreePadStateLayout::work()], -1e300);  // used
  EXPECT_TRUE(ydot.allFinite());
  return allocations;
}

TEST(FreePadRightHandSide, DoesNotAllocate) {
  if (!testing_alloc::kCountsMalloc) GTEST_SKIP() << "malloc is not counted under AddressSanitizer";
  ASSERT_GE(testing_alloc::AllocationsOfAnEigenBuffer(), 1);  // the counter works, for Eigen's buffers too
  EXPECT_EQ(AllocationsOfThreeDerivatives(test::Fjs1Law(false)), 0);
  rft::EffectTerms terms;
  terms.added_mass_ca = 1.0;
  terms.compaction_k_kg_m3 = 2e4;
  terms.compaction_depth_m = 0.003;
  terms.depth_exponent = 1.3;
  terms.damping_c_N_s_m3 = 3e3;
  const rft::SoilContactModel with_terms =
      rft::MakeSoilContactModel(rft::LawKind::kLi2013, test::Fjs1(false), 9.81, terms);
  EXPECT_EQ(AllocationsOfThreeDerivatives(with_terms), 0);
}

}  // namespace
}  // namespace touchdown::pad

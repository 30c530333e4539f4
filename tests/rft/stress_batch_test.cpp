// StressLaw3D::StressPerDepthBatch against StressPerDepth, for every law and decorator, and the
// contact's batched rotating path against the same pad with the per-element area terms switched on.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "rft/contact_wrench.h"
#include "rft/dynamic_term.h"
#include "rft/li2013_3d.h"
#include "rft/stress_law_3d_factory.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

SoilParameters BatchSoil() {
  SoilParameters s;
  s.name = "test_soil";
  s.zeta_N_m3 = 3.48e6;
  s.reference_gravity_m_s2 = 9.81;
  s.bulk_density_kg_m3 = 1540.0;
  s.internal_friction_angle_rad = 37.0 * std::numbers::pi / 180.0;
  s.surface_friction_coefficient = 0.4;
  return s;
}

// Normals and velocities that reach every branch of the laws: random ones, facets within and at
// the 1-degree horizontal band, vertical walls, velocities straight down, along a wall's e1 only
// (no part in the e2-z plane), backwards (the mirror rule) and zero.
void FillCases(std::vector<Eigen::Vector3d>& n, std::vector<Eigen::Vector3d>& v) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto unit = [&]() { return Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized(); };
  for (int i = 0; i < 150; ++i) {
    n.push_back(unit());
    v.push_back(2.0 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
  const double band = std::sin(std::numbers::pi / 180.0);
  for (double nh : {0.0, 0.3 * band, 0.999 * band, band, 1.001 * band}) {
    const Eigen::Vector3d facet = Eigen::Vector3d(nh, 0.2 * nh, -1.0).normalized();
    for (const Eigen::Vector3d& vel : {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0.3, -0.1, -0.5),
                                       Eigen::Vector3d(-0.4, 0.0, 0.1), Eigen::Vector3d(0, 0, 0)}) {
      n.push_back(facet);
      v.push_back(vel);
    }
  }
  const Eigen::Vector3d wall(1.0, 0.0, 0.0);
  for (const Eigen::Vector3d& vel : {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -0.5, 0), Eigen::Vector3d(0.2, 0, -1),
                                     Eigen::Vector3d(-0.3, 0.1, 0.4), Eigen::Vector3d(0, 0, 0)}) {
    n.push_back(wall);
    v.push_back(vel);
  }
  // Runs of one normal (the batch's common case) with different velocities.
  for (int i = 0; i < 40; ++i) {
    n.push_back(Eigen::Vector3d(0.1, 0.0, -1.0).normalized());
    v.push_back(Eigen::Vector3d(u(rng), u(rng), -1.0));
  }
}

TEST(RftStressBatch, EveryLawGivesTheSameStressesAsElementByElement) {
  std::vector<Eigen::Vector3d> n, v;
  FillCases(n, v);
  EffectTerms all;
  all.inertial_lambda = 2.0;
  all.damping_c_N_s_m3 = 1e4;
  all.gas_chi = 0.3;
  all.gas_c_N_s_m3 = 5e3;
  all.depth_exponent = 1.3;
  all.compaction_k_kg_m3 = 3e4;
  all.compaction_depth_m = 0.003;
  all.added_mass_ca = 2.0;
  EffectTerms gas;
  gas.gas_chi = 0.4;
  std::vector<std::shared_ptr<const StressLaw3D>> laws;
  laws.push_back(MakeStressLaw3D(LawKind::kLi2013, BatchSoil(), 9.81));
  laws.push_back(MakeStressLaw3D(LawKind::kAgarwal2023, BatchSoil(), 9.81));
  laws.push_back(MakeSoilContactModel(LawKind::kLi2013, BatchSoil(), 1.62, gas).law);
  laws.push_back(MakeSoilContactModel(LawKind::kLi2013, BatchSoil(), 9.81, all).law);
  laws.push_back(MakeSoilContactModel(LawKind::kAgarwal2023, BatchSoil(), 3.71, all).law);
  for (const auto& law : laws) {
    const int total = static_cast<int>(n.size());
    for (int start = 0; start < total; start += StressBatch::kCapacity) {
      StressBatch b;
      b.count = std::min(StressBatch::kCapacity, total - start);
      for (int i = 0; i < b.count; ++i) {
        b.nx[i] = n[start + i].x(), b.ny[i] = n[start + i].y(), b.nz[i] = n[start + i].z();
        b.vx[i] = v[start + i].x(), b.vy[i] = v[start + i].y(), b.vz[i] = v[start + i].z();
      }
      law->StressPerDepthBatch(b);
      for (int i = 0; i < b.count; ++i) {
        const Eigen::Vector3d one = law->StressPerDepth(n[start + i], v[start + i]);
        const Eigen::Vector3d batched(b.sx[i], b.sy[i], b.sz[i]);
        // Same formulas in another order: rounding only (the stresses are ~1e6-1e7 N/m^3).
        EXPECT_LE((batched - one).norm(), 1e-12 * (1.0 + one.norm()))
            << law->name() << " element " << start + i << ": n " << n[start + i].transpose() << ", v "
            << v[start + i].transpose() << ": " << batched.transpose() << " vs " << one.transpose();
      }
    }
    // A law that says it has no dynamic stress has none.
    if (!law->has_dynamic_stress()) {
      for (size_t i = 0; i < n.size(); ++i) EXPECT_EQ(law->DynamicStress(n[i], v[i]), Eigen::Vector3d::Zero());
    }
  }
  EXPECT_TRUE(laws[3]->has_dynamic_stress());
  EXPECT_FALSE(laws[0]->has_dynamic_stress());
}

TEST(RftStressBatch, EmptyBatchIsANoOp) {
  const auto law = MakeStressLaw3D(LawKind::kLi2013, BatchSoil(), 9.81);
  StressBatch b;
  b.count = 0;
  b.sx[0] = 42.0;
  law->StressPerDepthBatch(b);
  EXPECT_EQ(b.sx[0], 42.0);
}

// The contact's rotating path buffers leading elements and evaluates them in batches; a law with a
// dynamic term of lambda = 0 takes the same path with its per-element area terms on. Both must
// give the same wrench, over more elements than one batch holds.
TEST(RftStressBatch, RotatingContactIsTheSameWithAndWithoutAreaTerms) {
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 3), 48);
  ASSERT_GT(pad.size(), 3 * StressBatch::kCapacity);
  const Li2013TreersLaw plain(3.48e6);
  const DynamicTermLaw zero_lambda(std::make_unique<Li2013TreersLaw>(3.48e6), 0.0, 1540.0);
  ASSERT_TRUE(zero_lambda.has_dynamic_stress());
  PadKinematics k;
  k.R_WB = testing::RotX(0.15);
  k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.006);
  k.v_WB_W = Eigen::Vector3d(0.3, -0.1, -0.8);
  k.w_WB_W = Eigen::Vector3d(4.0, -2.0, 3.0);
  const ContactWrench a = ComputeContactWrench(pad, k, PlaneGround(), plain);
  const ContactWrench b = ComputeContactWrench(pad, k, PlaneGround(), zero_lambda);
  ASSERT_GT(a.leading_elements, StressBatch::kCapacity);
  EXPECT_EQ(a.leading_elements, b.leading_elements);
  EXPECT_LE((a.force_W - b.force_W).norm(), 1e-12 * a.force_W.norm());
  EXPECT_LE((a.moment_W - b.moment_W).norm(), 1e-12 * a.moment_W.norm());
}

// The vectorised path for a rotating pad over a plane (contact_wrench_rotating.cpp) carries the
// law's dynamic stress too: the same wrench as the general element-by-element path, which a pad
// without bounds takes, to rounding. Tilted and sinking (elements cut by the surface), spinning
// (elements cut by the leading boundary), lambda 1.1 as the shipped soils; the dynamic part is a
// good share of the force at 2 m/s.
TEST(RftStressBatch, RotatingVectorisedPathCarriesTheDynamicStress) {
  SurfaceElements bounded = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 3), 48);
  bounded.UpdateBounds();  // as footpad_geom does for every pad
  SurfaceElements unbounded = bounded;
  unbounded.Resize(bounded.size());  // keeps the size, drops the bounds: the general path
  unbounded.p0_B = bounded.p0_B, unbounded.p1_B = bounded.p1_B, unbounded.p2_B = bounded.p2_B;
  unbounded.n_B = bounded.n_B, unbounded.area_m2 = bounded.area_m2;
  ASSERT_FALSE(unbounded.HasBounds());
  const DynamicTermLaw dynamic(std::make_unique<Li2013TreersLaw>(3.48e6), 1.1, 1540.0);
  const Li2013TreersLaw quasi_static(3.48e6);
  PadKinematics k;
  k.R_WB = testing::RotX(0.15);
  k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.006);
  k.v_WB_W = Eigen::Vector3d(0.6, -0.2, -1.6);
  k.w_WB_W = Eigen::Vector3d(8.0, -4.0, 6.0);
  const ContactWrench fast = ComputeContactWrench(bounded, k, PlaneGround(), dynamic);
  const ContactWrench general = ComputeContactWrench(unbounded, k, PlaneGround(), dynamic);
  const ContactWrench without = ComputeContactWrench(bounded, k, PlaneGround(), quasi_static);
  ASSERT_GT(general.leading_elements, StressBatch::kCapacity);
  EXPECT_EQ(fast.leading_elements, general.leading_elements);
  EXPECT_NEAR(fast.submerged_area_m2, general.submerged_area_m2, 1e-14);
  EXPECT_GT((general.force_W - without.force_W).norm(), 0.05 * general.force_W.norm());  // the term matters
  EXPECT_GT((general.moment_W - without.moment_W).norm(), 0.02 * general.moment_W.norm());
  EXPECT_LE((fast.force_W - general.force_W).norm(), 1e-12 * general.force_W.norm());
  EXPECT_LE((fast.moment_W - general.moment_W).norm(), 1e-12 * general.moment_W.norm());
}

}  // namespace
}  // namespace touchdown::rft

// The effect terms with a per-element 3D form, as StressLaw3D decorators: rate damping and the
// gas cushion against closed forms on a horizontal plate, and the factory that stacks them with
// the inertial (dynamic) term.
#include <gtest/gtest.h>

#include <memory>

#include "rft/contact_wrench.h"
#include "rft/dynamic_term.h"
#include "rft/gas_cushion_term.h"
#include "rft/input_error.h"
#include "rft/li2013_3d.h"
#include "rft/rate_damping_term.h"
#include "rft/stress_law_3d_factory.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

constexpr double kZetaEffects = 2.0e6, kC = 4.0e4, kChi = 0.3, kCg = 1.5e4;
const Eigen::Vector3d kDown(0, 0, -1);

// A square plate L x L, 1 mm thick, its bottom at the pad frame's origin.
constexpr double kL = 0.04;
SurfaceElements Plate() {
  return testing::MakeBox(Eigen::Vector3d(-kL / 2, -kL / 2, 0.0), Eigen::Vector3d(kL / 2, kL / 2, 1e-3), 2);
}

TEST(RftRateDamping, StressIsCTimesNormalSpeedAgainstTheNormal) {
  const RateDampingLaw law(std::make_unique<Li2013TreersLaw>(kZetaEffects), kC);
  EXPECT_EQ(law.name(), "li2013+rate_damping");
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, 0.0, -0.9).normalized(), v(0.5, 0.2, -2.0);
  EXPECT_TRUE(law.DynamicStress(n, v).isApprox(-kC * n.dot(v) * n, 1e-14));
  EXPECT_EQ(law.DynamicStress(-n, v), Eigen::Vector3d::Zero());  // trailing
  EXPECT_EQ(law.DynamicStress(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 0, 0)), Eigen::Vector3d::Zero());  // sliding
  EXPECT_EQ(law.StressPerDepth(n, v), Li2013TreersLaw(kZetaEffects).StressPerDepth(n, v));
  EXPECT_THROW(RateDampingLaw(std::make_unique<Li2013TreersLaw>(kZetaEffects), -1.0), std::invalid_argument);
}

TEST(RftRateDamping, HorizontalPlateMovingDownGetsExactlyCvA) {
  const SurfaceElements plate = Plate();
  const RateDampingLaw law(std::make_unique<Li2013TreersLaw>(kZetaEffects), kC);
  for (double speed : {0.3, 1.7})
    for (double depth : {0.004, 0.011}) {
      PadKinematics k;
      k.p_WB = Eigen::Vector3d(0.1, 0.0, -depth);  // off the origin: moments are checked too
      k.v_WB_W = speed * kDown;
      const ContactWrench with = ComputeContactWrench(plate, k, PlaneGround(), law);
      const ContactWrench without = ComputeContactWrench(plate, k, PlaneGround(), law.inner());
      const Eigen::Vector3d extra = with.force_W - without.force_W;
      // Only the bottom leads with v.n = v; the side walls slide (v.n = 0): nothing there.
      EXPECT_NEAR(extra.z(), kC * speed * kL * kL, 1e-9 * extra.z()) << speed << " m/s, " << depth << " m";
      EXPECT_NEAR(extra.x(), 0.0, 1e-9 * extra.z());
      EXPECT_NEAR(extra.y(), 0.0, 1e-9 * extra.z());
      // Applied at the bottom's centroid, the pad frame's origin: no extra moment about it.
      EXPECT_LT((with.moment_W - without.moment_W).norm(), 1e-9 * extra.z() * kL);
    }
}

TEST(RftGasCushion, ScalesTheQuasiStaticStressAndAddsDamping) {
  const GasCushionLaw law(std::make_unique<Li2013TreersLaw>(kZetaEffects), kChi, kCg);
  EXPECT_EQ(law.name(), "li2013+gas_cushion");
  const Eigen::Vector3d n = Eigen::Vector3d(0.2, -0.1, -0.9).normalized(), v(0.3, 0.1, -1.2);
  EXPECT_TRUE(law.StressPerDepth(n, v).isApprox((1 - kChi) * Li2013TreersLaw(kZetaEffects).StressPerDepth(n, v), 1e-14));
  EXPECT_TRUE(law.DynamicStress(n, v).isApprox(-kCg * n.dot(v) * n, 1e-14));
  // A horizontal plate: (1 - chi) zeta A d quasi-static plus c_g v A.
  const SurfaceElements plate = Plate();
  const double speed = 0.8, depth = 0.006;
  PadKinematics k;
  k.p_WB = Eigen::Vector3d(0, 0, -depth);
  k.v_WB_W = speed * kDown;
  const double qs = ComputeContactWrench(plate, k, PlaneGround(), law.inner()).force_W.z();
  const double with = ComputeContactWrench(plate, k, PlaneGround(), law).force_W.z();
  EXPECT_NEAR(with, (1 - kChi) * qs + kCg * speed * kL * kL, 1e-9 * with);
  // The wrapped law's own dynamic term is kept, unscaled.
  const GasCushionLaw around_dynamic(
      std::make_unique<DynamicTermLaw>(std::make_unique<Li2013TreersLaw>(kZetaEffects), 1.5, 1600.0), kChi, 0.0);
  EXPECT_NEAR(around_dynamic.DynamicStress(kDown, 2.0 * kDown).z(), 1.5 * 1600.0 * 4.0, 1e-9);
  EXPECT_THROW(GasCushionLaw(std::make_unique<Li2013TreersLaw>(kZetaEffects), 1.0, 0.0), std::invalid_argument);
}

SoilParameters Soil() {
  SoilParameters s;
  s.name = "test_soil";
  s.zeta_N_m3 = kZetaEffects;
  s.reference_gravity_m_s2 = 9.81;
  s.bulk_density_kg_m3 = 1540.0;
  return s;
}

TEST(RftEffectFactory, NeutralTermsGiveTheBaseLawExactly) {
  const auto base = MakeStressLaw3D(LawKind::kLi2013, Soil(), 1.62);
  const SoilContactModel model = MakeSoilContactModel(LawKind::kLi2013, Soil(), 1.62, EffectTerms{});
  const StressLaw3D* same = model.law.get();
  EXPECT_EQ(same->name(), base->name());
  EXPECT_EQ(model.name(), "li2013");
  EXPECT_FALSE(model.pad_terms.has_power_depth() || model.pad_terms.has_compaction() ||
               model.pad_terms.has_added_mass());
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, 0.0, -0.9).normalized(), v(0.5, 0.2, -2.0);
  EXPECT_EQ(same->StressPerDepth(n, v), base->StressPerDepth(n, v));
  EXPECT_EQ(same->DynamicStress(n, v), base->DynamicStress(n, v));
}

TEST(RftEffectFactory, StacksTheTermsAndTheModelsInertialTermReplacesTheSoils) {
  SoilParameters s = Soil();
  s.dynamic_term = true;  // the soil's own lambda = 1 ...
  EffectTerms t;
  t.inertial_lambda = 2.5;  // ... replaced by the model's
  t.damping_c_N_s_m3 = kC;
  t.gas_chi = kChi;
  t.gas_c_N_s_m3 = kCg;
  const auto law = MakeSoilContactModel(LawKind::kLi2013, s, 9.81, t).law;
  EXPECT_EQ(law->name(), "li2013+dynamic+gas_cushion+rate_damping");
  const double v = 1.3;
  // Straight down on a horizontal face: every term along +z, summed.
  EXPECT_NEAR(law->DynamicStress(kDown, v * kDown).z(), 2.5 * 1540.0 * v * v + (kC + kCg) * v, 1e-9);
  EXPECT_NEAR(law->StressPerDepth(kDown, kDown).z(), (1 - kChi) * kZetaEffects, 1e-6);
  t = EffectTerms{};
  t.inertial_lambda = 1.0;
  s.bulk_density_kg_m3 = 0.0;
  EXPECT_THROW(MakeSoilContactModel(LawKind::kLi2013, s, 9.81, t), InputError);
}

}  // namespace
}  // namespace touchdown::rft

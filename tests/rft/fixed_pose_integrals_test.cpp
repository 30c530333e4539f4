// A pad that keeps still (FixedPoseIntegrals, rft/contact_wrench.h): its integrals formed once at a
// pose, then the wrench of a translation in any direction, must be ComputeContactWrench's at that
// pose (over a plane the force bit for bit, else to rounding; the moment to rounding), with
// and without a dynamic stress, with Janosi's shear mobilised in part and with an element ramp, on
// level ground, a slope and a ground that is no plane.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "rft/bekker_law.h"
#include "rft/contact_wrench.h"
#include "rft/dynamic_term.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

// A ground that is a plane but not a PlaneGround: the general path's depths.
class WavyGround final : public GroundSurface {
 public:
  double Height(double x_m, double y_m) const override { return 0.004 * std::sin(40.0 * x_m) + 0.05 * y_m; }
};

Eigen::Matrix3d Tilted(double roll_deg, double pitch_deg) {
  return (Eigen::AngleAxisd(pitch_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll_deg * M_PI / 180.0, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

void ExpectBitForBit(const SurfaceElements& pad, const GroundSurface& ground, const StressLaw3D& law,
                     const Eigen::Matrix3d& R, const Eigen::Vector3d& p, double mobilisation, double ramp,
                     const char* what) {
  FixedPoseIntegrals held;
  FormFixedPoseIntegrals(pad, R, p, ground, &held);
  ASSERT_FALSE(held.runs.empty()) << what;
  const bool plane = dynamic_cast<const PlaneGround*>(&ground) != nullptr;
  int leading = 0;
  for (int k = 0; k < 72; ++k) {
    for (double down : {0.0, -0.3, 0.5}) {  // horizontal probes, and a little down / up
      const double a = k * M_PI / 36.0;
      const Eigen::Vector3d v = 1e-6 * Eigen::Vector3d(std::cos(a), std::sin(a), down).normalized();
      PadKinematics kin;
      kin.R_WB = R;
      kin.p_WB = p;
      kin.v_WB_W = v;
      kin.shear_mobilisation = mobilisation;
      kin.element_ramp_speed_m_s = ramp;
      const ContactWrench full = ComputeContactWrench(pad, kin, ground, law);
      const ContactWrench fast = TranslationWrenchAt(held, v, law, PadLevelTerms{}, mobilisation, ramp);
      leading += full.leading_elements > 0;
      if (plane) {
        for (int j = 0; j < 3; ++j)
          EXPECT_EQ(fast.force_W[j], full.force_W[j]) << what << " direction " << k << " down " << down << " axis " << j;
      } else {  // the depths' own products contract differently off a plane
        EXPECT_LE((fast.force_W - full.force_W).norm(), 1e-14 * full.force_W.norm()) << what << " direction " << k;
      }
      // The moment's cross products contract into multiply-adds differently: equal to rounding, in
      // units of the force times the pad's size.
      EXPECT_LE((fast.moment_W - full.moment_W).norm(), 1e-14 * full.force_W.norm() * 0.03)
          << what << " direction " << k << " down " << down;
    }
  }
  EXPECT_GT(leading, 200) << what;  // the probes do load the pad
}

TEST(RftFixedPoseIntegrals, TranslationWrenchesAreTheContactsBitForBit) {
  const SurfaceElements pad = testing::LanderLikeFlatPad(24);  // the studies' fast rim (pad_meshes.h)
  const Li2013TreersLaw quasi_static(3.48e6);
  const DynamicTermLaw dynamic(std::make_unique<Li2013TreersLaw>(3.48e6), 1.1, 1540.0);
  const PlaneGround level, slope(0.0, std::tan(10.0 * M_PI / 180.0), -0.02);
  const WavyGround wavy;
  // Buried (its top 5 mm under, level) and cut by the surface through its wall.
  const Eigen::Vector3d deep(0.01, -0.02, 0.005), cut(0.0, 0.0, 0.016);
  for (const StressLaw3D* law : {static_cast<const StressLaw3D*>(&quasi_static), static_cast<const StressLaw3D*>(&dynamic)}) {
    ExpectBitForBit(pad, level, *law, Eigen::Matrix3d::Identity(), deep, 1.0, 0.0, "level, deep");
    ExpectBitForBit(pad, level, *law, Tilted(7.0, -4.0), cut, 1.0, 0.0, "level, tilted, cut");
    ExpectBitForBit(pad, slope, *law, Tilted(-3.0, 12.0), deep, 1.0, 0.0, "10 deg slope");
    ExpectBitForBit(pad, wavy, *law, Tilted(2.0, 2.0), cut, 1.0, 0.0, "another ground");
    ExpectBitForBit(pad, slope, *law, Tilted(5.0, 5.0), cut, 1.0, 1e-5, "element ramp above the probe speed");
  }
  // A law with Janosi's shear, mobilised in part (the lunar Bekker soil of docs/bekker_soil.md, n = 1).
  BekkerParameters b;
  b.n = 1.0;
  b.k_c_N_m_n1 = 1.4e3;
  b.k_phi_N_m_n2 = 820e3;
  b.cohesion_Pa = 170.0;
  b.friction_angle_rad = 35.0 * M_PI / 180.0;
  b.shear_modulus_K_m = 0.018;
  const BekkerLaw3D bekker(b, 0.055);
  ASSERT_TRUE(bekker.has_mobilised_shear());
  ExpectBitForBit(pad, slope, bekker, Tilted(-3.0, 12.0), deep, 0.4, 0.0, "Janosi's shear at 40 %");
}

// Storage is reused: a second pose forms its runs in the same vector, with no leftovers.
TEST(RftFixedPoseIntegrals, FormingAgainReplacesTheRuns) {
  const SurfaceElements pad = testing::LanderLikeFlatPad(24);  // the studies' fast rim (pad_meshes.h)
  const PlaneGround level;
  FixedPoseIntegrals held;
  FormFixedPoseIntegrals(pad, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 0.012), level, &held);
  const size_t deep = held.runs.size();
  const auto* storage = held.runs.data();
  FormFixedPoseIntegrals(pad, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 0.021), level, &held);
  EXPECT_LT(held.runs.size(), deep);  // only the bottom's rings touch
  EXPECT_EQ(held.runs.data(), storage);
  FormFixedPoseIntegrals(pad, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 0.5), level, &held);
  EXPECT_TRUE(held.runs.empty());  // in the air
  const Li2013TreersLaw law(3.48e6);
  EXPECT_EQ(TranslationWrenchAt(held, Eigen::Vector3d(1e-6, 0, 0), law, PadLevelTerms{}).force_W, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace touchdown::rft

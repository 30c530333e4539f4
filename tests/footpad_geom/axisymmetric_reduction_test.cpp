// Vertical intrusion of revolved meshes (flat, C4, curved) through ComputeContactWrench and the
// Treers 3D law reduces to the foundation's axisymmetric profile integral (paper eqs. 3-4).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "footpad_geom/axisymmetric_intrusion.h"
#include "footpad_geom/axisymmetric_profile.h"
#include "rft/contact_wrench.h"
#include "rft/li2013_3d.h"
#include "rft/stress_law.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

constexpr double kZeta = 3.48e6;

std::vector<std::pair<double, double>> Points(const geom::AxisymmetricProfile& p) {
  std::vector<std::pair<double, double>> out;
  for (const geom::ProfilePoint& q : p.points) out.push_back({q.x_m, q.u_m});
  return out;
}

class RftAxisymmetricReduction : public ::testing::TestWithParam<int> {};

TEST_P(RftAxisymmetricReduction, MeshMatchesProfileIntegralAndConverges) {
  const double r = 0.05, h = 0.016;
  const geom::AxisymmetricProfile profile =
      GetParam() == 0   ? geom::MakeFlatProfile(r, h)
      : GetParam() == 1 ? geom::MakeChamferProfile(r, h, 0.004)
                        : geom::MakeExponentialProfile(r, h, 0.0155 / std::expm1(31.901 * r), 31.901,
                                                       60);  // rim 0.5 mm below the top
  const geom::AxisymmetricIntrusion integral(profile, Li2013Law());
  const Li2013TreersLaw law(kZeta);
  PadKinematics k;
  k.v_WB_W = Eigen::Vector3d(0, 0, -1.2);
  double previous = 1.0;
  for (int sectors : {32, 128, 512}) {
    const SurfaceElements pad = testing::MakeRevolvedPad(Points(profile), sectors);
    double worst = 0.0;
    for (double d : {0.003, 0.009, 0.016, 0.022}) {  // the last is deeper than the pad (d > h)
      k.p_WB = Eigen::Vector3d(0, 0, -d);
      const ContactWrench w = ComputeContactWrench(pad, k, PlaneGround(), law);
      const double expected = integral.VerticalForce(d, kZeta);
      worst = std::max(worst, std::abs(w.force_W.z() / expected - 1.0));
      EXPECT_LT(std::hypot(w.force_W.x(), w.force_W.y()), 1e-9 * expected);
      EXPECT_LT(w.moment_W.norm(), 1e-9 * expected * r);
    }
    EXPECT_LT(worst, previous) << sectors;
    previous = worst;
  }
  EXPECT_LT(previous, 5e-3);  // the 0.5 %; in fact O(1/N^2), about 3e-5 at 512 sectors
  EXPECT_LT(previous, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(FlatC4Curved, RftAxisymmetricReduction, ::testing::Values(0, 1, 2));

}  // namespace
}  // namespace touchdown::rft

// CraterHeight against its closed form (Pike 1977 ratios, McGetchin et al. 1973 ejecta) at the
// centre, the rim and on the ejecta blanket, fresh and degraded.
#include "rft/crater_profile.h"

#include <gtest/gtest.h>

namespace touchdown::rft {
namespace {

TEST(RftCraterProfile, FreshCraterAtCentreRimAndEjecta) {
  const CraterShape fresh;
  const double D = 20.0, R = 10.0;
  // Centre: rim height minus rim-to-floor depth, (0.036 - 0.196) D = -0.16 D below the surroundings.
  EXPECT_NEAR(CraterHeight(fresh, D, 0.0), -0.16 * D, 1e-12 * D);
  EXPECT_NEAR(CraterHeight(fresh, D, R), 0.036 * D, 1e-12 * D);                           // rim crest
  EXPECT_NEAR(CraterHeight(fresh, D, 0.5 * R), 0.036 * D - 0.196 * D * 0.75, 1e-12 * D);  // paraboloid
  EXPECT_NEAR(CraterHeight(fresh, D, 2.0 * R), 0.036 * D / 8.0, 1e-12 * D);               // (r/R)^-3
  EXPECT_NEAR(CraterHeight(fresh, D, -3.0 * R), 0.036 * D / 27.0, 1e-12 * D);             // symmetric in r
  // Continuous at the rim from both sides.
  EXPECT_NEAR(CraterHeight(fresh, D, R * (1 - 1e-9)), CraterHeight(fresh, D, R * (1 + 1e-9)), 1e-7);
}

TEST(RftCraterProfile, DegradedCraterIsShallowerInProportion) {
  const CraterShape half = DegradedCraterShape(0.5);
  EXPECT_DOUBLE_EQ(half.depth_to_diameter, 0.098);
  EXPECT_DOUBLE_EQ(half.rim_height_to_diameter, 0.018);
  const double D = 4.0;
  EXPECT_NEAR(CraterHeight(half, D, 0.0), -0.08 * D, 1e-12 * D);
  EXPECT_NEAR(CraterHeight(half, D, 0.5 * D), 0.018 * D, 1e-12 * D);
  EXPECT_EQ(CraterHeight(DegradedCraterShape(0.0), D, 1.3), CraterHeight(CraterShape{}, D, 1.3));
}

}  // namespace
}  // namespace touchdown::rft

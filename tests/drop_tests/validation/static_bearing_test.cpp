// validate's static bearing pressure against the closed form of quasi-static RFT on a flat disc
// held with its bottom at depth d and its side wall submerged over d: F = s_b A d + s_w P d^2 / 2,
// s_b and s_w the law's vertical stress per depth on the bottom and on the wall (moving down), A
// the bottom's area (pi r^2: the rims are area preserving) and P the meshed rim's perimeter; and
// the measured-range comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/contact_model.h"
#include "drop_tests/validation/static_bearing.h"
#include "footpad_geom/revolve.h"
#include "rft/input_error.h"

namespace touchdown::validation {
namespace {

const std::string kShipped = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/validation";
constexpr double kMoon = 1.62;

struct Disc {
  io::PadSpec pad = io::LoadPad(kShipped + "/pads/surveyor_flat_disc.yaml");
  rft::SoilParameters soil = io::LoadSoil(kShipped + "/soils/surveyor3_mare_soil.yaml");
};

// The law's vertical stress per depth [Pa/m] on a face of outward normal n moving straight down.
double VerticalStressPerDepth(const rft::SoilParameters& soil, double gravity, const Eigen::Vector3d& n) {
  const rft::SoilContactModel model = model::MakeContactModel({.soil = soil, .gravity_m_s2 = gravity});
  return model.law->StressPerDepth(n, {0.0, 0.0, -1.0}).z();
}

TEST(StaticBearing, IsTheClosedFormOfRftOnAFlatDisc) {
  const Disc disc;
  const double s_bottom = VerticalStressPerDepth(disc.soil, kMoon, {0.0, 0.0, -1.0});
  const double s_wall = VerticalStressPerDepth(disc.soil, kMoon, {1.0, 0.0, 0.0});
  ASSERT_GT(s_bottom, 0.0);
  const int n = io::PadRimSegments(disc.pad);
  for (const double diameter : {0.2, 0.3})
    for (const double depth : {0.02, 0.035, 0.05}) {
      const double r = 0.5 * diameter;
      const double area = std::acos(-1.0) * r * r;
      const double perimeter = n * 2.0 * r * geom::AreaPreservingRadiusScale(n) * std::sin(std::acos(-1.0) / n);
      const double closed_form = (s_bottom * area * depth + s_wall * perimeter * depth * depth / 2.0) / area;
      EXPECT_NEAR(StaticBearingPressure(disc.pad, disc.soil, kMoon, depth, diameter), closed_form,
                  1e-12 * closed_form)
          << diameter << " m at " << depth << " m";
    }
}

TEST(StaticBearing, ScalesWithGravityAsTheSoilSays) {
  // Lithostatic: zeta, hence the pressure, proportional to g; held at its reference value it is not.
  Disc disc;
  const double earth = StaticBearingPressure(disc.pad, disc.soil, 9.81, 0.03, 0.25);
  const double moon = StaticBearingPressure(disc.pad, disc.soil, kMoon, 0.03, 0.25);
  EXPECT_NEAR(moon, earth * kMoon / 9.81, 1e-12 * moon);
  disc.soil.reference_gravity_m_s2 = kMoon;  // validate's zeta_fixed variants
  EXPECT_NEAR(StaticBearingPressure(disc.pad, disc.soil, kMoon, 0.03, 0.25), earth, 1e-12 * earth);
}

TEST(StaticBearing, IsStaticWhateverTheSoilsDynamicTerm) {
  Disc disc;
  ASSERT_TRUE(disc.soil.dynamic_term);
  const double with_term = StaticBearingPressure(disc.pad, disc.soil, kMoon, 0.03, 0.25);
  disc.soil.dynamic_term = false;
  EXPECT_EQ(StaticBearingPressure(disc.pad, disc.soil, kMoon, 0.03, 0.25), with_term);
}

TEST(StaticBearing, NeedsAFlatPad) {
  const io::PadSpec sphere = io::LoadPad(kShipped + "/pads/kd2007_steel_sphere.yaml");
  EXPECT_THROW(StaticBearingPressure(sphere, Disc().soil, kMoon, 0.03, 0.25), InputError);
}

TEST(CompareRanges, InsideOverlapsOrOutsideWithTheRelativeGap) {
  const Range measured{2.0, 6.0};
  EXPECT_EQ(CompareRanges({3.0, 5.0}, measured).agreement, RangeAgreement::kInside);
  EXPECT_EQ(CompareRanges({2.0, 6.0}, measured).agreement, RangeAgreement::kInside);
  EXPECT_EQ(CompareRanges({1.0, 3.0}, measured).agreement, RangeAgreement::kOverlaps);
  EXPECT_EQ(CompareRanges({1.0, 7.0}, measured).agreement, RangeAgreement::kOverlaps);
  EXPECT_EQ(CompareRanges({1.0, 3.0}, measured).relative_distance, 0.0);
  const RangeComparison below = CompareRanges({0.5, 1.5}, measured);
  EXPECT_EQ(below.agreement, RangeAgreement::kOutside);
  EXPECT_DOUBLE_EQ(below.relative_distance, -0.25);  // (1.5 - 2) / 2
  const RangeComparison above = CompareRanges({9.0, 12.0}, measured);
  EXPECT_EQ(above.agreement, RangeAgreement::kOutside);
  EXPECT_DOUBLE_EQ(above.relative_distance, 0.5);  // (9 - 6) / 6
  EXPECT_STREQ(RangeAgreementName(RangeAgreement::kOverlaps), "overlaps");
}

}  // namespace
}  // namespace touchdown::validation

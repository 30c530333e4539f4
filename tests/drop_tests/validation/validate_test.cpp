// `validate` on the shipped sources: every drop runs, the table's errors and exponents are the
// ones its own numbers give, and the outputs are written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "drop_tests/validation/power_law_fit.h"
#include "drop_tests/validation/validate.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::validation {
namespace {

// One run for the whole suite (a few hundred rig drops).
const ValidationResult& ShippedRun() {
  static const ValidationSet set = LoadValidationSet(std::string(TOUCHDOWN_SOURCE_DIR) + "/data/validation");
  static const ValidationResult result = RunValidation(set);
  return result;
}

const SourceResult& SourceNamed(const std::string& id) {
  for (const SourceResult& r : ShippedRun().sources)
    if (r.source->id == id) return r;
  throw std::runtime_error("no source " + id);
}

size_t VariantIndex(const SourceResult& r, const std::string& name) {
  for (size_t k = 0; k < r.variants.size(); ++k)
    if (r.variants[k].Name() == name) return k;
  throw std::runtime_error("no variant " + name);
}

TEST(ValidateShipped, EveryPointIsSimulatedAndItsErrorComputedFromIt) {
  for (const SourceResult& r : ShippedRun().sources) {
    ASSERT_EQ(r.variants.size(), r.source->low_gravity ? 4u : 2u) << r.source->id;
    for (const PointResult& p : r.points)
      for (size_t k = 0; k < r.variants.size(); ++k) {
        ASSERT_TRUE(std::isfinite(p.simulated[k]) && p.simulated[k] > 0.0) << p.point->id;
        EXPECT_EQ(p.relative_error[k], (p.simulated[k] - p.point->value) / p.point->value) << p.point->id;
      }
  }
  EXPECT_EQ(SourceNamed("katsuragi_durian_2007").points.size(), 13u);
}

TEST(ValidateShipped, ExponentsAreTheLogLogFitOfTheSimulatedValues) {
  int trends = 0;
  for (const SourceResult& r : ShippedRun().sources)
    for (const TrendResult& t : r.trends)
      for (size_t k = 0; k < r.variants.size(); ++k) {
        ASSERT_EQ(t.simulated[k].size(), t.trend->values.size());
        EXPECT_EQ(t.exponent[k], FitPowerLaw(t.x[k], t.simulated[k]).exponent) << t.trend->id;
        for (size_t i = 0; i < t.x[k].size(); ++i) {
          // The abscissa is the trend's value, or for the total drop distance h + d (d simulated).
          const double h_plus_d = t.trend->values[i] + t.simulated[k][i];
          EXPECT_EQ(t.x[k][i], t.trend->vary == Variable::kTotalDropDistance ? h_plus_d : t.trend->values[i]);
        }
        EXPECT_EQ(t.reproduced[k], TrendReproduced(*t.trend, t.exponent[k])) << t.trend->id;
        ++trends;
      }
  EXPECT_EQ(trends, 4 * 1 + 2 * 2 + 2 * 1 + 4 * 5);  // altshuler, ambroso, katsuragi_durian, murdoch
}

TEST(ValidateShipped, ACalibratedSourceReproducesItsDesignatedPointOnly) {
  const SourceResult& r = SourceNamed("katsuragi_durian_2007");
  ASSERT_EQ(r.source->zeta_route, ZetaRoute::kCalibratedOn);
  for (const PointResult& p : r.points)
    for (size_t k = 0; k < r.variants.size(); ++k) {
      if (p.point->id == r.source->calibrated_on) EXPECT_NEAR(p.relative_error[k], 0.0, 1e-9) << r.variants[k].Name();
      else EXPECT_GT(std::abs(p.relative_error[k]), 1e-4) << p.point->id;  // predictions, not fits
    }
  // Zeta is fitted per variant, and the dynamic term's share at rest is small: close but not equal.
  EXPECT_NE(r.zeta_N_m3[0], r.zeta_N_m3[1]);
  EXPECT_NEAR(r.zeta_N_m3[1] / r.zeta_N_m3[0], 1.0, 0.1);
}

TEST(ValidateShipped, ADerivedSourcesPointsAreAllPredictionsOfTheSameDropsAsItsTrend) {
  const SourceResult& r = SourceNamed("ambroso_2005");
  ASSERT_EQ(r.source->zeta_route, ZetaRoute::kDerived);
  ASSERT_EQ(r.points.size(), 5u);
  EXPECT_EQ(r.zeta_N_m3[0], r.zeta_N_m3[1]);  // the soil's own zeta, not fitted per variant
  // The law's points sit at the drop heights of the total-drop-distance trend: the same rig drops.
  const TrendResult& t = r.trends.at(0);
  ASSERT_EQ(t.trend->vary, Variable::kTotalDropDistance);
  for (size_t k = 0; k < r.variants.size(); ++k) {
    double sum = 0.0;
    for (size_t i = 0; i < r.points.size(); ++i) {
      EXPECT_EQ(*r.points[i].point->drop_height_m, t.trend->values[i]);
      EXPECT_EQ(r.points[i].simulated[k], t.simulated[k][i]) << r.points[i].point->id;
      sum += std::abs(r.points[i].relative_error[k]);
    }
    EXPECT_NEAR(r.mean_abs_error[k], sum / 5.0, 1e-15);  // no fitted point to leave out
  }
}

TEST(ValidateShipped, QuasiStaticLithostaticDepthFromRestDoesNotDependOnGravity) {
  // Weight and lithostatic resistance both scale with g: the stroke is the same, only slower.
  const SourceResult& r = SourceNamed("altshuler_2013");
  const TrendResult& t = r.trends.at(0);
  EXPECT_NEAR(t.exponent[VariantIndex(r, "quasi_static")], 0.0, 1e-6);
  EXPECT_NEAR(t.exponent[VariantIndex(r, "dynamic")], 0.0, 1e-6);
  // With zeta fixed the resistance does not grow with g but the weight does: deeper with g.
  EXPECT_GT(t.exponent[VariantIndex(r, "quasi_static_zeta_fixed")], 0.3);
}

TEST(ValidateShipped, TrendVerdictsFollowTheTolerance) {
  MeasuredTrend t;
  t.exponent = 1.0;
  t.tolerance = 0.15;
  EXPECT_TRUE(TrendReproduced(t, 0.86));
  EXPECT_FALSE(TrendReproduced(t, 0.84));
  t.direction = Direction::kDecreasing;
  EXPECT_TRUE(TrendReproduced(t, -0.01));
  EXPECT_FALSE(TrendReproduced(t, 0.01));
}

TEST(ValidateShipped, StaticBearingIsTheModelsRangeOverTheCornersAgainstTheMeasuredOne) {
  const SourceResult& r = SourceNamed("surveyor3_1968");
  ASSERT_EQ(r.bearings.size(), 1u);
  const BearingResult& b = r.bearings[0];
  const MeasuredBearing& m = *b.bearing;
  for (size_t k = 0; k < r.variants.size(); ++k) {
    rft::SoilParameters soil = r.source->soil;
    if (r.variants[k].zeta_fixed) soil.reference_gravity_m_s2 = r.source->gravity_m_s2;
    ASSERT_EQ(b.corners_Pa[k].size(), 4u);
    // Corner order: depth low/high x diameter low/high; the pressure grows with depth and falls
    // with the diameter, so the range's ends are the shallow-wide and the deep-narrow corners.
    EXPECT_EQ(b.corners_Pa[k][2], StaticBearingPressure(r.source->pad, soil, 1.62, m.depth_m.high, m.diameter_m.low));
    EXPECT_EQ(b.simulated_Pa[k].low, b.corners_Pa[k][1]);
    EXPECT_EQ(b.simulated_Pa[k].high, b.corners_Pa[k][2]);
    EXPECT_EQ(b.comparison[k].agreement, CompareRanges(b.simulated_Pa[k], m.pressure_Pa).agreement);
  }
  // Static: the dynamic variants are the quasi-static ones.
  EXPECT_EQ(b.corners_Pa[VariantIndex(r, "dynamic")], b.corners_Pa[VariantIndex(r, "quasi_static")]);
  const nlohmann::json j = ValidationJson(ShippedRun());
  const nlohmann::json& s = j["sources"][4];
  EXPECT_EQ(s["static_bearing"][0]["unit"], "N/cm^2");
  EXPECT_DOUBLE_EQ(s["static_bearing"][0]["simulated"]["quasi_static"]["range"][0].get<double>(),
                   b.simulated_Pa[0].low * 1e-4);
  // The other sources' JSON carries no static_bearing key.
  EXPECT_FALSE(j["sources"][2].contains("static_bearing"));
}

TEST(ValidateShipped, JsonAndReportCarryEverySource) {
  const nlohmann::json j = ValidationJson(ShippedRun());
  ASSERT_EQ(j["sources"].size(), 5u);
  EXPECT_DOUBLE_EQ(j["dynamic_rft"]["inertial_drag_lambda"].get<double>(), 1.1);
  const nlohmann::json& kd = j["sources"][2];
  EXPECT_EQ(kd["id"], "katsuragi_durian_2007");
  const PointResult& p = SourceNamed("katsuragi_durian_2007").points[0];
  EXPECT_DOUBLE_EQ(kd["points"][0]["measured"].get<double>(), p.point->value * 1e3);
  EXPECT_DOUBLE_EQ(kd["points"][0]["simulated"]["dynamic"]["relative_error"].get<double>(), p.relative_error[1]);
  const std::string md = ValidationMarkdown(ShippedRun());
  for (const char* id : {"altshuler_2013", "ambroso_2005", "katsuragi_durian_2007", "murdoch_2017", "surveyor3_1968"})
    EXPECT_NE(md.find(std::string("### ") + id), std::string::npos);
}

class ValidateOutputs : public testing_scratch::ScratchDirTest {};

TEST_F(ValidateOutputs, WritesTheReportAndEveryPlot) {
  const std::string out = Path("out");
  WriteValidationOutputs(ShippedRun(), out);
  EXPECT_TRUE(std::filesystem::exists(out + "/validation.json"));
  EXPECT_TRUE(std::filesystem::exists(out + "/validation.md"));
  EXPECT_TRUE(std::filesystem::exists(out + "/plots/katsuragi_durian_2007_final_depth.png"));
  EXPECT_TRUE(std::filesystem::exists(out + "/plots/murdoch_2017_depth_vs_gravity.svg"));
  const nlohmann::json j = nlohmann::json::parse(Slurp(out + "/validation.json"));
  EXPECT_EQ(j["sources"].size(), 5u);
  // Trends: log ranges fitted to the values with tics inside them, the measured exponent's
  // tolerance drawn, a measured direction stated, each variant's fitted slope in the key.
  const std::string script = Slurp(out + "/plots/validation.gp");
  EXPECT_NE(script.find("set xtics ("), std::string::npos);
  EXPECT_NE(script.find("title 'measured: tolerance'"), std::string::npos);
  EXPECT_NE(script.find("measured: stop time decreases"), std::string::npos);
  EXPECT_NE(script.find("quasi static: slope "), std::string::npos);
}

}  // namespace
}  // namespace touchdown::validation

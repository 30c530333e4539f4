// Loading validation sources: the shipped ones load; a bad file names its file, field and value.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "drop_tests/validation/shallow_impact_depth.h"
#include "drop_tests/validation/validation_source.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::validation {
namespace {

const std::string kShippedSources = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/validation";

// A minimal valid source, its pad and soil taken from the shipped ones; `extra` is appended.
std::string MinimalSource(const std::string& id, const std::string& extra) {
  return "schema_version: 1\ntype: validation_source\nid: " + id +
         "\ncitation: c\nread_at: r\nprojectile:\n  pad: " + kShippedSources +
         "/pads/kd2007_steel_sphere.yaml\n  description: d\nmedium:\n  soil: " + kShippedSources +
         "/soils/kd2007_glass_beads.yaml\n  description: d\n  zeta_route: derived\ngravity_m_s2: 9.81\n" + extra;
}

const std::string kOnePoint =
    "points:\n  - {id: a, impact_speed_m_s: 1.0, quantity: final_depth, depth_mm: 20, how: quoted, where: w}\n";

class ValidationSourceLoad : public testing_scratch::ScratchDirTest {
 protected:
  // The InputError message of loading `text` as source `id`.
  std::string ErrorOf(const std::string& id, const std::string& text) {
    const std::string path = Write(id + ".yaml", text);
    try {
      LoadValidationSource(path);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      return e.what();
    }
    ADD_FAILURE() << "no InputError for " << id;
    return "";
  }
};

TEST_F(ValidationSourceLoad, ShippedSourcesLoadWithTheirNumbers) {
  const ValidationSet set = LoadValidationSet(kShippedSources);
  ASSERT_EQ(set.sources.size(), 5u);
  EXPECT_EQ(set.sources[0].id, "altshuler_2013");
  EXPECT_EQ(set.sources[1].id, "ambroso_2005");
  EXPECT_EQ(set.sources[2].id, "katsuragi_durian_2007");
  EXPECT_EQ(set.sources[3].id, "murdoch_2017");
  EXPECT_EQ(set.sources[4].id, "surveyor3_1968");
  EXPECT_DOUBLE_EQ(set.dynamic.lambda, 1.1);
  const ValidationSource& kd = set.sources[2];
  ASSERT_TRUE(kd.law.has_value());
  EXPECT_DOUBLE_EQ(kd.law->d1_m, 0.087);
  EXPECT_DOUBLE_EQ(kd.law->k_over_m_s2, 1040.0);
  EXPECT_EQ(kd.points.size(), 13u);
  EXPECT_NEAR(kd.points[0].impact_speed_m_s, std::sqrt(2 * 9.81 * 0.83), 1e-12);
  EXPECT_DOUBLE_EQ(kd.pad.mass_kg, 0.0692);
  EXPECT_TRUE(set.sources[3].low_gravity);
  EXPECT_EQ(set.sources[1].trends[1].vary, Variable::kProjectileDensity);
}

TEST_F(ValidationSourceLoad, ShallowImpactPointsAreTheLawForTheSourcesSphereAndMedium) {
  const ValidationSource s = LoadValidationSource(kShippedSources + "/ambroso_2005.yaml");
  ASSERT_TRUE(s.shallow_impact_law.has_value());
  EXPECT_FALSE(s.law.has_value());
  EXPECT_DOUBLE_EQ(s.shallow_impact_law->prefactor, 0.14);
  EXPECT_DOUBLE_EQ(s.shallow_impact_law->friction_coefficient, 0.45);
  ASSERT_EQ(s.points.size(), 5u);
  // rho_b from the pad (69.2 g, radius 12.7 mm), rho_g the soil's 1520 kg/m^3, D = 25.4 mm.
  const double rho_b = 0.0692 / (4.0 / 3.0 * std::acos(-1.0) * 0.0127 * 0.0127 * 0.0127);
  const ShallowImpactParameters law{0.14, 0.45, rho_b, 1520.0, 0.0254};
  for (const MeasuredPoint& p : s.points) {
    ASSERT_TRUE(p.drop_height_m.has_value()) << p.id;
    EXPECT_EQ(p.value, ShallowImpactDepth(law, *p.drop_height_m)) << p.id;
    EXPECT_EQ(p.uncertainty, 0.0) << p.id;
    EXPECT_EQ(p.how, Provenance::kDerivedFromMeasuredLaw) << p.id;
  }
  // h = 1 m: 63.2011 mm (the law iterated to its fixed point by hand, Python).
  EXPECT_NEAR(s.points.back().value, 0.063201080516251274, 1e-12);
}

TEST_F(ValidationSourceLoad, SurveyorsStaticBearingIsARangeOverDepthsAndDiameters) {
  const ValidationSource s = LoadValidationSource(kShippedSources + "/surveyor3_1968.yaml");
  EXPECT_TRUE(s.points.empty());
  EXPECT_TRUE(s.trends.empty());
  EXPECT_TRUE(s.low_gravity);
  EXPECT_DOUBLE_EQ(s.gravity_m_s2, 1.62);
  ASSERT_EQ(s.bearings.size(), 1u);
  const MeasuredBearing& b = s.bearings[0];
  EXPECT_DOUBLE_EQ(b.pressure_Pa.low, 2e4);  // 2 N/cm^2
  EXPECT_DOUBLE_EQ(b.pressure_Pa.high, 6e4);
  EXPECT_DOUBLE_EQ(b.depth_m.low, 0.02);
  EXPECT_DOUBLE_EQ(b.depth_m.high, 0.05);
  EXPECT_DOUBLE_EQ(b.diameter_m.low, 0.2);
  EXPECT_DOUBLE_EQ(b.diameter_m.high, 0.3);
  EXPECT_EQ(b.how, Provenance::kQuoted);
  EXPECT_EQ(s.pad.file.shape, io::PadShape::kFlat);
  EXPECT_DOUBLE_EQ(s.soil.bulk_density_kg_m3, 1500.0);
  EXPECT_EQ(s.zeta_route, ZetaRoute::kDerived);
}

TEST_F(ValidationSourceLoad, AStaticBearingNeedsAFlatPadAndRanges) {
  // The minimal source with the shipped flat disc for its sphere.
  const auto bearing = [](const std::string& id, const std::string& fields) {
    std::string text = MinimalSource(id, "static_bearing:\n  - {id: b, " + fields + "}\n");
    const std::string sphere = "kd2007_steel_sphere.yaml";
    return text.replace(text.find(sphere), sphere.size(), "surveyor_flat_disc.yaml");
  };
  const std::string good = "pressure_N_cm2: [2, 6], depth_mm: [20, 50], diameter_mm: [200, 300], how: quoted, where: w";
  EXPECT_EQ(LoadValidationSource(Write("ok.yaml", bearing("ok", good))).bearings.size(), 1u);
  // A sphere is not a bearing area.
  EXPECT_NE(ErrorOf("sphere", MinimalSource("sphere", "static_bearing:\n  - {id: b, " + good + "}\n")).find("flat"),
            std::string::npos);
  EXPECT_NE(ErrorOf("reversed", bearing("reversed", "pressure_N_cm2: [6, 2], depth_mm: [20, 50], diameter_mm: [200, "
                                                    "300], how: quoted, where: w"))
                .find("pressure_N_cm2"),
            std::string::npos);
  EXPECT_NE(ErrorOf("three", bearing("three", "pressure_N_cm2: [2, 6], depth_mm: [20, 30, 50], diameter_mm: [200, "
                                              "300], how: quoted, where: w"))
                .find("depth_mm"),
            std::string::npos);
  EXPECT_NE(ErrorOf("no_diameter", bearing("no_diameter", "pressure_N_cm2: [2, 6], depth_mm: [20, 50], how: quoted, "
                                                          "where: w"))
                .find("diameter_mm"),
            std::string::npos);
  EXPECT_NE(ErrorOf("law", bearing("law", "pressure_N_cm2: [2, 6], depth_mm: [20, 50], diameter_mm: [200, 300], "
                                          "how: derived_from_measured_law, where: w"))
                .find("how"),
            std::string::npos);
  EXPECT_NE(ErrorOf("typo", bearing("typo", good + ", width_mm: 3")).find("width_mm"), std::string::npos);
}

TEST_F(ValidationSourceLoad, AMinimalSourceLoads) {
  const ValidationSource s = LoadValidationSource(Write("tiny.yaml", MinimalSource("tiny", kOnePoint)));
  ASSERT_EQ(s.points.size(), 1u);
  EXPECT_DOUBLE_EQ(s.points[0].value, 0.020);
  EXPECT_EQ(s.zeta_route, ZetaRoute::kDerived);
}

TEST_F(ValidationSourceLoad, BadFieldsAreNamedWithTheirValue) {
  EXPECT_NE(ErrorOf("wrong_id", MinimalSource("other", kOnePoint)).find("id"), std::string::npos);
  const std::string bad_how =
      "points:\n  - {id: a, impact_speed_m_s: 1.0, quantity: final_depth, depth_mm: 20, how: guessed, where: w}\n";
  EXPECT_NE(ErrorOf("bad_how", MinimalSource("bad_how", bad_how)).find("guessed"), std::string::npos);
  const std::string bad_quantity =
      "points:\n  - {id: a, impact_speed_m_s: 1.0, quantity: crater, depth_mm: 20, how: quoted, where: w}\n";
  EXPECT_NE(ErrorOf("bad_quantity", MinimalSource("bad_quantity", bad_quantity)).find("crater"), std::string::npos);
  const std::string no_law =
      "points:\n  - {id: a, drop_height_mm: 10, quantity: final_depth, from_law: true, how: derived_from_measured_law, "
      "where: w}\n";
  EXPECT_NE(ErrorOf("no_law", MinimalSource("no_law", no_law)).find("measured_law"), std::string::npos);
  const std::string shallow = "measured_law: {kind: shallow_impact, prefactor: 0.14, friction_coefficient: 0.45, "
                              "how: quoted, where: w}\n";
  const std::string bad_kind = "measured_law: {kind: poncelet, how: quoted, where: w}\n" + kOnePoint;
  EXPECT_NE(ErrorOf("bad_kind", MinimalSource("bad_kind", bad_kind)).find("poncelet"), std::string::npos);
  const std::string law_at_speed =
      shallow + "points:\n  - {id: a, impact_speed_m_s: 1.0, quantity: final_depth, from_law: true, "
                "how: derived_from_measured_law, where: w}\n";
  EXPECT_NE(ErrorOf("law_at_speed", MinimalSource("law_at_speed", law_at_speed)).find("drop_height_mm"),
            std::string::npos);
  const std::string no_mu = "measured_law: {kind: shallow_impact, prefactor: 0.14, friction_coefficient: 0, "
                            "how: quoted, where: w}\n" + kOnePoint;
  EXPECT_NE(ErrorOf("no_mu", MinimalSource("no_mu", no_mu)).find("friction_coefficient"), std::string::npos);
  const std::string flat_trend =
      "trends:\n  - {id: t, quantity: final_depth, vary: impact_speed_m_s, values: [1, 1], exponent: 1, "
      "tolerance: 0.1, tolerance_source: stated, how: quoted, where: w}\n";
  EXPECT_NE(ErrorOf("flat_trend", MinimalSource("flat_trend", flat_trend)).find("values"), std::string::npos);
  const std::string route = MinimalSource("route", kOnePoint);
  const std::string calibrated_on_missing = std::string(route).replace(
      route.find("zeta_route: derived"), 19, "zeta_route: calibrated_on\n  calibrated_on: zz");
  EXPECT_NE(ErrorOf("route", calibrated_on_missing).find("'zz'"), std::string::npos);
  EXPECT_NE(ErrorOf("typo", MinimalSource("typo", kOnePoint + "gravity: 1\n")).find("gravity"), std::string::npos);
}

TEST_F(ValidationSourceLoad, ASetNeedsSourcesAndItsModel) {
  EXPECT_THROW(LoadValidationSet(Path("none")), InputError);
  Write("tiny.yaml", MinimalSource("tiny", kOnePoint));
  try {
    LoadValidationSet(Path(""));
    ADD_FAILURE() << "a set without dynamic_rft.yaml loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dynamic_rft.yaml"), std::string::npos) << e.what();
  }
  Write("dynamic_rft.yaml", "schema_version: 1\ntype: validation_model\ninertial_drag_lambda: -1\nsource: s\n");
  EXPECT_THROW(LoadValidationSet(Path("")), InputError);
}

}  // namespace
}  // namespace touchdown::validation

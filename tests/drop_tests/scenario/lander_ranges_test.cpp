// A lander scenario and a lander file refuse physically meaningless magnitudes at load time, each
// with the range rft/physical_limits.h gives it (the same entry a study, a drop or a pad file
// uses), and a landing has the deterministic work limit a sweep's landing has.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "lander/integ/cvode_integrator.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::scenario {
namespace {

namespace fs = std::filesystem;

// The message LoadLanderScenario gives for a scenario file with `body` (empty when it loads).
std::string ScenarioError(const std::string& body) {
  const fs::path path = fs::temp_directory_path() / ("touchdown_lander_ranges_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << "schema_version: 1\ntype: lander\nlander: sutoh2017_lander\n" << body;
  std::string message;
  try {
    LoadLanderScenario(path.string());
  } catch (const InputError& e) {
    message = e.what();
  }
  fs::remove(path);
  return message;
}

const std::string kGround = "ground: {soil: fjs1_lp}\n";
const std::string kInitial = "initial: {drop_height_m: 0.1}\n";

// The message LoadLanderSpec gives for the shipped lander with `key` (a dotted path) set to `value`.
std::string LanderError(const std::string& key, const std::string& value) {
  const std::string file = io::DataDirectory() + "/landers/sutoh2017_lander.yaml";
  YAML::Node node = YAML::Clone(io::YamlFields::LoadFile(file).node());
  const size_t dot = key.find('.');
  if (dot == std::string::npos) node[key] = YAML::Load(value);
  else node[key.substr(0, dot)][key.substr(dot + 1)] = YAML::Load(value);
  try {
    LoadLanderSpec(io::YamlFields(node, file, ""));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void ExpectRefused(const std::string& message, const std::string& field, const std::string& range) {
  EXPECT_NE(message.find(field + ": must be "), std::string::npos) << message;
  EXPECT_NE(message.find(range), std::string::npos) << message;
}

TEST(LanderRanges, ShippedLanderLoads) {
  EXPECT_EQ(LanderError("total_mass_kg", "4.3"), "");
}

TEST(LanderRanges, ScenarioMagnitudes) {
  ExpectRefused(ScenarioError("gravity_m_s2: 1e12\n" + kGround + kInitial), "gravity_m_s2", "between 1e-06 and 1000 m/s^2");
  ExpectRefused(ScenarioError(kGround + "initial: {drop_height_m: 0.1, horizontal_velocity_m_s: [1e10, 0]}\n"),
                "initial.horizontal_velocity_m_s (its magnitude)", "between 0 and 100 m/s");
  ExpectRefused(ScenarioError(kGround + "initial: {drop_height_m: 0.1, angular_rate_deg_s: [1e10, 0, 0]}\n"),
                "initial.angular_rate_deg_s[0]", "between -3600 and 3600 deg/s");
  ExpectRefused(ScenarioError("ground: {soil: fjs1_lp, height_m: 1e300}\n" + kInitial), "ground.height_m",
                "between -100 and 100 m");
  ExpectRefused(ScenarioError("ground: {soil: fjs1_lp, downhill_azimuth_deg: 1e6}\n" + kInitial),
                "ground.downhill_azimuth_deg", "between -360 and 360 deg");
  ExpectRefused(ScenarioError(kGround + "initial: {drop_height_m: 1e6}\n"), "initial.drop_height_m",
                "between 0 and 100 m");
  // A height and a gravity each in range, but a touchdown at 141 m/s.
  ExpectRefused(ScenarioError("gravity_m_s2: 100\n" + kGround + "initial: {drop_height_m: 100}\n"),
                "initial.drop_height_m (the touchdown speed it gives)", "between 0 and 100 m/s");
  ExpectRefused(ScenarioError(kGround + "initial: {drop_height_m: 0.1, release_vertical_speed_m_s: -1e9}\n"),
                "initial.release_vertical_speed_m_s", "between -100 and 100 m/s");
  ExpectRefused(ScenarioError(kGround + kInitial + "simulation: {capture_speed_m_s: 1e9}\n"),
                "simulation.capture_speed_m_s", "between 0 and 100 m/s");
  // At the bounds: loads.
  EXPECT_EQ(ScenarioError("gravity_m_s2: 1000\n" + kGround +
                          "initial: {touchdown_speed_m_s: 1, horizontal_velocity_m_s: [60, -80], "
                          "angular_rate_deg_s: [3600, -3600, 0]}\n"),
            "");
}

TEST(LanderRanges, LanderMagnitudes) {
  ExpectRefused(LanderError("total_mass_kg", "1e30"), "total_mass_kg", "between 1e-06 and 1e+06 kg");
  ExpectRefused(LanderError("cog_height_mm", "1e9"), "cog_height_mm", "between 0 and 100000 mm");
  ExpectRefused(LanderError("legs.joint_radius_mm", "1e12"), "legs.joint_radius_mm", "between 0 and 100000 mm");
  ExpectRefused(LanderError("body_inertia_kg_m2.ixx", "1e30"), "body_inertia_kg_m2.ixx", "and at most 1e+10 kg m^2");
  ExpectRefused(LanderError("legs.cone_limit", "{half_angle_deg: 500, stiffness_N_m_rad: 10}"),
                "legs.cone_limit.half_angle_deg", "and at most 180 deg");
  ExpectRefused(LanderError("legs.absorber", "{kind: spring_damper, stiffness_N_m: 1e300}"),
                "legs.absorber.stiffness_N_m", "and at most 1e+12 N/m");
  ExpectRefused(LanderError("legs.absorber", "{kind: spring_damper, stiffness_N_m: 1e4, damping_N_s_m: 1e300}"),
                "legs.absorber.damping_N_s_m", "between 0 and 1e+10 N s/m");
  ExpectRefused(LanderError("legs.load_limit_N", "-5"), "legs.load_limit_N", "N");
  ExpectRefused(LanderError("legs.load_limit_N", "1e12"), "legs.load_limit_N", "N");
  EXPECT_EQ(LanderError("legs.load_limit_N", "2500"), "") << "a limit in range loads";
}

// Legs that cannot be placed on the lander's pad (lander/multibody/leg_placement.h) are refused
// naming the lander file's key, in the block it sits in.
TEST(LanderRanges, LegsThatDoNotFitNameTheirKey) {
  std::string e = LanderError("total_mass_kg", "0.3");  // the four 80 g pads weigh 0.32 kg
  EXPECT_NE(e.find("sutoh2017_lander.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("total_mass_kg: must exceed the four pads' mass"), std::string::npos) << e;
  e = LanderError("cog_height_mm", "0.1");
  EXPECT_NE(e.find("cog_height_mm: puts the body's centre of mass below the joints"), std::string::npos) << e;
  e = LanderError("legs.hip_height_mm", "5");  // the joints are 20 mm above the pad bottoms
  EXPECT_NE(e.find("legs.hip_height_mm: must be above the ball-joint centres"), std::string::npos) << e;
}

// pad_attitude is read into an enum at load; any other word is refused, naming the field.
TEST(LanderRanges, PadAttitude) {
  EXPECT_NE(ScenarioError(kGround + "initial: {drop_height_m: 0.1, pad_attitude: tilted}\n")
                .find("initial.pad_attitude: must be 'body' or 'level', got 'tilted'"),
            std::string::npos);
  EXPECT_EQ(ScenarioError(kGround + "initial: {drop_height_m: 0.1, pad_attitude: level}\n"), "");
  LanderScenario s = test::CoarseScenario("lander_case_A");
  EXPECT_EQ(s.initial.pad_attitude, PadAttitude::kBody);  // the default
  s.initial.roll_rad = 0.1;
  s.initial.pad_attitude = PadAttitude::kLevel;
  const lander::LanderSetup level = ResolveLander(s);
  s.initial.pad_attitude = PadAttitude::kBody;
  const lander::LanderSetup body = ResolveLander(s);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    EXPECT_TRUE(level.initial.R_WP[i].isApprox(Eigen::Matrix3d::Identity(), 1e-15));
    EXPECT_TRUE(body.initial.R_WP[i].isApprox(body.initial.R_WB, 1e-15));
  }
  EXPECT_FALSE(body.initial.R_WB.isApprox(Eigen::Matrix3d::Identity(), 1e-6));
}

// The lander body's tensor is checked as a pad's is (io::ReadInertia, geom::ValidateInertia).
TEST(LanderRanges, BodyInertiaIsARigidBodys) {
  const std::string e = LanderError("body_inertia_kg_m2", "{ixx: 0.01, iyy: 0.01, izz: 0.06}");
  EXPECT_NE(e.find("body_inertia_kg_m2: is not a rigid body's inertia"), std::string::npos) << e;
  EXPECT_NE(e.find("I1 + I2 >= I3"), std::string::npos) << e;
}

TEST(LanderRanges, LandingHasTheSweepsWorkLimit) {
  LanderScenario s = test::CoarseScenario("lander_case_A");
  EXPECT_EQ(s.options.integrator.max_rhs_evaluations, limits::kDefaultMaxRunEvaluations);
  s.options.integrator.max_rhs_evaluations = 50;
  try {
    RunLanderScenario(s);
    FAIL() << "ran past the work limit";
  } catch (const integ::LimitExceeded& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("lander scenario lander_case_A (", 0), 0u) << what;
    EXPECT_NE(what.find("evaluation limit exceeded"), std::string::npos) << what;
    EXPECT_EQ(e.limit(), "max_rhs_evaluations");
  }
}

}  // namespace
}  // namespace touchdown::scenario

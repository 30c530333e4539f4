// The touchdown executable as a user meets it: JSON of one drop, a campaign's outputs, and
// every bad input answered by one line on stderr, exit status 2 and no partial output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int status = -1;
  std::string out, err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun Touchdown(const std::string& args) {
    const std::string out = (dir_ / "stdout").string(), err = (dir_ / "stderr").string();
    const std::string command = std::string(TOUCHDOWN_BINARY) + " " + args + " >" + out + " 2>" + err;
    const int raw = std::system(command.c_str());
    CliRun r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = Slurp(out);
    r.err = Slurp(err);
    return r;
  }
  static std::string Slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

TEST_F(Cli, DropPrintsJsonWithTheContractedKeys) {
  const std::string trace = (dir_ / "t.csv").string();
  const CliRun r = Touchdown("drop --pad flat --soil fjs1_lp --speed 1.0 --trace " + trace);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"final_penetration_m", "peak_force_N", "time_to_rest_s", "max_deceleration_m_s2",
                          "impact_energy_J", "dissipated_energy_J"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_NEAR(j["impact_energy_J"].get<double>(), 0.5 * 1.6 * 1.0, 1e-9);
  const std::string csv = Slurp(trace);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t_s,penetration_m,velocity_m_s,force_N");
}

// Rerunning a drop onto its own trace replaces it (a rig trace by a free one too): its first line is a
// trace header only touchdown writes. A file of the user's stays refused, and so does a trace into a
// directory that does not exist, which touchdown does not create.
TEST_F(Cli, DropReplacesItsOwnTraceButCreatesNoDirectory) {
  const std::string trace = (dir_ / "t.csv").string();
  const std::string drop = "drop --pad flat --soil fjs1_lp --speed 1.0 --trace ";
  ASSERT_EQ(Touchdown(drop + trace).status, 0);
  const CliRun again = Touchdown(drop + trace);
  EXPECT_EQ(again.status, 0) << again.err;
  const CliRun free = Touchdown(drop + trace + " --free");
  EXPECT_EQ(free.status, 0) << free.err;
  EXPECT_NE(Slurp(trace).find("force_x_N"), std::string::npos);
  const std::string mine = (dir_ / "mine.csv").string();
  { std::ofstream(mine) << "t_s,penetration_m\n"; }
  const CliRun refused = Touchdown(drop + mine);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("was not written by touchdown"), std::string::npos) << refused.err;
  const fs::path missing = dir_ / "no_such_dir" / "x.csv";
  const CliRun nowhere = Touchdown(drop + missing.string());
  EXPECT_EQ(nowhere.status, 2);
  EXPECT_NE(nowhere.err.find(missing.string() + ": directory '" + missing.parent_path().string() + "' does not exist"),
            std::string::npos)
      << nowhere.err;
  EXPECT_FALSE(fs::exists(missing.parent_path()));
}

TEST_F(Cli, ForceOfFlatPadMatchesTheClosedForm) {
  // Straight down: quasi-static zeta (pi r^2 d + 0.128 pi r d^2), the revolved mesh within 0.5 %
  // of it; with --dynamic at 1 m/s, plus the soil's dynamic term lambda rho v^2 pi r^2 on the
  // bottom face (the wall has v.n = 0).
  const CliRun r = Touchdown("force --pad flat --soil fjs1_lp --depth 0.005");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const double zeta = 3.4810783e6, radius = 0.05, d = 0.005, lambda = 1.1, rho = 1540.0, v = 1.0;
  const double quasi_static = zeta * (M_PI * radius * radius * d + 0.1284 * M_PI * radius * d * d);
  EXPECT_NEAR(j["force_N"][2].get<double>(), quasi_static, 5e-3 * quasi_static);
  EXPECT_FALSE(j["dynamic_term"].get<bool>());
  const CliRun slow = Touchdown("force --pad flat --soil fjs1_lp --depth 0.005 --velocity 0,0,-0.01");
  ASSERT_EQ(slow.status, 0) << slow.err;
  EXPECT_NEAR(nlohmann::json::parse(slow.out)["force_N"][2].get<double>(), j["force_N"][2].get<double>(),
              1e-12 * quasi_static);  // quasi-static: the speed does not matter, only the direction
  const CliRun dynamic = Touchdown("force --pad flat --soil fjs1_lp --depth 0.005 --dynamic");
  ASSERT_EQ(dynamic.status, 0) << dynamic.err;
  const nlohmann::json jd = nlohmann::json::parse(dynamic.out);
  const double closed = quasi_static + lambda * rho * v * v * M_PI * radius * radius;
  EXPECT_NEAR(jd["force_N"][2].get<double>(), closed, 5e-3 * closed);
  EXPECT_TRUE(jd["dynamic_term"].get<bool>());
  EXPECT_NEAR(j["force_N"][0].get<double>(), 0.0, 1e-9);
  EXPECT_GT(j["leading_elements"].get<int>(), 0);
  // Tilted and moving sideways: a horizontal force opposing the motion appears.
  const CliRun t = Touchdown("force --pad flat --soil fjs1_lp --depth 0.005 --tilt-deg 10 --velocity 0.5,0,-1");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_LT(nlohmann::json::parse(t.out)["force_N"][0].get<double>(), 0.0);
}

TEST_F(Cli, ForceAndDropOnABekkerSoil) {
  // The soil's own law (bekker): F = A (k_c / b + k_phi) d on the revolved flat pad's footprint.
  const CliRun r = Touchdown("force --pad flat --soil lunar_nominal_bekker --depth 0.005");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["law"], "bekker");
  const double b = j["bekker_plate_b_m"].get<double>(), d = 0.005;
  EXPECT_NEAR(b, 0.05, 0.05 * 2e-3);  // the revolved polygon's equal-area radius
  const double closed = M_PI * b * b * (1.4e3 / b + 820e3) * d;
  EXPECT_NEAR(j["force_N"][2].get<double>(), closed, 1e-9 * closed);
  // The same soil on the rig, and --law bekker asked for on it.
  const CliRun rig = Touchdown("drop --pad flat --soil lunar_nominal_bekker --speed 1 --gravity 1.62 --law bekker");
  ASSERT_EQ(rig.status, 0) << rig.err;
  EXPECT_EQ(nlohmann::json::parse(rig.out)["law"], "bekker");
}

// `force` and `drop` never print null or NaN for a number, at the edges of
// the physical ranges (rft/physical_limits.h) too; beyond them the input is refused (exit 2).
void ExpectOnlyFiniteNumbers(const nlohmann::json& v, const std::string& where) {
  EXPECT_FALSE(v.is_null()) << where;
  if (v.is_number()) {
    EXPECT_TRUE(std::isfinite(v.get<double>())) << where;
  }
  if (v.is_object())
    for (const auto& [key, x] : v.items()) ExpectOnlyFiniteNumbers(x, where + "." + key);
  if (v.is_array())
    for (size_t i = 0; i < v.size(); ++i) ExpectOnlyFiniteNumbers(v[i], where + "[" + std::to_string(i) + "]");
}

TEST_F(Cli, JsonOutputsCarryNoNullOrNaNAtTheLimits) {
  for (const std::string& args :
       {std::string("force --pad flat --soil fjs1_lp --depth 10 --tilt-deg 180 --velocity 60,0,-80 --omega 0,0,1000"),
        std::string("force --pad flat --soil fjs1_lp --depth -10 --velocity 0,0,-100"),
        std::string("force --pad hex --soil fjs1_lp --depth 0.01 --law agarwal2023 --omega 1000,0,0"),
        std::string("drop --pad flat --soil fjs1_lp --speed 100"),
        std::string("drop --pad flat --soil fjs1_lp --speed 0"),
        std::string("drop --pad flat --soil fjs1_lp --speed 2 --free --tilt-deg 30 --horizontal-speed 1")}) {
    const CliRun r = Touchdown(args);
    ASSERT_EQ(r.status, 0) << args << ": " << r.err;
    ExpectOnlyFiniteNumbers(nlohmann::json::parse(r.out), args);
  }
  for (const std::string& args : {std::string("force --pad flat --soil fjs1_lp --depth 0.01 --velocity 1e200,0,-1e200"),
                                  std::string("force --pad flat --soil fjs1_lp --depth 0.01 --omega 1e300,0,0"),
                                  std::string("drop --pad flat --soil fjs1_lp --speed 1e200")}) {
    const CliRun r = Touchdown(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

TEST_F(Cli, MassGravityAndZetaOverridesApply) {
  const CliRun base = Touchdown("drop --pad flat --soil fjs1_lp --speed 1.0");
  const CliRun heavy = Touchdown("drop --pad flat --soil fjs1_lp --speed 1.0 --mass 3.2 --zeta 4");
  ASSERT_EQ(base.status, 0);
  ASSERT_EQ(heavy.status, 0) << heavy.err;
  const auto b = nlohmann::json::parse(base.out), h = nlohmann::json::parse(heavy.out);
  EXPECT_DOUBLE_EQ(h["pad_mass_kg"].get<double>(), 3.2);
  EXPECT_NEAR(h["zeta_N_cm3"].get<double>(), 4.0, 1e-12);
  const CliRun moon = Touchdown("drop --pad flat --soil fjs1_lp --speed 1.0 --gravity 1.62");
  ASSERT_EQ(moon.status, 0) << moon.err;
  const auto m = nlohmann::json::parse(moon.out);
  EXPECT_NEAR(m["zeta_N_cm3"].get<double>(), b["zeta_N_cm3"].get<double>() * 1.62 / 9.81, 1e-9);
}

TEST_F(Cli, CampaignWritesTablesTracesPlotsAndResolvedScenario) {
  const fs::path out = dir_ / "campaign";
  const CliRun r = Touchdown(std::string("campaign ") + TOUCHDOWN_SOURCE_DIR +
                          "/data/scenarios/sutoh2017_single_footpad.yaml --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(out / "summary.csv"));
  EXPECT_TRUE(fs::is_regular_file(out / "summary.json"));
  EXPECT_TRUE(fs::is_regular_file(out / "scenario_resolved.yaml"));
  EXPECT_TRUE(fs::is_regular_file(out / "traces" / "flat_fjs1_lp_v1.00.csv"));
  for (const char* png : {"fig3_time_histories.png", "fig4_peaks.png", "fig6_force_penetration.png"}) {
    ASSERT_TRUE(fs::is_regular_file(out / "plots" / png)) << png;
    EXPECT_GT(fs::file_size(out / "plots" / png), 5000u) << png;
  }
  std::ifstream csv(out / "summary.csv");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 13);  // header + 12 drops
  EXPECT_NE(r.out.find("curved_over_flat_penetration_lp"), std::string::npos);
}

struct BadInput {
  const char* name;
  std::string args;      // may contain {dir}
  std::string expected;  // fragment of the one stderr line
};

class CliBadInput : public Cli, public ::testing::WithParamInterface<BadInput> {};

std::string Expand(std::string s, const std::string& dir) {
  for (size_t p; (p = s.find("{dir}")) != std::string::npos;) s.replace(p, 5, dir);
  return s;
}

TEST_P(CliBadInput, OneLineExitTwoNoOutput) {
  Write("bad_scenario.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [1.0, -2]}\n");
  Write("unknown_pad_scenario.yaml", "drops:\n  - {pad: hexagon, soil: fjs1_lp, impact_speeds_m_s: 1.0}\n");
  Write("malformed.yaml", "drops: [ {pad: flat\n");
  Write("zero_area_pad.yaml", "mass_kg: 1\nprofile: {shape: flat, radius_mm: 0, thickness_mm: 16}\n");
  Write("zero_area_scenario.yaml",
        "drops:\n  - {pad: " + (dir_ / "zero_area_pad.yaml").string() + ", soil: fjs1_lp, impact_speeds_m_s: 1}\n");
  const CliRun r = Touchdown(Expand(GetParam().args, dir_.string()));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(Expand(GetParam().expected, dir_.string())), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "partial output directory left behind";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"UnknownPad", "drop --pad hexagon --soil fjs1_lp --speed 1", "pads: unknown name 'hexagon'"},
        BadInput{"UnknownSoil", "drop --pad flat --soil mud --speed 1", "soils: unknown name 'mud'"},
        BadInput{"MissingPadFile", "drop --pad {dir}/nope.yaml --soil fjs1_lp --speed 1", "{dir}/nope.yaml: file not found"},
        BadInput{"NegativeSpeed", "drop --pad flat --soil fjs1_lp --speed -1",
                 "impact_speed_m_s: must be between 0 and 100 m/s, got -1"},
        BadInput{"NanSpeed", "drop --pad flat --soil fjs1_lp --speed nan", "impact_speed_m_s"},
        BadInput{"InfiniteMass", "drop --pad flat --soil fjs1_lp --speed 1 --mass inf",
                 "mass_kg: must be between 1e-06 and 1e+06 kg, got inf"},
        BadInput{"ZeroGravity", "drop --pad flat --soil fjs1_lp --speed 1 --gravity 0", "gravity_m_s2"},
        BadInput{"NegativeZeta", "drop --pad flat --soil fjs1_lp --speed 1 --zeta -3", "zeta_N_cm3"},
        BadInput{"TextSpeed", "drop --pad flat --soil fjs1_lp --speed fast", "speed"},
        BadInput{"ZeroAreaPad", "drop --pad {dir}/zero_area_pad.yaml --soil fjs1_lp --speed 1",
                 "zero_area_pad.yaml: profile.radius_mm: must be positive, got '0'"},
        BadInput{"MissingScenario", "campaign {dir}/none.yaml --out {dir}/out", "none.yaml: file not found"},
        BadInput{"MalformedScenario", "campaign {dir}/malformed.yaml --out {dir}/out", "malformed.yaml: malformed YAML"},
        BadInput{"NegativeSpeedInScenario", "campaign {dir}/bad_scenario.yaml --out {dir}/out",
                 "bad_scenario.yaml: drops[0].impact_speeds_m_s[1]: must be >= 0, got '-2'"},
        BadInput{"UnknownPadInScenario", "campaign {dir}/unknown_pad_scenario.yaml --out {dir}/out",
                 "unknown_pad_scenario.yaml: drops[0].pad: pads: unknown name 'hexagon'"},
        BadInput{"ZeroAreaPadInScenario", "campaign {dir}/zero_area_scenario.yaml --out {dir}/out",
                 "profile.radius_mm: must be positive"},
        BadInput{"MissingOut", "campaign {dir}/bad_scenario.yaml", "--out is required"},
        BadInput{"ForceBadTiltAxis", "force --pad flat --soil fjs1_lp --depth 0.01 --tilt-axis z", "tilt_axis: must be x or y"},
        BadInput{"ForceNanDepth", "force --pad flat --soil fjs1_lp --depth nan", "--depth: must be between -10 and 10 m, got nan"},
        BadInput{"ForceNoMotion", "force --pad flat --soil fjs1_lp --depth 0.01 --velocity 0,0,0",
                 "the pad must move"},
        BadInput{"ForceUnknownLaw", "force --pad flat --soil fjs1_lp --depth 0.01 --law wong", "wong"},
        BadInput{"DropBekkerOnRftSoil", "drop --pad flat --soil fjs1_lp --speed 1 --law bekker",
                 "bekker.k_phi_kN_m_n2: k_c and k_phi cannot both be 0"},
        BadInput{"CalibrateBekkerNoShear",
                 "calibrate " TOUCHDOWN_SOURCE_DIR "/data/datasets/air_vs_vacuum_synthetic --law bekker --soil fjs1_lp "
                 "--pad flat --atmosphere vacuum --out {dir}/fit.yaml",
                 "--shear-from: soil 'fjs1_lp' has no bekker block"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace

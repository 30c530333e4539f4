// The comparison metrics against closed forms, the join on drop conditions, and
// `touchdown compare` end to end on a dataset exported from a sweep (simulated vs itself).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "drop_tests/dataset/compare.h"
#include "rft/input_error.h"

namespace {

namespace fs = std::filesystem;
using namespace touchdown::dataset;

DatasetTrace Linear(double k, double d_max, int n, double t_step = 1e-3) {
  DatasetTrace t;
  for (int i = 0; i < n; ++i) {
    const double d = d_max * i / (n - 1);
    t.t_s.push_back(i * t_step);
    t.penetration_m.push_back(d);
    t.force_N.push_back(k * d);
  }
  return t;
}

TEST(CompareMetrics, IdenticalTracesGiveZero) {
  const DatasetTrace t = Linear(1e4, 0.02, 30);
  EXPECT_EQ(ForceNrmseTime(t, t).value, 0.0);
  EXPECT_EQ(ForceNrmsePenetration(t, t).value, 0.0);
  // The samples with d > 0 (1-29) but the stroke's first and last (LoadingStrokeIndices).
  EXPECT_EQ(ForceNrmsePenetration(t, t).used, 27u);
}

TEST(CompareMetrics, ConstantForceOffsetOverPeak) {
  const DatasetTrace measured = Linear(1e4, 0.02, 30);
  DatasetTrace simulated = measured;
  for (double& f : simulated.force_N) f += 7.0;
  const double peak = 1e4 * 0.02;
  EXPECT_NEAR(ForceNrmseTime(measured, simulated).value, 7.0 / peak, 1e-12);
  EXPECT_NEAR(ForceNrmsePenetration(measured, simulated).value, 7.0 / peak, 1e-12);
}

TEST(CompareMetrics, StiffnessMismatchAgainstPenetrationHasAClosedForm) {
  // F_meas = k d, F_sim = k' d on the same depths: NRMSE = |k' - k| sqrt(mean d_i^2) / (k d_max),
  // the mean over the loading stroke: samples 1 to n - 1 (d > 0) without the first and the last.
  const double k = 1e4, k_sim = 1.2e4, d_max = 0.02;
  const int n = 41;
  const DatasetTrace measured = Linear(k, d_max, n);
  const DatasetTrace simulated = Linear(k_sim, d_max, 11, 4e-3);  // coarser, still exact for a line
  double mean_sq = 0.0;
  for (int i = 2; i < n - 1; ++i) mean_sq += std::pow(d_max * i / (n - 1), 2);
  mean_sq /= (n - 3);
  EXPECT_NEAR(ForceNrmsePenetration(measured, simulated).value, (k_sim - k) * std::sqrt(mean_sq) / (k * d_max), 1e-12);
}

TEST(CompareMetrics, RestSamplesWithPenetrationNoiseAreNotPartOfTheStroke) {
  // Stroke F = k d to 20 mm, then rest (force = the weight, 5 N) with +-0.05 mm of noise on the
  // penetration, the deepest sample late in the rest. Only the stroke is compared against
  // penetration: identical strokes give 0, where the rest samples (5 N against F_sim(d) ~ 200 N)
  // would give about 0.9.
  DatasetTrace measured = Linear(1e4, 0.02, 21);
  DatasetTrace simulated = measured;
  for (int i = 0; i < 40; ++i) {
    measured.t_s.push_back(measured.t_s.back() + 1e-3);
    measured.penetration_m.push_back(0.02 + (i % 2 == 0 ? -5e-5 : (i == 35 ? 6e-5 : 4e-5)));
    measured.force_N.push_back(5.0);
  }
  const NrmseResult r = ForceNrmsePenetration(measured, simulated);
  EXPECT_EQ(r.value, 0.0);
  EXPECT_EQ(r.used, 18u);  // the stroke's samples with d > 0 (1-20) but its first and last
}

TEST(CompareMetrics, SamplesBeyondTheSimulatedStrokeAreCountedNotCompared) {
  const DatasetTrace measured = Linear(1e4, 0.02, 21);
  const DatasetTrace simulated = Linear(1e4, 0.01, 11);
  const NrmseResult r = ForceNrmsePenetration(measured, simulated);
  EXPECT_EQ(r.samples, 18u);  // samples 2-19: d > 0 without the stroke's first and last
  EXPECT_EQ(r.used, 9u);      // 2-10: d_i = i mm up to the simulated 10 mm
  EXPECT_NEAR(r.value, 0.0, 1e-12);
}

TEST(CompareMetrics, AfterTheSimulatedTraceTheForceStaysAtItsLastValue) {
  const DatasetTrace simulated = Linear(1e4, 0.01, 11);  // ends at t = 10 ms with 100 N
  DatasetTrace measured;
  measured.t_s = {0.02};
  measured.penetration_m = {0.01};
  measured.force_N = {100.0};
  EXPECT_NEAR(ForceNrmseTime(measured, simulated).value, 0.0, 1e-12);
  EXPECT_NEAR(InterpolateClamped({0.0, 1.0}, {0.0, 10.0}, 0.25), 2.5, 1e-15);
}

DatasetDrop Drop(const std::string& id, const std::string& pad, double speed) {
  DatasetDrop d;
  d.drop_id = id;
  d.pad = pad;
  d.soil = "fjs1_lp";
  d.atmosphere = touchdown::rft::Atmosphere::kVacuum;
  d.impact_speed_m_s = speed;
  d.pad_mass_kg = 1.6;
  d.gravity_m_s2 = 9.81;
  return d;
}

TEST(CompareJoin, MatchesOnConditionsAndNamesAnUnmatchedDrop) {
  Dataset measured, simulated;
  measured.drops = {Drop("m1", "flat", 1.0), Drop("m2", "curved", 0.7), Drop("m3", "flat", 1.0)};
  simulated.drops = {Drop("s1", "curved", 0.7), Drop("s2", "flat", 1.0 + 1e-12)};
  const std::vector<const DatasetDrop*> p = JoinOnConditions(measured, simulated);
  EXPECT_EQ(p[0]->drop_id, "s2");
  EXPECT_EQ(p[1]->drop_id, "s1");
  EXPECT_EQ(p[2]->drop_id, "s2");
  measured.drops.push_back(Drop("m4", "flat", 1.5));
  try {
    JoinOnConditions(measured, simulated);
    FAIL();
  } catch (const touchdown::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("drop m4"), std::string::npos) << e.what();
  }
}

TEST(CompareCli, SimulatedDatasetAgainstItselfHasZeroErrors) {
  const fs::path dir = fs::temp_directory_path() / ("touchdown_compare_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << "schema_version: 1\ntype: sweep\ntraces: full\nrest_duration_s: 0.02\n"
                                   "fixed: {soil: fjs1_lp}\ngrid: {pad: [flat, curved], impact_speed_m_s: [0.7, 1.5]}\n";
  auto run = [&](const std::string& args) {
    const std::string cmd = std::string(TOUCHDOWN_BINARY) + " " + args + " >" + (dir / "out.txt").string() + " 2>" +
                            (dir / "err.txt").string();
    const int raw = std::system(cmd.c_str());
    std::ifstream err(dir / "err.txt");
    std::stringstream s;
    s << err.rdbuf();
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << args << "\n" << s.str();
  };
  run("sweep " + (dir / "s.yaml").string() + " --out " + (dir / "sweep").string() + " --progress none");
  run("export " + (dir / "sweep").string() + " --to " + (dir / "sim").string());
  // Simulating the exported drops again (catalogue soils) and joining them both give zero error.
  // The exported traces are the simulator's own samples, values at instants: compared as such.
  run("compare " + (dir / "sim").string() + " --sensor-sampling instantaneous --out " + (dir / "cmp").string());
  run("compare " + (dir / "sim").string() + " --simulated " + (dir / "sim").string() + " --out " +
      (dir / "join").string());
  for (const char* out : {"cmp", "join"}) {
    std::ifstream in(dir / out / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["drops_compared"].get<int>(), 4) << out;
    // compare simulates at its recording rate (4 kHz under the sweep's 1 kHz traces): the same
    // drops to the integrator's tolerance; joined, the same numbers exactly.
    for (const char* key : {"final_penetration_rel_error", "peak_force_rel_error", "force_nrmse"})
      EXPECT_NEAR(j[key].get<double>(), 0.0, std::string(out) == "join" ? 1e-12 : 1e-8) << out << " " << key;
    EXPECT_TRUE(fs::is_regular_file(dir / out / "per_drop.csv"));
    EXPECT_TRUE(fs::is_regular_file(dir / out / "plots" / "compare.gp"));
    if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
      EXPECT_TRUE(fs::is_regular_file(dir / out / "plots" / "drops" / "d0.png")) << out;
      EXPECT_TRUE(fs::is_regular_file(dir / out / "plots" / "drops" / "d0.svg")) << out;  // every figure: PNG and SVG
      EXPECT_TRUE(fs::is_regular_file(dir / out / "plots" / "parity.png")) << out;
      EXPECT_TRUE(fs::is_regular_file(dir / out / "plots" / "parity.svg")) << out;
    }
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "cmp" / "simulated" / "drops.csv"));
  fs::remove_all(dir);
}

}  // namespace

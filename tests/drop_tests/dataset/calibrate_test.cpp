// Calibration recovers a known zeta. The measured data here are SYNTHETIC: drops simulated
// with a chosen zeta_true (not the soil file's), with seeded Gaussian noise added to the force,
// written in the dataset format and labelled `source = synthetic` in drops.csv.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <sys/wait.h>
#include <unistd.h>

#include "drop_tests/dataset/calibrate.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"

namespace {

namespace fs = std::filesystem;
using namespace touchdown::dataset;
using namespace touchdown::drop;
using namespace touchdown::io;
using namespace touchdown::model;
using namespace touchdown::pad;

constexpr double kZetaTrue = 5.0e6;  // N/m^3 at 9.81 m/s^2; the soil file says 3.48 N/cm^3

// Six drops (flat and curved pads at the paper's three speeds) on fjs1_lp with zeta_true; the
// force gets N(0, (noise * peak)^2) noise from a fixed seed.
Dataset SyntheticDataset(double noise, uint64_t seed, double rest_duration_s = RigDropOptions{}.rest_duration_s,
                         double depth_noise_m = 0.0) {
  std::mt19937_64 rng(seed);
  Dataset ds;
  ds.extra_columns = {"source"};
  int k = 0;
  for (const char* pad_name : {"flat", "curved"})
    for (double v : {0.7, 1.0, 1.5}) {
      DropConditions c;
      c.impact_speed_m_s = v;
      c.zeta_N_m3 = kZetaTrue;
      RigDropOptions rig;
      rig.rest_duration_s = rest_duration_s;
      const PadDrop sim = RunDrop(ResolveDrop(LoadPad(pad_name), LoadSoil("fjs1_lp"), c, {.rig = rig}));
      DatasetDrop d;
      d.drop_id = "synthetic_" + std::to_string(k++);
      d.pad = pad_name;
      d.soil = "fjs1_lp";
      d.atmosphere = touchdown::rft::Atmosphere::kVacuum;
      d.impact_speed_m_s = v;
      d.pad_mass_kg = sim.mass_kg;
      d.gravity_m_s2 = 9.81;
      d.trace_file = "traces/" + d.drop_id + ".csv";
      d.extra = {"synthetic"};
      std::normal_distribution<double> gauss(0.0, noise * sim.result.peak_force_N);
      std::normal_distribution<double> depth_gauss(0.0, depth_noise_m > 0.0 ? depth_noise_m : 1.0);
      for (const DropSample& s : sim.result.trace) {
        d.trace.t_s.push_back(s.t_s);
        d.trace.penetration_m.push_back(s.penetration_m + (depth_noise_m > 0.0 && s.penetration_m > 0.0 ? depth_gauss(rng) : 0.0));
        d.trace.force_N.push_back(s.force_N + (noise > 0 ? gauss(rng) : 0.0));
      }
      ds.drops.push_back(std::move(d));
    }
  return ds;
}

TEST(Calibrate, NoiseFreeSyntheticDataGiveZetaExactly) {
  Dataset ds = SyntheticDataset(0.0, 1);
  ds.directory = ".";
  const std::vector<ZetaFit> fits = CalibrateZeta(ds, {});
  ASSERT_EQ(fits.size(), 1u);
  // Not to rounding: fjs1_lp's dynamic term (2 % of the force at 1 m/s) is taken off with the sink
  // rate from central differences of the 1 kHz trace (8e-5 relative and 0.06 N rms measured; the
  // exact case is FactoryDrops.CalibrateRegressesOnTheFactorysRigIntegral).
  EXPECT_NEAR(fits[0].zeta_N_m3 / kZetaTrue, 1.0, 2e-4);
  EXPECT_EQ(fits[0].drops, 6);
  EXPECT_LT(fits[0].residual_rms_N, 0.2);
  EXPECT_NE(fits[0].method.find("dynamic term"), std::string::npos);
}

TEST(Calibrate, NoisySyntheticDataGiveZetaWithinTheReportedInterval) {
  Dataset ds = SyntheticDataset(0.03, 20261122);
  ds.directory = ".";
  const ZetaFit fit = CalibrateZeta(ds, {}).at(0);
  EXPECT_LE(fit.low_N_m3, kZetaTrue);
  EXPECT_GE(fit.high_N_m3, kZetaTrue);
  // Informative: the 95 % interval is within a few percent (noise 3 % of peak, hundreds of samples).
  EXPECT_LT((fit.high_N_m3 - fit.low_N_m3) / kZetaTrue, 0.05);
  EXPECT_EQ(fit.degrees_of_freedom, 5.0);  // drops as clusters
}

TEST(Calibrate, LoadingStrokeEndsWhereThePadStops) {
  // Loading to 8.2 mm, then rest at the weight (16 N) with a noisy rest sample 0.04 mm deeper.
  DatasetTrace t;
  const double d[] = {0.0, 0.002, 0.004, 0.006, 0.008, 0.0082, 0.0082, 0.00824, 0.0082};
  const double f[] = {0.0, 50.0, 110.0, 170.0, 220.0, 227.0, 16.0, 15.0, 17.0};
  for (int i = 0; i < 9; ++i) {
    t.t_s.push_back(0.001 * i);
    t.penetration_m.push_back(d[i]);
    t.force_N.push_back(f[i]);
  }
  // The stroke is samples 1-5 (d > 0, the force above half its peak); its first and last are left
  // out (astride the touchdown and the stop, an averaging sensor mixes in the free fall and the weight).
  EXPECT_EQ(LoadingStrokeIndices(t), (std::vector<size_t>{2, 3, 4}));
  // Without a fall of the force the stroke runs to the deepest sample (noise-free simulations).
  t.force_N = {0.0, 50.0, 110.0, 170.0, 220.0, 227.0, 228.0, 229.0, 230.0};
  // (samples 1-7, the deepest the last), again without the first and the last.
  EXPECT_EQ(LoadingStrokeIndices(t), (std::vector<size_t>{2, 3, 4, 5, 6}));
}

TEST(Calibrate, RestSamplesWithDepthNoiseDoNotBiasZeta) {
  // 30 ms of rest after each stop and 0.03 mm of depth noise (as the shipped synthetic dataset):
  // a rest sample is often the deepest, and the rest reaction (the weight) is not F(d).
  Dataset ds = SyntheticDataset(0.0, 7, 0.03, 3e-5);
  ds.directory = ".";
  const ZetaFit fit = CalibrateZeta(ds, {}).at(0);
  // Depth noise of 0.03 mm on 5-25 mm strokes moves zeta by well under 2 %.
  EXPECT_NEAR(fit.zeta_N_m3 / kZetaTrue, 1.0, 0.02);
}

TEST(Calibrate, OneDropFallsBackToTheIidInterval) {
  // y = 2 x +- 1 (alternating): the closed-form slope sum x y / sum x^2 and SE = s / sqrt(sum x^2).
  StrokeSamples s;
  double sxx = 0.0;
  const int n = 10;
  for (int i = 1; i <= n; ++i) {
    s.x.push_back(i);
    s.force_N.push_back(2.0 * i + (i % 2 ? 1.0 : -1.0));
    sxx += i * i;
  }
  const ZetaFit fit = FitZeta({s}, 0.95);
  double sxy = 0.0;
  for (int i = 0; i < n; ++i) sxy += s.x[i] * s.force_N[i];
  EXPECT_NEAR(fit.zeta_N_m3, sxy / sxx, 1e-12);
  double sse = 0.0;
  for (int i = 0; i < n; ++i) sse += std::pow(s.force_N[i] - fit.zeta_N_m3 * s.x[i], 2);
  EXPECT_NEAR(fit.standard_error_N_m3, std::sqrt(sse / (n - 1) / sxx), 1e-12);
  EXPECT_EQ(fit.degrees_of_freedom, n - 1.0);
  // t(0.975, 9) = 2.262157 (tables).
  EXPECT_NEAR((fit.high_N_m3 - fit.zeta_N_m3) / fit.standard_error_N_m3, 2.262157, 1e-6);
}

TEST(CalibrateCli, WritesAModelThatDropAndCompareUse) {
  const fs::path dir = fs::temp_directory_path() / ("touchdown_calibrate_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  WriteDataset(SyntheticDataset(0.02, 7), (dir / "measured").string());
  auto run = [&](const std::string& args) {
    const std::string cmd = std::string(TOUCHDOWN_BINARY) + " " + args + " >" + (dir / "out.txt").string() + " 2>" +
                            (dir / "err.txt").string();
    const int raw = std::system(cmd.c_str());
    std::ifstream out(dir / "out.txt"), err(dir / "err.txt");
    std::stringstream s;
    s << out.rdbuf() << err.rdbuf();
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << args << "\n" << s.str();
    return s.str();
  };
  run("calibrate " + (dir / "measured").string() + " --param zeta --per soil --out " + (dir / "model.yaml").string());
  const ModelFile model = LoadModelFile((dir / "model.yaml").string());
  const SoilOverride& o = model.soils.at("fjs1_lp");
  EXPECT_LE(*o.zeta_low_N_m3, kZetaTrue);
  EXPECT_GE(*o.zeta_high_N_m3, kZetaTrue);
  ASSERT_TRUE(o.fit.has_value());
  EXPECT_EQ(o.fit->drops, 6);
  // `drop --model` runs with the calibrated zeta.
  const std::string drop = run("drop --pad flat --soil fjs1_lp --speed 1.0 --model " + (dir / "model.yaml").string());
  const nlohmann::json j = nlohmann::json::parse(drop);
  EXPECT_NEAR(j["zeta_N_cm3"].get<double>(), o.zeta_N_m3 / 1e6, 1e-9);
  // compare with the model: what is left is the noise, 2 % of each drop's peak force. The synthetic
  // traces are values at instants, so compare records its simulations so.
  run("compare " + (dir / "measured").string() + " --sensor-sampling instantaneous --model " + (dir / "model.yaml").string() + " --out " +
      (dir / "cmp").string());
  std::ifstream in(dir / "cmp" / "summary.json");
  const nlohmann::json c = nlohmann::json::parse(in);
  EXPECT_NEAR(c["force_nrmse"].get<double>(), 0.02, 0.004);
  EXPECT_LT(c["final_penetration_rel_error"].get<double>(), 0.01);
  fs::remove_all(dir);
}

// `calibrate --report R.json` on a dataset: each soil's zeta with its variance in the schema
// `calibrate --targets --report` writes, so a stability study's soil_uncertainty draws from it (a
// one-landing study of the coarse lander reads it back: mean and sigma as the fit reported them).
TEST(CalibrateCli, ReportHoldsEachSoilsZetaAndVarianceForAStudyToDraw) {
  const fs::path dir = fs::temp_directory_path() / ("touchdown_calibrate_report_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  WriteDataset(SyntheticDataset(0.02, 7), (dir / "measured").string());
  auto run = [&](const std::string& args, int expected) {
    const std::string cmd = std::string(TOUCHDOWN_BINARY) + " " + args + " >" + (dir / "out.txt").string() + " 2>" +
                            (dir / "err.txt").string();
    const int raw = std::system(cmd.c_str());
    // Each stream read on its own: inserting an empty file's buffer fails the stream it goes into.
    std::string text;
    for (const char* name : {"out.txt", "err.txt"}) {
      std::ifstream f(dir / name);
      text += std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == expected) << args << "\n" << text;
    return text;
  };
  const std::string measured = (dir / "measured").string(), model = (dir / "model.yaml").string(),
                    report = (dir / "report.json").string();
  run("calibrate " + measured + " --out " + model + " --report " + report, 0);
  std::ifstream in(report);
  const nlohmann::json r = nlohmann::json::parse(in);
  const nlohmann::json& fit = r["fits"][0];
  ASSERT_EQ(r["covariance"]["parameters"].size(), 1u);
  const nlohmann::json& p = r["covariance"]["parameters"][0];
  EXPECT_EQ(p["soil"], "fjs1_lp");
  EXPECT_EQ(p["kind"], "soil_zeta");
  EXPECT_EQ(p["value"].get<double>(), fit["zeta_N_cm3"].get<double>());
  const double se = fit["standard_error_N_cm3"].get<double>();
  EXPECT_GT(se, 0.0);
  EXPECT_EQ(r["covariance"]["matrix"][0][0].get<double>(), se * se);
  // The model file holds zeta to 10 significant digits, the report the fit's double.
  EXPECT_NEAR(LoadModelFile(model).soils.at("fjs1_lp").zeta_N_m3 / 1e6, fit["zeta_N_cm3"].get<double>(),
              1e-9 * fit["zeta_N_cm3"].get<double>());
  EXPECT_NE(r["command"].get<std::string>().find("--report " + report), std::string::npos);
  // A rerun may replace its own report; a user's file, the model file itself and --per all are refused.
  run("calibrate " + measured + " --out " + model + " --report " + report, 0);
  std::ofstream(dir / "mine.json") << "{}\n";
  EXPECT_NE(run("calibrate " + measured + " --out " + model + " --report " + (dir / "mine.json").string(), 2).find("mine.json"),
            std::string::npos);
  EXPECT_NE(run("calibrate " + measured + " --out " + model + " --report " + model, 2).find("--report"), std::string::npos);
  EXPECT_NE(run("calibrate " + measured + " --out " + model + " --per all --report " + report, 2).find("--per soil"),
            std::string::npos);
  // The study draws fjs1_lp's zeta from it.
  std::ofstream(dir / "study.yaml") << "schema_version: 1\ntype: stability\nname: drawn\nlander: {scenario: "
                                    << TOUCHDOWN_SOURCE_DIR << "/data/studies/lab_coarse_lander_scenario.yaml}\n"
                                    << "random: {samples: 1, seed: 1, slope_deg: {uniform: [0, 1]}}\n"
                                    << "study: {recheck: none, joint_range_sensitivity: none, soil_uncertainty: "
                                    << "{fjs1_lp: {calibration: report.json}}}\n";
  run("stability " + (dir / "study.yaml").string() + " --out " + (dir / "study").string() + " --progress none", 0);
  std::ifstream summary_in(dir / "study" / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_in);
  const nlohmann::json& drawn = summary["soil_uncertainty"]["parameters"][0];
  EXPECT_EQ(drawn["soil"], "fjs1_lp");
  EXPECT_EQ(drawn["mean"].get<double>(), p["value"].get<double>());
  EXPECT_NEAR(drawn["sigma"].get<double>(), se, 1e-15 * se);
  fs::remove_all(dir);
}

}  // namespace

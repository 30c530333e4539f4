// A model file's effect terms in every simulation that reads it: rig drops (drop, sweep,
// compare), the free pad and the lander (3D contact: every effect's 3D form), and the model.yaml `diagnose` writes,
// round-tripped through `drop` and `compare` (with its fit record's residual).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "drop_tests/dataset/compare.h"
#include "drop_tests/gap/diagnose.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/model/contact_model.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/dataset/sensor_sampling.h"
#include "drop_tests/dataset/synth.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::model {
namespace {

namespace fs = std::filesystem;

class ModelEffects : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_model_effects_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A model file with the given `effects:` body (YAML flow mapping).
  std::string Model(const std::string& name, const std::string& effects) {
    const fs::path p = dir_ / (name + ".yaml");
    std::ofstream(p) << "schema_version: 1\ntype: model\nname: " << name << "\neffects: " << effects << "\n";
    return p.string();
  }
  static std::string Slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // Runs the touchdown binary; returns the exit status, stdout and stderr.
  int Touchdown(const std::string& args, std::string* out, std::string* err = nullptr) {
    const fs::path o = dir_ / "stdout", e = dir_ / "stderr";
    const int raw = std::system((std::string(TOUCHDOWN_BINARY) + " " + args + " >" + o.string() + " 2>" + e.string()).c_str());
    *out = Slurp(o);
    if (err) *err = Slurp(e);
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  }

  // A rig drop of `pad` on loose FJS-1 at 1.2 m/s in `atmosphere`, under the model at `path`.
  static drop::PadDrop RigDrop(const std::string& path, const std::string& atmosphere = "air", const std::string& pad = "flat") {
    drop::DropConditions c;
    c.impact_speed_m_s = 1.2;
    c.atmosphere = rft::ParseAtmosphere(atmosphere);
    rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
    // The effects are defined on top of quasi-static RFT; the soil's own dynamic term (the shipped
    // lambda 1.1) is tested in DropFactory.SoilsDynamicTermIsInertialDragOnRigAndFreePad.
    soil.dynamic_term = false;
    if (!path.empty()) {
      const ModelFile m = LoadModelFile(path);
      soil = ApplyModel(m, soil);
      c.effects = ModelEffectTerms(m);
      c.effects_source = path;
    }
    return RunDrop(ResolveDrop(io::LoadPad(pad), soil, c));
  }

  fs::path dir_;
};

TEST_F(ModelEffects, EachEffectChangesTheRigDropTheWayItsFormSays) {
  const drop::PadDrop base = RigDrop(""), base_vacuum = RigDrop("", "vacuum");
  const double d0 = base.result.final_penetration_m;
  // The force 1 ms after touchdown: speed terms (and the compaction transient) show there.
  const double f0 = base.result.trace[1].force_N;
  struct Case {
    const char* effects;
    int depth;  // -1 shallower, +1 deeper than quasi-static RFT
    bool higher_early_force;
  };
  for (const Case& c : {Case{"{inertial_drag: {lambda: 3}}", -1, true}, Case{"{rate_damping: {c_N_s_m3: 20000}}", -1, true},
                        Case{"{added_mass: {c_a: 3}}", -1, false}, Case{"{compaction_peak: {k_c_kg_m3: 30000, d_c_mm: 3}}", -1, true},
                        Case{"{depth_exponent: {p: 1.4}}", +1, false}, Case{"{gas_cushion: {chi: 0.3, c_g_N_s_m3: 0}}", +1, false}}) {
    const drop::PadDrop d = RigDrop(Model("m", c.effects));
    const double depth = d.result.final_penetration_m;
    if (c.depth < 0) {
      EXPECT_LT(depth, 0.98 * d0) << c.effects;
    } else {
      EXPECT_GT(depth, 1.02 * d0) << c.effects;
    }
    if (c.higher_early_force) {
      EXPECT_GT(d.result.trace[1].force_N, 1.05 * f0) << c.effects;
    }
  }
  // The gas cushion acts in air only: a vacuum drop is exactly quasi-static RFT.
  const drop::PadDrop vacuum = RigDrop(Model("gas", "{gas_cushion: {chi: 0.3, c_g_N_s_m3: 8000}}"), "vacuum");
  EXPECT_EQ(vacuum.result.final_penetration_m, base_vacuum.result.final_penetration_m);
  const nlohmann::json j = drop::SummaryJson(vacuum);
  EXPECT_TRUE(j["effects"].empty()) << j.dump();
  EXPECT_TRUE(j["effects_not_applied"].contains("gas_cushion")) << j.dump();
  // The sensor offset is a measurement effect: the simulated drop is the true one.
  const drop::PadDrop sensor = RigDrop(Model("sensor", "{sensor_offset: {dz_mm: 1, dt_ms: 2}}"));
  EXPECT_EQ(sensor.result.final_penetration_m, d0);
  EXPECT_TRUE(drop::SummaryJson(sensor)["effects_not_applied"].contains("sensor_offset"));
}

TEST_F(ModelEffects, NeutralParametersReproduceTheBaseDropExactly) {
  const std::string neutral = Model(
      "neutral",
      "{inertial_drag: {lambda: 0}, rate_damping: {c_N_s_m3: 0}, added_mass: {c_a: 0}, added_mass_plug: {c_p: 0}, "
      "compaction_peak: {k_c_kg_m3: 0, d_c_mm: 3}, depth_exponent: {p: 1}, gas_cushion: {chi: 0, c_g_N_s_m3: 0}, "
      "sensor_offset: {dz_mm: 0, dt_ms: 0}}");
  EXPECT_TRUE(ActiveEffects(ModelEffectTerms(LoadModelFile(neutral))).empty());
  for (const char* pad : {"flat", "curved"}) {
    const pad::RigDropResult a = RigDrop("", "air", pad).result, b = RigDrop(neutral, "air", pad).result;
    ASSERT_EQ(a.trace.size(), b.trace.size()) << pad;
    for (size_t i = 0; i < a.trace.size(); ++i) {
      EXPECT_EQ(a.trace[i].penetration_m, b.trace[i].penetration_m) << pad << " sample " << i;
      EXPECT_EQ(a.trace[i].force_N, b.trace[i].force_N) << pad << " sample " << i;
    }
  }
}

TEST_F(ModelEffects, FreeVerticalDropWithEffectsMatchesTheRigDrop) {
  // A level pad dropped straight down as a free body is the rig drop with the 3D contact: each
  // effect's 3D form reduces to the rig's form - inertial_drag (the dynamic term) and rate_damping
  // on the bottom face (the rig's I3 and I2 on the profile), compaction_peak (k_c (v.n)^2 per
  // element x exp(-z_pad/d_c): the rig's k_c v^2 exp(-d/d_c) I3), depth_exponent (z^p integrated
  // exactly per triangle: the rig's exact power law per profile piece) and added_mass (the cone on
  // the footprint, the rig's m_a(d), on the pad's vertical inertia; force as the load cell reads it;
  // added_mass_plug likewise).
  // The shipped soil's own dynamic term (lambda 1.1) acts in both, hence "+dynamic" in every law.
  struct Case {
    const char* name;
    const char* effects;
    const char* pad;
    const char* law;
  };
  const Case cases[] = {
      {"drag", "{inertial_drag: {lambda: 2}, rate_damping: {c_N_s_m3: 15000}}", "flat", "li2013+dynamic+rate_damping"},
      {"compaction", "{compaction_peak: {k_c_kg_m3: 30000, d_c_mm: 3}}", "flat", "li2013+dynamic+compaction_peak"},
      {"depth", "{depth_exponent: {p: 1.4}}", "flat", "li2013+dynamic+depth_exponent"},
      {"depth_curved", "{depth_exponent: {p: 0.7}}", "curved", "li2013+dynamic+depth_exponent"},
      {"mass", "{added_mass: {c_a: 3}}", "flat", "li2013+dynamic+added_mass"},
      {"mass_curved", "{added_mass: {c_a: 3}}", "curved", "li2013+dynamic+added_mass"},
      {"plug", "{added_mass_plug: {c_p: 1}}", "flat", "li2013+dynamic+added_mass_plug"},
      {"plug_curved", "{added_mass_plug: {c_p: 1}}", "curved", "li2013+dynamic+added_mass_plug"},
  };
  for (const Case& k : cases) {
    const std::string model = Model(k.name, k.effects);
    const ModelFile m = LoadModelFile(model);
    const io::PadSpec pad = io::LoadPad(k.pad);
    const rft::SoilParameters soil = ApplyModel(m, io::LoadSoil("fjs1_lp"));
    drop::DropConditions c;
    c.impact_speed_m_s = 1.0;
    c.effects = ModelEffectTerms(m);
    c.effects_source = model;
    const drop::PadDrop rig = RunDrop(ResolveDrop(pad, soil, c));
    c.free = true;
    const drop::PadDrop free = drop::RunDrop(drop::ResolveDrop(pad, soil, c));
    ASSERT_TRUE(free.free.has_value()) << k.name;
    EXPECT_EQ(free.contact_model, k.law);
    // The peak force read from the solution (vertical_peaks.h), not from the samples: a
    // compaction peak or a plug is largest just after first contact, which the rig records at
    // t = 0+ and the free pad, starting a hair above the surface, between its samples.
    auto stroke_peak = [](const drop::PadDrop& p) { return p.result.peak_force_N; };
    const double d = rig.result.final_penetration_m, f = stroke_peak(rig);
    drop::DropConditions plain = c;
    plain.effects = {};
    plain.free = false;
    const drop::PadDrop base = RunDrop(ResolveDrop(pad, soil, plain));
    std::printf("[ free vs rig ] %-12s %-6s depth %.5f / %.5f mm (%+.3f %%), peak %.2f / %.2f N (%+.3f %%); "
                "without the effect %.5f mm, %.2f N\n",
                k.name, k.pad, 1e3 * free.result.final_penetration_m, 1e3 * d,
                100 * (free.result.final_penetration_m / d - 1), stroke_peak(free), f,
                100 * (stroke_peak(free) / f - 1), 1e3 * base.result.final_penetration_m, stroke_peak(base));
    EXPECT_NEAR(free.result.final_penetration_m, d, 5e-3 * d) << k.name;
    EXPECT_NEAR(stroke_peak(free), f, 5e-3 * f) << k.name;
    // The effect acts: the drop differs from quasi-static RFT by well over the tolerance.
    EXPECT_GT(std::abs(d / base.result.final_penetration_m - 1) + std::abs(f / stroke_peak(base) - 1), 0.03)
        << k.name;
  }
}

// Every effect of the library runs on free drops and landers; neutral parameters change nothing.
TEST_F(ModelEffects, EveryEffectRunsOnFreeDropsAndLanders) {
  const io::PadSpec pad = io::LoadPad("curved");
  scenario::LanderScenario base_scenario = test::CoarseScenario("lander_case_A");
  const scenario::LanderRun base = scenario::RunLanderScenario(base_scenario);
  ASSERT_TRUE(base.result.rest_time_s.has_value());
  for (const char* effects : {"{added_mass: {c_a: 1}}", "{compaction_peak: {k_c_kg_m3: 30000, d_c_mm: 2}}",
                              "{depth_exponent: {p: 1.2}}"}) {
    const std::string path = Model("effect", effects);
    const ModelFile m = LoadModelFile(path);
    drop::DropConditions c;
    c.impact_speed_m_s = 1.0;
    c.free = true;
    // (Tilted free drops take 20-60 s here; the rotating contact path of each term is checked in
    // tests/rft/pad_effect_terms_test.cpp.)
    c.effects = ModelEffectTerms(m);
    c.effects_source = path;
    const auto t0 = std::chrono::steady_clock::now();
    const drop::PadDrop d = drop::RunDrop(drop::ResolveDrop(pad, io::LoadSoil("fjs1_lp"), c));
    const auto t1 = std::chrono::steady_clock::now();
    ASSERT_TRUE(d.free.has_value());
    EXPECT_GT(d.result.final_penetration_m, 0.0) << effects;
    // Energy closes with the effect (the accretion loss counts as dissipated).
    const pad::FreeDropResult& r = *d.free;
    EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, r.impact_energy_J + r.gravity_work_J,
                1e-4 * r.impact_energy_J)
        << effects;
    scenario::LanderScenario s = base_scenario;
    s.model = m;
    const scenario::LanderRun run = scenario::RunLanderScenario(s);
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("[ timing ] %s: free drop %.2f s, lander %.2f s\n", effects,
                std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count());
    ASSERT_TRUE(run.result.rest_time_s.has_value()) << effects;
    std::printf("[ lander case A ] %-48s pad 1 depth %.4f mm (base %.4f mm), peak pad force %.2f N (base %.2f N)\n",
                effects, 1e3 * run.result.final_penetration_m[0], 1e3 * base.result.final_penetration_m[0],
                run.result.peak_pad_force_N[0], base.result.peak_pad_force_N[0]);
    EXPECT_NE(run.result.final_penetration_m[0], base.result.final_penetration_m[0]) << effects;
    for (int i = 1; i < 4; ++i)
      EXPECT_NEAR(run.result.final_penetration_m[i], run.result.final_penetration_m[0],
                  1e-6 * run.result.final_penetration_m[0])
          << effects;
  }
  // Neutral parameters: the lander run is bit-identical to the base.
  scenario::LanderScenario s = base_scenario;
  s.model = LoadModelFile(Model("neutral", "{added_mass: {c_a: 0}, compaction_peak: {k_c_kg_m3: 0, d_c_mm: 3}, "
                                           "depth_exponent: {p: 1}}"));
  const scenario::LanderRun neutral = scenario::RunLanderScenario(s);
  ASSERT_EQ(neutral.result.trace.size(), base.result.trace.size());
  for (size_t i = 0; i < base.result.trace.size(); ++i) {
    EXPECT_EQ(neutral.result.trace[i].p_WB, base.result.trace[i].p_WB) << i;
    for (int j = 0; j < 4; ++j) EXPECT_EQ(neutral.result.trace[i].pad_force_W[j], base.result.trace[i].pad_force_W[j]);
  }
  EXPECT_EQ(neutral.result.final_penetration_m, base.result.final_penetration_m);
  // The CLI: a free drop under each model runs (exit 0).
  std::string out, err;
  EXPECT_EQ(Touchdown("drop --pad flat --soil fjs1_lp --speed 1 --free --model " + Model("am", "{added_mass: {c_a: 1}}"),
                      &out, &err),
            0)
      << err;
  EXPECT_NE(out.find("added_mass"), std::string::npos) << out;
}

TEST_F(ModelEffects, LanderSoilsCarryTheModelsTerms) {
  scenario::LanderScenario s = scenario::LoadLanderScenario(std::string(TOUCHDOWN_SOURCE_DIR) + "/data/scenarios/lander_case_A.yaml");
  s.model = LoadModelFile(Model("lander", "{inertial_drag: {lambda: 1.5}, sensor_offset: {dz_mm: 1, dt_ms: 0}}"));
  const lander::LanderSetup setup = scenario::ResolveLander(s);
  ASSERT_EQ(setup.terrain.soils.size(), 1u);
  EXPECT_EQ(setup.terrain.soils[0].contact.name(), "li2013+dynamic");
  const Eigen::Vector3d down(0, 0, -1);
  EXPECT_NEAR(setup.terrain.soils[0].contact.law->DynamicStress(down, 2.0 * down).z(),
              1.5 * io::LoadSoil("fjs1_lp").bulk_density_kg_m3 * 4.0, 1e-9);
  // gas_cushion only where the bed is in air (fjs1_lp is a vacuum bed).
  s.model = LoadModelFile(Model("gas", "{gas_cushion: {chi: 0.3, c_g_N_s_m3: 5000}}"));
  EXPECT_EQ(scenario::ResolveLander(s).terrain.soils[0].contact.name(), "li2013+dynamic");  // the soil's own term
  rft::SoilParameters air = io::LoadSoil("fjs1_lp");
  air.atmosphere = rft::Atmosphere::kAir;
  EXPECT_EQ(MakeContactModel({.law = rft::LawKind::kLi2013, .soil = air, .gravity_m_s2 = 9.81, .model = &*s.model}).name(),
            "li2013+dynamic+gas_cushion");
}

// compare --model with a sensor_offset: the simulated traces are shifted as the rig records them
// (time by -dt, penetration by +dz), so a noise-free record with that offset hidden is matched,
// from either sensor when compare records the simulation through the same one.
TEST_F(ModelEffects, CompareAppliesTheSensorOffsetToTheSimulatedTraces) {
  for (const pad::SensorSampling sampling : {pad::SensorSampling::kInstantaneous, pad::SensorSampling::kPeriodMean}) {
    SCOPED_TRACE(dataset::SensorSamplingName(sampling));
    dataset::SynthSpec spec;
    spec.name = "offset";
    spec.source = "offset.yaml";
    spec.rest_duration_s = 0.01;
    spec.sensor_sampling = sampling;
    for (double v : {0.8, 1.4}) spec.drops.push_back({"flat", "fjs1_lp", rft::Atmosphere::kVacuum, v, std::nullopt, 9.81, 0});
    spec.noise = dataset::SynthNoise{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    spec.hidden_effect = Effect{"sensor_offset", {0.001, 0.004}};
    dataset::Dataset measured = dataset::Synthesize(spec);
    measured.directory = dir_.string();
    const std::string model_path = Model("offset", "{sensor_offset: {dz_mm: 1, dt_ms: 4}}");
    auto compared = [&](const std::optional<ModelFile>& model) {
      const dataset::Dataset simulated = dataset::SimulateMeasuredDrops(measured, model, sampling);
      std::vector<const dataset::DatasetDrop*> partners;
      for (const dataset::DatasetDrop& s : simulated.drops) partners.push_back(&s);
      return CompareDrops(measured, partners);
    };
    const dataset::Comparison with = compared(LoadModelFile(model_path)), without = compared(std::nullopt);
    std::printf("[ sensor offset, %s ] force NRMSE %.2e with the offset, %.2e without; depth error %.2e / %.2e\n",
                dataset::SensorSamplingName(sampling), with.force_nrmse, without.force_nrmse,
                with.final_penetration_rel_error, without.final_penetration_rel_error);
    EXPECT_LT(with.force_nrmse, 5e-3);
    EXPECT_GT(without.force_nrmse, 10 * with.force_nrmse);
    EXPECT_LT(with.final_penetration_rel_error, 1e-3);
    EXPECT_GT(without.final_penetration_rel_error, 0.05);
  }
}

// diagnose on a small synthetic dataset with hidden rate damping writes DIR/model.yaml; that
// file drives `drop` and `compare` to the diagnosis's own numbers, and its fit record carries the
// fitted model's force residual in newtons.
TEST_F(ModelEffects, DiagnosedModelFileRoundTripsThroughDropAndCompare) {
  dataset::SynthSpec spec;
  spec.name = "roundtrip";
  spec.source = "roundtrip.yaml";
  spec.seed = 5;
  spec.rest_duration_s = 0.008;
  for (rft::Atmosphere atm : {rft::Atmosphere::kAir, rft::Atmosphere::kVacuum})
    for (double v : {0.8, 1.2, 1.6}) spec.drops.push_back({"flat", "fjs1_lp", atm, v, std::nullopt, 9.81, 0});
  spec.noise = dataset::SynthNoise{0.5, 1e-5, 1.0, 2e-5, 0.1, 5e-6};
  spec.hidden_effect = Effect{"rate_damping", {15000.0}};
  dataset::Dataset ds = dataset::Synthesize(spec);
  ds.directory = (dir_ / "measured").string();
  dataset::WriteDataset(ds, ds.directory);
  const dataset::Dataset measured = dataset::ReadDataset(ds.directory);
  gap::DiagnoseOptions o;
  o.threads = 2;
  o.permutations = 100;
  o.try_pairs = false;
  // compare records its drops through a given sampling and with no per-drop nuisances: so does the
  // diagnosis that its numbers are checked against here.
  o.sensor_sampling = pad::SensorSampling::kPeriodMean;
  o.drop_nuisances = false;
  const gap::Diagnosis d = gap::RunDiagnosis(measured, o);
  ASSERT_EQ(d.named_effect, "rate_damping") << d.decision;
  gap::WriteDiagnosis(d, measured, (dir_ / "diagnosis").string());
  const std::string model_path = (dir_ / "diagnosis" / "model.yaml").string();
  const ModelFile model = LoadModelFile(model_path);
  const gap::CandidateScore& w = d.candidates[d.winner];

  // The per-drop gap figure explains its "made worse" mark only when a drop was made worse.
  bool any_worse = false;
  for (size_t i = 0; i < w.gaps.size(); ++i) any_worse = any_worse || w.gaps[i].force_nrmse > d.base.gaps[i].force_nrmse;
  const std::string script = Slurp(dir_ / "diagnosis" / "plots" / "diagnose.gp");
  EXPECT_EQ(script.find("title 'made worse by the effect'") != std::string::npos, any_worse);

  // drop --model: the CLI's drop is the in-process drop under the fitted model, to the last bit.
  std::string out;
  ASSERT_EQ(Touchdown("drop --pad flat --soil fjs1_lp --speed 1.2 --model " + model_path, &out), 0);
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j["effects"], nlohmann::json::array({"rate_damping"}));
  drop::DropConditions c;
  c.impact_speed_m_s = 1.2;
  c.effects = ModelEffectTerms(model);
  const drop::PadDrop in_process = RunDrop(ResolveDrop(io::LoadPad("flat"), ApplyModel(model, io::LoadSoil("fjs1_lp")), c));
  EXPECT_EQ(j["final_penetration_m"].get<double>(), in_process.result.final_penetration_m);
  EXPECT_NEAR(c.effects.damping_c_N_s_m3, w.fit.effects[0].values[0], 1e-6 * w.fit.effects[0].values[0]);

  // compare --model: per drop the force NRMSE of the diagnosis's augmented model.
  const dataset::Dataset simulated = dataset::SimulateMeasuredDrops(measured, model, *o.sensor_sampling);
  std::vector<const dataset::DatasetDrop*> partners;
  for (const dataset::DatasetDrop& s : simulated.drops) partners.push_back(&s);
  const dataset::Comparison cmp = CompareDrops(measured, partners);
  double held = 0.0, n_held = 0.0;
  for (size_t i = 0; i < d.problem.drops.size(); ++i) {
    EXPECT_NEAR(cmp.drops[d.problem.drops[i].dataset_index].force_nrmse_time.value, w.gaps[i].force_nrmse,
                0.02 * w.gaps[i].force_nrmse + 1e-4)
        << d.problem.drops[i].drop_id;
    if (!d.problem.drops[i].train) held += cmp.drops[d.problem.drops[i].dataset_index].force_nrmse_time.value, n_held += 1;
  }
  EXPECT_NEAR(held / n_held, w.held_out.force_nrmse, 0.02 * w.held_out.force_nrmse);

  // fit.residual_rms_N: the fitted model's force residual over the training samples, in newtons,
  // recomputed here from compare's simulated traces.
  const SoilOverride& o_lp = model.soils.at("fjs1_lp");
  ASSERT_TRUE(o_lp.fit.has_value());
  double sum = 0.0;
  long samples = 0;
  for (const gap::FitDrop& f : d.problem.drops) {
    if (!f.train) continue;
    const dataset::DatasetTrace& m = measured.drops[f.dataset_index].trace;
    const dataset::DatasetTrace& s = simulated.drops[f.dataset_index].trace;
    for (size_t i = 0; i < m.size(); ++i) {
      const double f_sim = m.t_s[i] < s.t_s.front() ? 0.0 : dataset::InterpolateClamped(s.t_s, s.force_N, m.t_s[i]);
      sum += (f_sim - m.force_N[i]) * (f_sim - m.force_N[i]);
      ++samples;
    }
  }
  const double rms = std::sqrt(sum / samples);
  std::printf("[ residual ] fit.residual_rms_N %.4f N (recomputed %.4f N) over %ld samples; load-cell noise 0.5 N\n",
              o_lp.fit->residual_rms_N, rms, o_lp.fit->samples);
  EXPECT_EQ(o_lp.fit->samples, samples);
  EXPECT_GT(o_lp.fit->residual_rms_N, 0.0);
  EXPECT_NEAR(o_lp.fit->residual_rms_N, rms, 0.03 * rms);
  EXPECT_NEAR(o_lp.fit->residual_rms_N, w.fit.residual_rms_N[0], 1e-6 * rms);
}

}  // namespace
}  // namespace touchdown::model

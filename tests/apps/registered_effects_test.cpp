// Every registered effect (rft/effects/, one file each) held to the library's contract, so that a
// new effect needs only its own file, its own closed-form test (tests/rft/effects/) and its docs
// rows: it is in the library, its docs rows stand in docs/model_gap.md, neutral values change
// nothing, its 3D form gives the rig's force for a level pad dropped straight down, and it runs in
// the lander, in `synth` and as a candidate of `diagnose`. Each effect is tried at its parameters'
// fitting starts (EffectParameter::start, typical magnitudes).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "drop_tests/dataset/synth.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/gap/diagnose_fit.h"
#include "drop_tests/model/effects.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "rft/effects/effect_definition.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::model {
namespace {

namespace fs = std::filesystem;

class RegisteredEffectsContract : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_registered_effects_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A model file holding effect `e` at `values` (SI), written as a user writes it (file units).
  ModelFile Model(const rft::EffectDefinition& e, const std::vector<double>& values) {
    std::ostringstream body;
    body << "schema_version: 1\ntype: model\nname: m\neffects:\n  " << e.id << ": {";
    for (size_t k = 0; k < values.size(); ++k)
      body << (k ? ", " : "") << e.parameters[k].key << ": " << values[k] / e.parameters[k].file_to_si;
    body << "}\n";
    const fs::path p = dir_ / (e.id + ".yaml");
    std::ofstream(p) << body.str();
    return LoadModelFile(p.string());
  }
  static std::vector<double> Starts(const rft::EffectDefinition& e) {
    std::vector<double> v;
    for (const rft::EffectParameter& p : e.parameters) v.push_back(p.start);
    return v;
  }
  static std::vector<double> Neutral(const rft::EffectDefinition& e) {
    std::vector<double> v;
    for (const rft::EffectParameter& p : e.parameters) v.push_back(p.neutral);
    return v;
  }
  // A drop of `pad` on loose FJS-1 at 1.2 m/s in air under `m` (none: quasi-static RFT with the
  // soil's own dynamic term off), on the rig or as a free body.
  static drop::PadDrop Drop(const ModelFile* m, const std::string& pad, bool free = false) {
    drop::DropConditions c;
    c.impact_speed_m_s = 1.2;
    c.atmosphere = rft::Atmosphere::kAir;
    c.free = free;
    rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
    soil.dynamic_term = false;
    if (m) {
      c.effects = ModelEffectTerms(*m);
      c.effects_source = m->source;
    }
    return drop::RunDrop(drop::ResolveDrop(io::LoadPad(pad), soil, c));
  }

  fs::path dir_;
};

TEST_F(RegisteredEffectsContract, EachIsInTheLibraryWithItsDocsRows) {
  ASSERT_FALSE(rft::RegisteredEffects().empty());
  std::ifstream in(std::string(TOUCHDOWN_SOURCE_DIR) + "/docs/model_gap.md");
  std::stringstream docs;
  docs << in.rdbuf();
  for (const rft::EffectDefinition& e : rft::RegisteredEffects()) {
    const EffectInfo& info = FindEffect(e.id);
    EXPECT_EQ(info.registered, &e);
    EXPECT_EQ(info.parameters.size(), e.parameters.size());
    EXPECT_NE(docs.str().find(e.docs_rig_row + "\n"), std::string::npos) << "docs/model_gap.md lacks " << e.docs_rig_row;
    EXPECT_NE(docs.str().find(e.docs_3d_row + "\n"), std::string::npos) << "docs/model_gap.md lacks " << e.docs_3d_row;
    // Out of range in a model file: refused at load, naming the parameter.
    std::vector<double> bad = Starts(e);
    bad[0] = e.parameters[0].lower - std::max(1.0, std::abs(e.parameters[0].lower));
    EXPECT_THROW(Model(e, bad), InputError) << e.id;
  }
}

TEST_F(RegisteredEffectsContract, NeutralValuesReproduceTheBaseDropExactly) {
  for (const rft::EffectDefinition& e : rft::RegisteredEffects()) {
    const ModelFile m = Model(e, Neutral(e));
    EXPECT_TRUE(ActiveEffects(ModelEffectTerms(m)).empty()) << e.id;
    for (const char* pad : {"flat", "curved"}) {
      const pad::RigDropResult a = Drop(nullptr, pad).result, b = Drop(&m, pad).result;
      ASSERT_EQ(a.trace.size(), b.trace.size()) << e.id << " " << pad;
      for (size_t i = 0; i < a.trace.size(); ++i) {
        EXPECT_EQ(a.trace[i].penetration_m, b.trace[i].penetration_m) << e.id << " " << pad << " sample " << i;
        EXPECT_EQ(a.trace[i].force_N, b.trace[i].force_N) << e.id << " " << pad << " sample " << i;
      }
    }
  }
}

// A level pad dropped straight down as a free body is the rig drop with the 3D contact: each
// registered effect's element stress, summed over the pad's triangles, is its rig form.
TEST_F(RegisteredEffectsContract, TheFreeVerticalDropIsTheRigDrop) {
  for (const rft::EffectDefinition& e : rft::RegisteredEffects()) {
    const ModelFile m = Model(e, Starts(e));
    for (const char* pad : {"flat", "curved"}) {
      const drop::PadDrop rig = Drop(&m, pad), free = Drop(&m, pad, true), base = Drop(nullptr, pad);
      ASSERT_TRUE(free.free.has_value());
      EXPECT_NE(free.contact_model.find(e.id), std::string::npos) << free.contact_model;
      const double d = rig.result.final_penetration_m, f = rig.result.peak_force_N;
      std::printf("[ free vs rig ] %-10s %-6s depth %.5f / %.5f mm (%+.3f %%), peak %.2f / %.2f N; without it "
                  "%.5f mm, %.2f N\n",
                  e.id.c_str(), pad, 1e3 * free.result.final_penetration_m, 1e3 * d,
                  100 * (free.result.final_penetration_m / d - 1), free.result.peak_force_N, f,
                  1e3 * base.result.final_penetration_m, base.result.peak_force_N);
      EXPECT_NEAR(free.result.final_penetration_m, d, 5e-3 * d) << e.id << " " << pad;
      EXPECT_NEAR(free.result.peak_force_N, f, 5e-3 * f) << e.id << " " << pad;
      // At its typical magnitude the effect acts: well over the tolerance above.
      EXPECT_GT(std::abs(d / base.result.final_penetration_m - 1) + std::abs(f / base.result.peak_force_N - 1), 0.03)
          << e.id << " " << pad;
    }
  }
}

// The lander (its four pads alike on level ground), `synth` (a hidden effect) and `diagnose` (a
// candidate, with the library's range) take every registered effect.
TEST_F(RegisteredEffectsContract, RunsInTheLanderSynthAndDiagnose) {
  const scenario::LanderScenario base_scenario = test::CoarseScenario("lander_case_A");
  const scenario::LanderRun base = scenario::RunLanderScenario(base_scenario);
  for (const rft::EffectDefinition& e : rft::RegisteredEffects()) {
    scenario::LanderScenario s = base_scenario;
    s.model = Model(e, Starts(e));
    const scenario::LanderRun run = scenario::RunLanderScenario(s);
    ASSERT_TRUE(run.result.rest_time_s.has_value()) << e.id;
    EXPECT_NE(run.result.final_penetration_m[0], base.result.final_penetration_m[0]) << e.id;
    for (int i = 1; i < 4; ++i)
      EXPECT_NEAR(run.result.final_penetration_m[i], run.result.final_penetration_m[0],
                  1e-6 * run.result.final_penetration_m[0])
          << e.id;

    dataset::SynthSpec spec;
    spec.name = "hidden_" + e.id;
    for (double v : {0.8, 1.4}) spec.drops.push_back({"flat", "fjs1_lp", rft::Atmosphere::kAir, v, std::nullopt, 9.81, 0});
    spec.noise = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // noiseless: the effect alone tells the sets apart
    dataset::SynthSpec plain = spec;
    spec.hidden_effect = Effect{e.id, Starts(e)};
    const dataset::Dataset hidden = dataset::Synthesize(spec), none = dataset::Synthesize(plain);
    ASSERT_EQ(hidden.drops.size(), 2u);
    EXPECT_NE(hidden.drops[0].trace.penetration_m.back(), none.drops[0].trace.penetration_m.back()) << e.id;

    const gap::FitProblem p = gap::MakeFitProblem(hidden, std::vector<bool>(hidden.drops.size(), false), 1);
    const gap::CandidateTerm& t = gap::FindTerm(p, e.id);
    EXPECT_EQ(t.effect, FindEffect(e.id).kind);
    EXPECT_EQ(t.parameters.size(), e.parameters.size());
  }
}

}  // namespace
}  // namespace touchdown::model

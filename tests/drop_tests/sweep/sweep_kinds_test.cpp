// The kinds of sweep drop beyond the rig: free 6-DOF pads (non-zero tilt or horizontal speed),
// lander scenarios with swept parameters, and model effects acting on sweep drops - each stored
// in results.sqlite with its own columns, reproducible, and exported where it is a pad drop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "drop_tests/sweep/sweep_export.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "rft/units.h"

namespace touchdown::sweep {
namespace {

namespace fs = std::filesystem;

// The flat pad revolved with 8 segments: tilted free drops take milliseconds, not seconds.
const char* kCoarseFlat = R"(schema_version: 1
name: coarse_flat
kind: axisymmetric
mass_kg: 1.6
angular_segments: 8
profile: {shape: flat, radius_mm: 50, thickness_mm: 16}
)";

class SweepKinds : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_sweep_kinds_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    Write("coarse_flat.yaml", kCoarseFlat);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  static SweepRunOptions Quiet(int threads) {
    SweepRunOptions o;
    o.threads = threads;
    o.progress = ProgressMode::kNone;
    return o;
  }
  fs::path dir_;
};

TEST_F(SweepKinds, TiltAndHorizontalSpeedRunFreeDropsWithTheirOwnColumns) {
  const std::string file = Write("free.yaml", R"(schema_version: 1
type: sweep
name: free
traces: decimated
trace_max_samples: 16
fixed: {pad: coarse_flat.yaml, soil: fjs1_lp, impact_speed_m_s: 1.0}
grid: {tilt_deg: [0, 2], horizontal_speed_m_s: [0, 0.1]}
)");
  const SweepPlan plan = LoadSweepPlan(file);
  ASSERT_EQ(plan.size(), 4);
  RunSweep(plan, (dir_ / "out").string(), Quiet(2));
  const std::vector<DropRecord> records = ResultsDb(ResultsDbPath((dir_ / "out").string())).ReadAll(true);
  ASSERT_EQ(records.size(), 4u);
  for (const DropRecord& r : records) {
    ASSERT_TRUE(r.ok) << r.drop_id << ": " << r.failure;
    const bool free = r.tilt_deg != 0.0 || r.horizontal_speed_m_s != 0.0;
    EXPECT_EQ(r.kind, free ? DropKind::kFree : DropKind::kRig) << r.drop_id;
    EXPECT_GT(r.final_penetration_m, 0.0);
    EXPECT_GE(r.trace.size(), 3u);
    if (!free) {
      EXPECT_EQ(r.final_tilt_deg, 0.0);
      EXPECT_EQ(r.horizontal_travel_m, 0.0);
    }
    if (r.horizontal_speed_m_s > 0.0) {
      EXPECT_GT(r.horizontal_travel_m, 1e-4) << r.drop_id;
    }
    if (r.tilt_deg > 0.0) {
      EXPECT_GT(r.final_tilt_deg, 0.0) << r.drop_id;
      EXPECT_LT(r.final_tilt_deg, 2.0) << r.drop_id;  // the soil levels a landing pad
    }
    EXPECT_TRUE(std::isnan(r.final_roll_deg));  // lander columns stay empty
  }
  // The free drop is the one `touchdown drop --free` runs, to the last bit.
  const DropRecord& tilted = records[2];  // tilt 2, horizontal 0
  ASSERT_EQ(tilted.tilt_deg, 2.0);
  drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  c.tilt_rad = 2.0 * units::kDeg;
  const drop::PadDrop direct = drop::RunDrop(drop::ResolveDrop(plan.pads[0], plan.soils[0], c));
  EXPECT_EQ(direct.result.final_penetration_m, tilted.final_penetration_m);
  EXPECT_EQ(direct.free->final_tilt_deg, tilted.final_tilt_deg);
  // Any thread count gives the same records.
  const std::vector<DropRecord> one = RunSweepInMemory(plan, 1);
  for (size_t i = 0; i < one.size(); ++i) EXPECT_TRUE(SameRecord(one[i], records[i])) << i;
  // Export: the extra columns, read back identical.
  ExportSweep((dir_ / "out").string(), (dir_ / "dataset").string(), {});
  const dataset::Dataset back = dataset::ReadDataset((dir_ / "dataset").string());
  ASSERT_EQ(back.drops.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(*back.ExtraNumber(back.drops[i], "final_tilt_deg"), records[i].final_tilt_deg);
    EXPECT_EQ(*back.ExtraNumber(back.drops[i], "horizontal_travel_m"), records[i].horizontal_travel_m);
    EXPECT_EQ(*back.ExtraNumber(back.drops[i], "tilt_deg"), records[i].tilt_deg);
  }
}

TEST_F(SweepKinds, ModelEffectsActOnSweepDrops) {
  // The model's lambda 4 replaces the soil's own dynamic term (lambda 1.1).
  Write("drag.yaml", "schema_version: 1\ntype: model\neffects: {inertial_drag: {lambda: 4}}\n");
  const std::string sweep = R"(schema_version: 1
type: sweep
traces: none
fixed: {pad: flat, soil: fjs1_lp}
grid: {impact_speed_m_s: [0.8, 1.2]}
)";
  const SweepPlan with = LoadSweepPlan(Write("with.yaml", sweep + "model: drag.yaml\n"));
  const SweepPlan without = LoadSweepPlan(Write("without.yaml", sweep));
  EXPECT_NE(PlanDigest(with), PlanDigest(without));
  const std::vector<DropRecord> a = RunSweepInMemory(with, 1), b = RunSweepInMemory(without, 1);
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(a[i].ok && b[i].ok);
    EXPECT_LT(a[i].final_penetration_m, 0.97 * b[i].final_penetration_m) << i;
    drop::DropConditions c;
    c.impact_speed_m_s = a[i].impact_speed_m_s;
    c.effects.inertial_lambda = 4.0;
    pad::RigDropOptions rig;
    rig.rest_duration_s = 0.0;  // a sweep's default: summaries only
    EXPECT_EQ(drop::RunDrop(drop::ResolveDrop(io::LoadPad("flat"), io::LoadSoil("fjs1_lp"), c, {.rig = rig})).result.final_penetration_m,
              a[i].final_penetration_m);
  }
  // Every effect has a 3D form: a model with added mass loads for rig and tilted (free) sweeps alike.
  Write("mass.yaml", "schema_version: 1\ntype: model\neffects: {added_mass: {c_a: 1}}\n");
  EXPECT_NO_THROW(LoadSweepPlan(Write("rig_only.yaml", sweep + "model: mass.yaml\n")));
  EXPECT_NO_THROW(
      LoadSweepPlan(Write("tilted.yaml", sweep + "model: mass.yaml\nrandom: {samples: 2, seed: 1, tilt_deg: {uniform: [0, 3]}}\n")));
}

TEST_F(SweepKinds, LanderSweepRecordsTheLanderSummary) {
  const std::string file = Write("lander.yaml", std::string(R"(schema_version: 1
type: sweep
name: lander_speeds
lander: {scenario: )") + TOUCHDOWN_SOURCE_DIR + R"(/data/scenarios/lander_case_A.yaml}
grid: {impact_speed_m_s: [1.0, 1.4]}
)");
  SweepPlan plan = LoadSweepPlan(file);
  ASSERT_TRUE(plan.lander.has_value());
  EXPECT_EQ(plan.traces, TraceStorage::kNone);
  ASSERT_EQ(plan.size(), 2);
  test::CoarsenPad(*plan.lander);  // a few hundred triangles per pad: the test stays fast
  RunSweep(plan, (dir_ / "out").string(), Quiet(2));
  const std::vector<DropRecord> records = ResultsDb(ResultsDbPath((dir_ / "out").string())).ReadAll(false);
  ASSERT_EQ(records.size(), 2u);
  for (const DropRecord& r : records) {
    ASSERT_TRUE(r.ok) << r.drop_id << ": " << r.failure;
    EXPECT_EQ(r.kind, DropKind::kLander);
    EXPECT_EQ(r.soil, "fjs1_lp");
    EXPECT_EQ(r.tipped_over, 0.0);
    EXPECT_NEAR(r.final_roll_deg, 0.0, 1e-6);
    EXPECT_NEAR(r.final_pitch_deg, 0.0, 1e-6);
    EXPECT_EQ(r.roll_deg, 0.0);
    for (double d : r.pad_final_penetration_m) EXPECT_NEAR(d, r.pad_final_penetration_m[0], 1e-9);
    EXPECT_GT(r.pad_final_penetration_m[0], 1e-3);
    // The drop's penetration is its deepest pad's (the four agree to 1e-9 m, not bit for bit).
    EXPECT_EQ(r.final_penetration_m,
              *std::max_element(r.pad_final_penetration_m.begin(), r.pad_final_penetration_m.end()));
    EXPECT_GT(r.impact_energy_J, 0.0);
    EXPECT_GT(r.time_to_rest_s, 0.0);
  }
  EXPECT_EQ(records[0].impact_speed_m_s, 1.0);
  EXPECT_GT(records[1].final_penetration_m, records[0].final_penetration_m);  // faster: deeper
  // The impact energy is the whole lander's kinetic energy at touchdown: M v^2 / 2.
  EXPECT_NEAR(records[1].impact_energy_J, 0.5 * plan.lander->lander.total_mass_kg * 1.4 * 1.4, 1e-3);
  // Stored and recomputed records agree bit for bit; export refuses a lander sweep.
  const std::vector<DropRecord> again = RunSweepInMemory(plan, 1);
  for (size_t i = 0; i < 2; ++i) EXPECT_TRUE(SameRecord(again[i], records[i], false)) << i;
  EXPECT_THROW(SweepToDataset((dir_ / "out").string(), {}), InputError);
  // The MPI message format carries the lander columns.
  const std::vector<DropRecord> sent = DeserializeRecords(SerializeRecords(records));
  for (size_t i = 0; i < 2; ++i) EXPECT_TRUE(SameRecord(sent[i], records[i])) << i;
}

TEST_F(SweepKinds, LanderSweepParametersReachTheScenario) {
  const std::string file = Write("lander.yaml", std::string(R"(schema_version: 1
type: sweep
lander: {scenario: )") + TOUCHDOWN_SOURCE_DIR + R"(/data/scenarios/lander_case_A.yaml}
fixed: {pitch_deg: 2, roll_deg: -1, gravity_m_s2: 1.62, horizontal_speed_m_s: 0.3, soil: fjs1_cp}
)");
  const SweepPlan plan = LoadSweepPlan(file);
  const SweepDropParams p = plan.DropAt(0);
  EXPECT_NEAR(p.pitch_rad, 2.0 * units::kDeg, 1e-15);
  EXPECT_TRUE(p.Given(SweepParam::kRoll));
  EXPECT_FALSE(p.Given(SweepParam::kImpactSpeed));  // the scenario's drop height stays
  EXPECT_EQ(plan.soils.at(0).name, "fjs1_cp");
  // A model with any effect of the library runs a lander: accepted at load, its soils carry it.
  Write("mass.yaml", "schema_version: 1\ntype: model\neffects: {added_mass: {c_a: 1}}\n");
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const SweepPlan with_model = LoadSweepPlan(Write("with_model.yaml", text + "model: mass.yaml\n"));
  ASSERT_TRUE(with_model.lander.has_value());
  EXPECT_EQ(scenario::ResolveLander(*with_model.lander).terrain.soils.at(0).contact.name(), "li2013+dynamic+added_mass");
}

}  // namespace
}  // namespace touchdown::sweep

// Sweep drops the earlier sweeps left out: mesh pads (every drop a free 6-DOF drop, also straight
// down) through sweep, export, compare and calibrate (its 3D force as the regressor), and lander sweeps over the soil under each
// pad (`pad_soils`: the paper's Table II ground cases or four soils), recorded per pad in the
// results database and in `export`.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unistd.h>

#include "drop_tests/dataset/calibrate.h"
#include "drop_tests/dataset/compare.h"
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "drop_tests/sweep/sweep_export.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::sweep {
namespace {

namespace fs = std::filesystem;

// The sample hex pad without its remeshing: the 24-triangle prism, so a drop takes milliseconds.
std::string CoarseHex() {
  return std::string(R"(schema_version: 1
name: coarse_hex
kind: mesh
mesh: {file: )") + TOUCHDOWN_SOURCE_DIR + R"(/data/pads/meshes/hex_pad.stl, unit: mm}
mass_kg: 1.6
reference_point_mm: [0, 0, 16]
)";
}

class SweepDrop : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_sweep_drop_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    Write("coarse_hex.yaml", CoarseHex());
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string Out(const std::string& name) const { return (dir_ / name).string(); }
  static SweepRunOptions Quiet(int threads) {
    SweepRunOptions o;
    o.threads = threads;
    o.progress = ProgressMode::kNone;
    return o;
  }
  // The message of the InputError LoadSweepPlan throws for `text` ("" if it accepts it).
  std::string Refusal(const std::string& text) {
    try {
      LoadSweepPlan(Write("bad.yaml", text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

std::string LanderSweep(const std::string& body) {
  return std::string("schema_version: 1\ntype: sweep\nname: pad_soils\nlander: {scenario: ") + TOUCHDOWN_SOURCE_DIR +
         "/data/scenarios/lander_case_A.yaml}\n" + body;
}

TEST_F(SweepDrop, MeshPadsRunAsFreeDropsStraightDown) {
  const std::string file = Write("mesh.yaml", R"(schema_version: 1
type: sweep
name: mesh_pads
traces: decimated
fixed: {soil: fjs1_lp, gravity_m_s2: 9.81}
grid: {pad: [coarse_hex.yaml, flat], impact_speed_m_s: [1.0]}
)");
  const SweepPlan plan = LoadSweepPlan(file);
  ASSERT_EQ(plan.size(), 2);
  RunSweep(plan, Out("out"), Quiet(2));
  const std::vector<DropRecord> records = ResultsDb(ResultsDbPath(Out("out"))).ReadAll(true);
  ASSERT_EQ(records.size(), 2u);
  const DropRecord& hex = records[0];
  const DropRecord& flat = records[1];
  ASSERT_TRUE(hex.ok) << hex.failure;
  ASSERT_TRUE(flat.ok) << flat.failure;
  EXPECT_EQ(hex.pad, "coarse_hex");
  EXPECT_EQ(hex.kind, DropKind::kFree);  // no profile for the rig: the free pad
  EXPECT_EQ(flat.kind, DropKind::kRig);
  // Level and straight down: it stays level and does not travel (symmetric prism, 1e-9 of a degree / metre).
  EXPECT_NEAR(hex.final_tilt_deg, 0.0, 1e-9);
  EXPECT_NEAR(hex.horizontal_travel_m, 0.0, 1e-9);
  EXPECT_EQ(hex.tilt_deg, 0.0);
  EXPECT_GT(hex.final_penetration_m, 1e-3);
  EXPECT_FALSE(hex.trace.empty());
  // The hexagon (3 sqrt(3)/2 R^2) has 17 % less bottom area than the circle of the same radius: deeper.
  EXPECT_GT(hex.final_penetration_m, flat.final_penetration_m);
  // Exactly the free drop `touchdown drop --free` runs, and the same for any number of threads.
  drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  c.free = true;
  drop::DropRunOptions o;
  o.free.integrator.max_wall_time_s = kDefaultMaxDropWallTimeS;
  const drop::PadDrop direct = drop::RunDrop(drop::ResolveDrop(plan.pads[0], plan.soils[0], c, o));
  EXPECT_EQ(direct.result.final_penetration_m, hex.final_penetration_m);
  EXPECT_EQ(direct.result.peak_force_N, hex.peak_force_N);
  const std::vector<DropRecord> again = RunSweepInMemory(plan, 1);
  for (size_t i = 0; i < 2; ++i) EXPECT_TRUE(SameRecord(again[i], records[i])) << i;

  // Export (full traces simulated again and checked against the stored summaries), then the
  // exported dataset through compare --model (the mesh row simulated as a free drop) ...
  ExportOptions full;
  full.full_traces = true;
  const ExportSummary s = ExportSweep(Out("out"), Out("dataset"), full);
  EXPECT_EQ(s.exported, 2);
  EXPECT_EQ(s.resimulated, 2);
  const dataset::Dataset ds = dataset::ReadDataset(Out("dataset"));
  ASSERT_EQ(ds.drops.size(), 2u);
  EXPECT_EQ(ds.drops[0].pad, fs::absolute(dir_ / "coarse_hex.yaml").string());
  const dataset::Dataset sim = dataset::SimulateMeasuredDrops(ds, std::nullopt, pad::SensorSampling::kInstantaneous);
  ASSERT_EQ(sim.drops.size(), 2u);
  // compare simulates at its recording rate (dataset::RecordingSimulationRate_Hz: 4 kHz under these
  // 1 kHz traces), the sweep at 1 kHz: the same drop, to the integrator's tolerance.
  EXPECT_NEAR(*sim.drops[0].final_penetration_m, hex.final_penetration_m, 1e-6 * hex.final_penetration_m);
  EXPECT_NEAR(*sim.drops[1].final_penetration_m, flat.final_penetration_m, 1e-6 * flat.final_penetration_m);
  // ... and calibrate: the mesh pad's regressor is its 3D force straight down, so the simulated
  // drops (the soil file's zeta) give that zeta back, from both pads. Noise-free, but the soil's
  // dynamic term (2 % of the force) is taken off with the sink rate from central differences of
  // the 1 kHz trace: 7e-5 relative measured, 2e-4 allowed.
  const std::vector<dataset::ZetaFit> fits = dataset::CalibrateZeta(ds, {});
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_EQ(fits[0].drops, 2);
  EXPECT_NEAR(fits[0].zeta_N_m3 / plan.soils[0].zeta_N_m3, 1.0, 2e-4);
  dataset::Dataset hex_only = ds;
  hex_only.drops.resize(1);
  EXPECT_NEAR(dataset::CalibrateZeta(hex_only, {}).at(0).zeta_N_m3 / plan.soils[0].zeta_N_m3, 1.0, 2e-4);
}

TEST_F(SweepDrop, MeshPadSweepAppliesEveryModelEffectInItsFreeDrops) {
  // added_mass has a 3D form: the mesh pad's free drop carries the entrained grains, which
  // change its stroke; the axisymmetric pad's rig drop takes the same effect.
  Write("mass.yaml", "schema_version: 1\ntype: model\neffects: {added_mass: {c_a: 1}}\n");
  auto run = [&](const std::string& name, const std::string& model_line) {
    const SweepPlan plan = LoadSweepPlan(Write("sweep_" + name + ".yaml", "schema_version: 1\ntype: sweep\n" + model_line +
                                                                   "fixed: {soil: fjs1_lp, impact_speed_m_s: 1.0}\n"
                                                                   "grid: {pad: [flat, coarse_hex.yaml]}\n"));
    RunSweep(plan, Out(name), Quiet(1));
    return ResultsDb(ResultsDbPath(Out(name))).ReadAll(false);
  };
  const std::vector<DropRecord> base = run("base", "");
  const std::vector<DropRecord> mass = run("mass", "model: mass.yaml\n");
  ASSERT_EQ(base.size(), 2u);
  ASSERT_EQ(mass.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(base[i].ok) << base[i].failure;
    ASSERT_TRUE(mass[i].ok) << mass[i].failure;
    EXPECT_EQ(base[i].pad, mass[i].pad);
    EXPECT_NE(base[i].final_penetration_m, mass[i].final_penetration_m) << base[i].pad;
  }
  EXPECT_EQ(mass[1].kind, DropKind::kFree);
}

TEST_F(SweepDrop, PadSoilsTakeTableIICasesOrFourSoils) {
  const SweepPlan plan = LoadSweepPlan(
      Write("cases.yaml", LanderSweep("grid: {pad_soils: [A, B, C, [fjs1_lp, fjs1_lp, fjs1_cp, fjs1_cp]]}\n")));
  ASSERT_EQ(plan.size(), 4);
  ASSERT_EQ(plan.pad_soil_sets.size(), 4u);
  EXPECT_EQ(plan.pad_patch_half_width_m, 0.08);  // case A has no patch of its own: the shipped scenarios' size
  auto names = [&](int set) {
    std::string s;
    for (int i : plan.pad_soil_sets[set].soil) s += plan.soils[i].name + " ";
    return s;
  };
  EXPECT_EQ(plan.pad_soil_sets[0].label, "A");
  EXPECT_EQ(names(0), "fjs1_lp fjs1_lp fjs1_lp fjs1_lp ");
  EXPECT_EQ(plan.pad_soil_sets[1].label, "B");
  EXPECT_EQ(names(1), "fjs1_cp fjs1_lp fjs1_lp fjs1_lp ");
  EXPECT_EQ(plan.pad_soil_sets[2].label, "C");
  EXPECT_EQ(names(2), "fjs1_cp fjs1_cp fjs1_lp fjs1_lp ");
  EXPECT_EQ(plan.pad_soil_sets[3].label, "");
  EXPECT_EQ(names(3), "fjs1_lp fjs1_lp fjs1_cp fjs1_cp ");
  for (int64_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(plan.DropAt(i).Given(SweepParam::kPadSoils));
    EXPECT_EQ(plan.DropAt(i).pad_soils, i);
  }
  // A random choice and a fixed value take the same forms; the half width may be given.
  const SweepPlan random = LoadSweepPlan(Write(
      "random.yaml", "schema_version: 1\ntype: sweep\nlander: {scenario: lander_case_B, pad_patch_half_width_m: 0.05}\n"
                     "random: {samples: 8, seed: 3, pad_soils: {choice: [A, C]}}\n"));
  EXPECT_EQ(random.pad_patch_half_width_m, 0.05);
  EXPECT_EQ(random.pad_soil_sets.size(), 2u);
  EXPECT_EQ(LoadSweepPlan(Write("fixed.yaml", LanderSweep("fixed: {pad_soils: [fjs1_cp, fjs1_cp, fjs1_cp, fjs1_lp]}\n")))
                .pad_soil_sets.size(),
            1u);

  // Refused at load, naming the file, the field and the value.
  std::string m = Refusal(LanderSweep("grid: {pad_soils: [A, D]}\n"));
  EXPECT_NE(m.find("bad.yaml: grid.pad_soils[1]: "), std::string::npos) << m;
  EXPECT_NE(m.find("Table II (A, B or C)"), std::string::npos) << m;
  EXPECT_NE(m.find("'D'"), std::string::npos) << m;
  m = Refusal(LanderSweep("grid: {pad_soils: [[fjs1_cp, fjs1_lp, fjs1_lp]]}\n"));
  EXPECT_NE(m.find("grid.pad_soils[0]: "), std::string::npos) << m;
  EXPECT_NE(m.find("four soils"), std::string::npos) << m;
  m = Refusal(LanderSweep("grid: {pad_soils: [[fjs1_cp, fjs1_lp, nosuchsoil, fjs1_lp]]}\n"));
  EXPECT_NE(m.find("grid.pad_soils[0][2]: "), std::string::npos) << m;
  EXPECT_NE(m.find("nosuchsoil"), std::string::npos) << m;
  m = Refusal(LanderSweep("fixed: {soil: fjs1_cp}\ngrid: {pad_soils: [A, B]}\n"));
  EXPECT_NE(m.find("grid.pad_soils: "), std::string::npos) << m;
  EXPECT_NE(m.find("exclude each other"), std::string::npos) << m;
  m = Refusal(LanderSweep("random: {samples: 2, seed: 1, pad_soils: {uniform: [0, 1]}}\n"));
  EXPECT_NE(m.find("random.pad_soils.uniform: "), std::string::npos) << m;
  m = Refusal("schema_version: 1\ntype: sweep\nfixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1}\n"
              "grid: {pad_soils: [A, B]}\n");
  EXPECT_NE(m.find("grid.pad_soils: a lander parameter"), std::string::npos) << m;
  m = Refusal(std::string("schema_version: 1\ntype: sweep\nlander: {scenario: lander_case_A, "
                          "pad_patch_half_width_m: -1}\ngrid: {pad_soils: [A]}\n"));
  EXPECT_NE(m.find("lander.pad_patch_half_width_m: "), std::string::npos) << m;
}

TEST_F(SweepDrop, PadSoilsReachTheGroundAndAreRecordedAndExported) {
  // Short runs: coarse pads, released just above the ground at 1.4 m/s, 40 ms simulated (the
  // stroke; an asymmetric lander then rocks for seconds).
  SweepPlan plan = LoadSweepPlan(Write(
      "cases.yaml", LanderSweep("fixed: {impact_speed_m_s: 1.4}\ngrid: {pad_soils: [A, B, [fjs1_lp, fjs1_lp, fjs1_cp, fjs1_lp]]}\n")));
  test::CoarsenPad(*plan.lander);
  plan.lander->options.duration_s = 0.04;
  RunSweep(plan, Out("out"), Quiet(2));
  const std::vector<DropRecord> records = ResultsDb(ResultsDbPath(Out("out"))).ReadAll(false);
  ASSERT_EQ(records.size(), 3u);
  for (const DropRecord& r : records) ASSERT_TRUE(r.ok) << r.drop_id << ": " << r.failure;
  using Soils = std::array<std::string, 4>;
  EXPECT_EQ(records[0].pad_soil, (Soils{"fjs1_lp", "fjs1_lp", "fjs1_lp", "fjs1_lp"}));
  EXPECT_EQ(records[0].ground_case, "A");
  EXPECT_EQ(records[1].pad_soil, (Soils{"fjs1_cp", "fjs1_lp", "fjs1_lp", "fjs1_lp"}));
  EXPECT_EQ(records[1].ground_case, "B");
  EXPECT_EQ(records[2].pad_soil, (Soils{"fjs1_lp", "fjs1_lp", "fjs1_cp", "fjs1_lp"}));
  EXPECT_EQ(records[2].ground_case, "");
  for (const DropRecord& r : records) EXPECT_EQ(r.soil, "fjs1_lp");  // the ground's own soil around the patches

  // Case B from the sweep is the scenario lander_case_B under the same conditions, bit for bit.
  scenario::LanderScenario b = test::CoarseScenario("lander_case_B");
  b.options.duration_s = 0.04;
  b.initial.drop_height_m.reset();
  b.initial.touchdown_speed_m_s = 1.4;
  const scenario::LanderRun run = scenario::RunLanderScenario(b);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(records[1].pad_final_penetration_m[i], run.result.final_penetration_m[i]) << i;
  // Case A: all four pads alike; case B: the pad on the closely packed patch goes least deep.
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(records[0].pad_final_penetration_m[i], records[0].pad_final_penetration_m[0], 1e-9);
  EXPECT_LT(records[1].pad_final_penetration_m[0], records[1].pad_final_penetration_m[2]);
  EXPECT_LT(records[2].pad_final_penetration_m[2], records[2].pad_final_penetration_m[0]);

  // The MPI message format and a recomputation carry the per-pad soils.
  const std::vector<DropRecord> sent = DeserializeRecords(SerializeRecords(records));
  for (size_t i = 0; i < records.size(); ++i) EXPECT_TRUE(SameRecord(sent[i], records[i])) << i;
  EXPECT_TRUE(SameRecord(RunSweepInMemory(plan, 1)[1], records[1], false));

  // export: lander_drops.csv with the per-pad soils and the ground case.
  const ExportSummary s = ExportSweep(Out("out"), Out("export"), {});
  EXPECT_TRUE(s.lander);
  EXPECT_EQ(s.exported, 3);
  EXPECT_FALSE(fs::exists(dir_ / "export" / "drops.csv"));
  std::ifstream in(dir_ / "export" / "lander_drops.csv");
  std::string header, row;
  std::getline(in, header);
  std::string expected;
  for (const std::string& c : kLanderExportColumns) expected += (expected.empty() ? "" : ",") + c;
  EXPECT_EQ(header, expected);
  EXPECT_NE(header.find(",ground_case,pad1_soil,pad2_soil,pad3_soil,pad4_soil,"), std::string::npos);
  std::getline(in, row);
  std::getline(in, row);
  EXPECT_EQ(row.rfind("d1,", 0), 0u) << row;
  EXPECT_NE(row.find(",B,fjs1_cp,fjs1_lp,fjs1_lp,fjs1_lp,"), std::string::npos) << row;
  // Each column the database has by that name holds its number (empty where it has none).
  std::vector<std::string> cells;
  std::stringstream cells_in(row + ",");  // a last empty cell is a cell
  for (std::string cell; std::getline(cells_in, cell, ',');) cells.push_back(cell);
  ASSERT_EQ(cells.size(), kLanderExportColumns.size()) << row;
  int numbers = 0;
  for (size_t k = 0; k < cells.size(); ++k) {
    const std::string& name = kLanderExportColumns[k];
    bool in_database = false;
    for (const std::vector<RecordNumber>* group : {&RigNumbers(), &FreeAndLanderNumbers(), &StabilityNumbers()})
      for (const RecordNumber& n : *group) in_database = in_database || name == n.name;
    if (!in_database) continue;
    const double v = RecordNumberNamed(name).Of(records[1]);
    EXPECT_EQ(cells[k], std::isfinite(v) ? io::FormatNumber(v) : "") << name;
    ++numbers;
  }
  EXPECT_EQ(numbers, static_cast<int>(kLanderExportColumns.size()) - 10);  // all but 9 texts and solver_steps
}

}  // namespace
}  // namespace touchdown::sweep

// The whole import: raw files and a mapping written from drops with a known answer, imported,
// read back as a dataset; the mapping's further keys and import's own columns in drops.csv; the
// README and the mapping's copy; a bad cell in the last file or a user's folder at the target
// leave nothing written.
#include "drop_tests/dataset/daq_import.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "rft/input_error.h"
#include "tests/drop_tests/dataset/daq_test_files.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::dataset {
namespace {

namespace fs = std::filesystem;
using testing_drop::DropLine;
using testing_drop::DropRecord;
using testing_drop::DropShape;
using testing_drop::MakeDrop;
using testing_drop::MappingText;
using testing_drop::RawDropText;

class DaqImport : public testing_scratch::ScratchDirTest {
 protected:
  // Two drops: a flat-like and a curved-like pad; their records kept for the truth.
  std::string WriteSet(bool acceleration, bool time_column, const std::string& zero = "none", bool specific_force = false) {
    fs::create_directories(dir_ / "raw");
    DropShape flat;
    flat.force_noise_N = 0.3, flat.displacement_noise_m = 5e-6, flat.acceleration_noise_m_s2 = 0.05;
    flat.acceleration_bias_m_s2 = 0.1;
    DropShape curved = flat;
    curved.stiffness = 1.5e8, curved.exponent = 3.0, curved.dynamic = 0.0, curved.speed_m_s = 1.4, curved.seed = 9;
    curved.phase = 0.81, curved.touchdown_in_file_s = 30.25;
    shapes_ = {flat, curved};
    records_ = {MakeDrop(flat), MakeDrop(curved)};
    Write("raw/d1.csv", RawDropText(records_[0], acceleration, time_column, specific_force));
    Write("raw/d2.csv", RawDropText(records_[1], acceleration, time_column, specific_force));
    const std::string time = time_column ? "{column: Time, unit: ms}" : "{sample_rate_hz: 5000}";
    return Write("import.yaml", MappingText(acceleration, time,
                                           DropLine("d1", "flat", 1.0, ", replicate: 1") +
                                               DropLine("d2", "curved", 1.4, ", operator: ab, replicate: 2"),
                                           zero));
  }
  static std::string Cell(const Dataset& ds, const DatasetDrop& d, const std::string& column) {
    const auto it = std::find(ds.extra_columns.begin(), ds.extra_columns.end(), column);
    EXPECT_NE(it, ds.extra_columns.end()) << column;
    return it == ds.extra_columns.end() ? "" : d.extra[it - ds.extra_columns.begin()];
  }
  std::vector<DropShape> shapes_;
  std::vector<DropRecord> records_;
};

TEST_F(DaqImport, DisplacementRoundTrip) {
  const std::string mapping = WriteSet(false, true);
  const ImportRun run = ImportToDirectory(mapping, Path("out"));
  const Dataset back = ReadDataset(Path("out"));
  ASSERT_EQ(back.drops.size(), 2u);
  std::vector<std::string> expected = {"replicate", "operator"};
  for (const auto* list : {&kImportColumns, &kImportDisplacementColumns}) expected.insert(expected.end(), list->begin(), list->end());
  EXPECT_EQ(back.extra_columns, expected);
  EXPECT_EQ(back.drops[0].extra[1], "");  // d1 has no operator
  EXPECT_EQ(back.drops[1].extra[1], "ab");
  for (size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    const DatasetDrop& d = back.drops[k];
    const double t0 = *back.ExtraNumber(d, "touchdown_time_in_file_s");
    const double u = *back.ExtraNumber(d, "touchdown_uncertainty_s");
    EXPECT_NEAR(t0, shapes_[k].touchdown_in_file_s, 3 * u);
    EXPECT_LT(d.trace.t_s.front(), -0.02);  // the pre-trigger kept, at negative times
    EXPECT_NEAR(*back.ExtraNumber(d, "pretrigger_s"), -d.trace.t_s.front(), 1e-12);
    EXPECT_NEAR(*back.ExtraNumber(d, "force_zero_N"), 4.2, 0.15);
    EXPECT_NEAR(*back.ExtraNumber(d, "displacement_at_touchdown_m"), 0.007 + shapes_[k].speed_m_s * (t0 - shapes_[k].touchdown_in_file_s), 3e-5);
    EXPECT_NEAR(*back.ExtraNumber(d, "measured_impact_speed_m_s"), shapes_[k].speed_m_s, 0.02);
    // The penetration is referenced to the detected touchdown: off by v0 times its error.
    EXPECT_NEAR(d.trace.penetration_m.back(), records_[k].final_depth_m, shapes_[k].speed_m_s * 3 * u + 3e-5);
    EXPECT_NEAR(d.trace.force_N.back(), 1.6 * 9.81, 0.5);
    EXPECT_EQ(d.penetration_zero, PenetrationZero::kTouchdown);  // what diagnose's time moves with
  }
  EXPECT_EQ(run.dataset, back);
  const std::string readme = Slurp(dir_ / "out" / "README.md");
  EXPECT_NE(readme.find(fs::absolute(mapping).lexically_normal().string()), std::string::npos);
  EXPECT_NE(readme.find("Test drops made in code."), std::string::npos);
  EXPECT_NE(readme.find("d2 | " + (dir_ / "raw" / "d2.csv").string()), std::string::npos) << readme;
  EXPECT_EQ(Slurp(dir_ / "out" / "import.yaml"), Slurp(mapping));
}

TEST_F(DaqImport, AccelerationRoundTrip) {
  const std::string mapping = WriteSet(true, false, "free_fall", true);  // a specific-force accelerometer
  ImportToDirectory(mapping, Path("out"));
  const Dataset back = ReadDataset(Path("out"));
  for (size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    const DatasetDrop& d = back.drops[k];
    EXPECT_EQ(Cell(back, d, "raw_file"), "raw/d" + std::to_string(k + 1) + ".csv");
    EXPECT_EQ(Cell(back, d, "penetration_from"), "acceleration");
    EXPECT_EQ(d.penetration_zero, PenetrationZero::kTouchdown);
    EXPECT_NEAR(*back.ExtraNumber(d, "pretrigger_acceleration_m_s2"), 9.81, 0.05);
    EXPECT_NEAR(*back.ExtraNumber(d, "acceleration_bias_m_s2"), 0.0, 0.05);  // free_fall took it with g
    const double u = *back.ExtraNumber(d, "touchdown_uncertainty_s");
    EXPECT_NEAR(d.trace.penetration_m.back(), records_[k].final_depth_m, 0.02 * records_[k].final_depth_m + shapes_[k].speed_m_s * 3 * u);
  }
  EXPECT_EQ(Cell(back, back.drops[0], "penetration_filter"), "none");
}

TEST_F(DaqImport, AFilterNeedsItsSampleRate) {
  const std::string mapping = WriteSet(false, false);
  std::string text = Slurp(mapping);
  text.replace(text.find("offset: 2048}"), 13, "offset: 2048, filter: cfc600}");
  Write("import.yaml", text);
  try {
    ImportRaw(mapping);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), mapping + ": channels.force.filter: cfc600 needs a sample rate of 6000 Hz at least (10 CFC), and " +
                                         Path("raw/d1.csv") + " is sampled at 5000 Hz: choose a lower class or none");
  }
  text.replace(text.find("cfc600"), 6, "cfc180");
  Write("import.yaml", text);
  const ImportRun run = ImportRaw(mapping);
  EXPECT_EQ(Cell(run.dataset, run.dataset.drops[0], "force_filter"), "cfc180");
}

TEST_F(DaqImport, NothingIsWrittenOnFailure) {
  const std::string mapping = WriteSet(false, true);
  // Line 5, the second sample: its force cell made text; text in the unused Status is fine.
  std::string raw = Slurp(dir_ / "raw" / "d2.csv");
  size_t line5 = 0;
  for (int k = 0; k < 4; ++k) line5 = raw.find('\n', line5) + 1;
  const size_t fz = raw.find(';', line5) + 1;
  raw.replace(fz, raw.find(';', fz) - fz, "12O4");
  raw.replace(raw.find("OK\n", line5), 2, "no sync");
  Write("raw/d2.csv", raw);
  try {
    ImportToDirectory(mapping, Path("out"));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), Path("raw/d2.csv") + ": line 5, column 2 (Fz): not a finite number: '12O4'");
  }
  EXPECT_FALSE(fs::exists(Path("out")));
}

TEST_F(DaqImport, AUsersFolderIsNeverWritten) {
  const std::string mapping = WriteSet(false, true);
  fs::create_directories(dir_ / "mine");
  Write("mine/notes.txt", "mine\n");
  EXPECT_THROW(ImportToDirectory(mapping, Path("mine")), InputError);
  EXPECT_EQ(Slurp(dir_ / "mine" / "notes.txt"), "mine\n");
  EXPECT_THROW(ImportToDirectory(mapping, Path("raw")), InputError);  // around its inputs
  EXPECT_TRUE(fs::exists(dir_ / "raw" / "d1.csv"));
}

}  // namespace
}  // namespace touchdown::dataset

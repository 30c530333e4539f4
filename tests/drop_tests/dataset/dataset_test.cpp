// The dataset format: an exact write/read round trip, and every malformed file refused with
// an InputError naming the file, the line and the column, before anything is returned.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/formats/dataset_csv.h"
#include "rft/input_error.h"

namespace {

namespace fs = std::filesystem;
using touchdown::InputError;
using namespace touchdown::dataset;
using namespace touchdown::io;

class DatasetDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_dataset_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void Write(const std::string& relative, const std::string& text) {
    fs::create_directories((dir_ / relative).parent_path());
    std::ofstream(dir_ / relative) << text;
  }
  static std::string Slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

// A small dataset with awkward numbers (no short decimal form), an extra parameter column with
// an empty cell and an extra trace column.
Dataset MakeDataset() {
  Dataset ds;
  ds.extra_columns = {"tilt_deg", "operator"};
  for (int k = 0; k < 3; ++k) {
    DatasetDrop d;
    d.drop_id = "run_" + std::to_string(k);
    d.pad = k == 2 ? "curved" : "flat";
    d.soil = "fjs1_lp";
    d.atmosphere = k == 1 ? touchdown::rft::Atmosphere::kAir : touchdown::rft::Atmosphere::kVacuum;
    d.impact_speed_m_s = 0.7 + k / 3.0;
    d.pad_mass_kg = 1.6;
    d.gravity_m_s2 = 9.81;
    d.trace_file = "traces/" + d.drop_id + ".csv";
    if (k != 1) d.final_penetration_m = 0.01 + 1e-17 * k + 1.0 / 7.0e3;
    d.peak_force_N = 100.0 / 3.0 + k;
    d.extra = {k == 0 ? "" : "0", "lab" + std::to_string(k)};
    d.trace.extra_columns = {"velocity_m_s"};
    d.trace.extra.resize(1);
    for (int i = 0; i < 20; ++i) {
      d.trace.t_s.push_back(i * 1e-3 - 2e-3);
      d.trace.penetration_m.push_back(std::sin(i * 0.1) / 70.0);
      d.trace.force_N.push_back(std::exp(i * 0.2) * std::numbers::pi);
      d.trace.extra[0].push_back(1.0 / (i + 3.0));
    }
    ds.drops.push_back(d);
  }
  return ds;
}

TEST_F(DatasetDir, RoundTripIsExactAndRewriteIsByteIdentical) {
  const Dataset original = MakeDataset();
  WriteDataset(original, (dir_ / "a").string());
  const Dataset back = ReadDataset((dir_ / "a").string());
  EXPECT_TRUE(back == original);
  ASSERT_EQ(back.drops.size(), 3u);
  EXPECT_EQ(back.drops[0].trace.force_N, original.drops[0].trace.force_N);  // bitwise equal doubles
  EXPECT_FALSE(back.drops[1].final_penetration_m.has_value());
  EXPECT_EQ(back.drops[0].extra[0], "");
  EXPECT_EQ(*back.ExtraNumber(back.drops[1], "tilt_deg"), 0.0);
  EXPECT_FALSE(back.ExtraNumber(back.drops[0], "tilt_deg").has_value());
  WriteDataset(back, (dir_ / "b").string());
  EXPECT_EQ(Slurp(dir_ / "a" / "drops.csv"), Slurp(dir_ / "b" / "drops.csv"));
  EXPECT_EQ(Slurp(dir_ / "a" / "traces" / "run_2.csv"), Slurp(dir_ / "b" / "traces" / "run_2.csv"));
  for (const fs::directory_entry& e : fs::directory_iterator(dir_))  // no staging left
    EXPECT_EQ(e.path().filename().string().rfind(".a.partial-", 0), std::string::npos) << e.path();
}

TEST_F(DatasetDir, DerivedFinalPenetrationAndPeakForceComeFromTheTrace) {
  const Dataset ds = MakeDataset();
  const DatasetDrop& d = ds.drops[1];  // no final_penetration_m column value
  EXPECT_EQ(d.FinalPenetration(), d.trace.penetration_m.back());
  EXPECT_EQ(ds.drops[0].PeakForce(), *ds.drops[0].peak_force_N);
}

TEST(DatasetCsv, NumbersRoundTripInShortestForm) {
  for (double v : {0.1, 1.0 / 3.0, 1e-300, 6.02214076e23, -0.0, 123456789.123456789}) {
    double back = 0.0;
    ASSERT_TRUE(ParseNumber(FormatNumber(v), &back)) << v;
    EXPECT_EQ(back, v);
  }
  double v = 0.0;
  EXPECT_FALSE(ParseNumber("1.0x", &v));
  EXPECT_FALSE(ParseNumber("nan", &v));
  EXPECT_FALSE(ParseNumber("inf", &v));
  EXPECT_FALSE(ParseNumber("", &v));
  EXPECT_TRUE(ParseNumber("+2.5", &v));
  EXPECT_EQ(v, 2.5);
}

struct Malformed {
  const char* name;
  std::string drops_csv;  // written to drops.csv
  std::string trace_csv;  // written to traces/a.csv
  std::string expected;   // fragment of the error message ({dir} = the dataset directory)
};
void PrintTo(const Malformed& c, std::ostream* os) { *os << c.name; }  // readable test names


const std::string kHeader = "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace\n";
const std::string kRow = "a,flat,fjs1_lp,vacuum,1.0,1.6,9.81,traces/a.csv\n";
const std::string kTrace = "t_s,penetration_m,force_N\n0,0,0\n0.001,0.001,10\n0.002,0.0015,20\n";

class DatasetMalformed : public DatasetDir, public ::testing::WithParamInterface<Malformed> {};

TEST_P(DatasetMalformed, RefusedWithFileLineAndColumn) {
  Write("drops.csv", GetParam().drops_csv);
  Write("traces/a.csv", GetParam().trace_csv);
  std::string expected = GetParam().expected;
  for (size_t p; (p = expected.find("{dir}")) != std::string::npos;) expected.replace(p, 5, dir_.string());
  try {
    ReadDataset(dir_.string());
    FAIL() << "accepted a malformed dataset";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DatasetMalformed,
    ::testing::Values(
        Malformed{"MissingDropsColumn", "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,trace\n" +
                                            std::string("a,flat,fjs1_lp,vacuum,1,1.6,traces/a.csv\n"),
                  kTrace, "{dir}/drops.csv: line 1: missing column 'gravity_m_s2'"},
        Malformed{"MissingTraceColumn", kHeader + kRow, "t_s,force_N\n0,0\n",
                  "{dir}/traces/a.csv: line 1: missing column 'penetration_m'"},
        Malformed{"NonNumericSpeed", kHeader + "a,flat,fjs1_lp,vacuum,fast,1.6,9.81,traces/a.csv\n", kTrace,
                  "{dir}/drops.csv: line 2, column 5 (impact_speed_m_s): not a finite number: 'fast'"},
        Malformed{"NonNumericTraceCell", kHeader + kRow, "t_s,penetration_m,force_N\n0,0,0\n0.001,0.001,1O\n",
                  "{dir}/traces/a.csv: line 3, column 3 (force_N): not a finite number: '1O'"},
        Malformed{"NanTraceCell", kHeader + kRow, "t_s,penetration_m,force_N\n0,nan,0\n",
                  "{dir}/traces/a.csv: line 2, column 2 (penetration_m): not a finite number: 'nan'"},
        Malformed{"NonMonotonicTime", kHeader + kRow, "t_s,penetration_m,force_N\n0,0,0\n0.002,0.001,1\n0.001,0.002,2\n",
                  "{dir}/traces/a.csv: line 4, column 1 (t_s): time must increase strictly"},
        Malformed{"RepeatedTime", kHeader + kRow, "t_s,penetration_m,force_N\n0,0,0\n0,0.001,1\n",
                  "{dir}/traces/a.csv: line 3, column 1 (t_s): time must increase strictly"},
        Malformed{"UnknownPad", kHeader + "a,hexagon_xl,fjs1_lp,vacuum,1,1.6,9.81,traces/a.csv\n", kTrace,
                  "{dir}/drops.csv: line 2, column 2 (pad): unknown pad"},
        Malformed{"UnknownSoil", kHeader + "a,flat,mud,vacuum,1,1.6,9.81,traces/a.csv\n", kTrace,
                  "{dir}/drops.csv: line 2, column 3 (soil): unknown soil"},
        Malformed{"BadAtmosphere", kHeader + "a,flat,fjs1_lp,argon,1,1.6,9.81,traces/a.csv\n", kTrace,
                  "line 2, column 4 (atmosphere): must be 'vacuum' or 'air', got 'argon'"},
        Malformed{"NegativeMass", kHeader + "a,flat,fjs1_lp,vacuum,1,-1.6,9.81,traces/a.csv\n", kTrace,
                  "line 2, column 6 (pad_mass_kg): must be positive"},
        Malformed{"DuplicateId", kHeader + kRow + kRow, kTrace, "line 3, column 1 (drop_id): duplicate drop id 'a'"},
        Malformed{"MissingTraceFile", kHeader + "a,flat,fjs1_lp,vacuum,1,1.6,9.81,traces/b.csv\n", kTrace,
                  "line 2, column 8 (trace): {dir}/traces/b.csv: trace file not found"},
        Malformed{"AbsoluteTracePath", kHeader + "a,flat,fjs1_lp,vacuum,1,1.6,9.81,/etc/passwd\n", kTrace,
                  "line 2, column 8 (trace): must be relative to the dataset directory"},
        Malformed{"ShortRow", kHeader + "a,flat,fjs1_lp,vacuum,1,1.6,9.81\n", kTrace,
                  "{dir}/drops.csv: line 2: expected 8 cells as in the header, got 7"},
        Malformed{"LongTraceRow", kHeader + kRow, "t_s,penetration_m,force_N\n0,0,0,5\n",
                  "{dir}/traces/a.csv: line 2: expected 3 cells as in the header, got 4"},
        Malformed{"EmptyDropsFile", "", kTrace, "{dir}/drops.csv: line 1: empty file"},
        Malformed{"NoDrops", kHeader, kTrace, "{dir}/drops.csv: line 2: no drops"},
        Malformed{"NoSamples", kHeader + kRow, "t_s,penetration_m,force_N\n", "{dir}/traces/a.csv: line 2: no samples"},
        Malformed{"BadOptionalColumn", "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace,"
                                       "peak_force_N\na,flat,fjs1_lp,vacuum,1,1.6,9.81,traces/a.csv,big\n",
                  kTrace, "line 2, column 9 (peak_force_N): not a finite number: 'big'"},
        Malformed{"DuplicateColumn", "drop_id,pad,pad\n", kTrace, "line 1, column 3: duplicate column 'pad'"},
        Malformed{"DataAfterBlankLine", kHeader + kRow + "\n" + kRow, kTrace, "line 4: data after a blank line"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(DatasetDir, MissingDirectoryIsAnInputError) {
  EXPECT_THROW(ReadDataset((dir_ / "nowhere").string()), InputError);
}

TEST_F(DatasetDir, WriterRefusesWhatItCouldNotReadBack) {
  Dataset ds = MakeDataset();
  ds.drops[1].drop_id = ds.drops[0].drop_id;
  EXPECT_THROW(WriteDataset(ds, (dir_ / "x").string()), InputError);
  ds = MakeDataset();
  ds.drops[0].pad = "fl,at";
  EXPECT_THROW(WriteDataset(ds, (dir_ / "x").string()), InputError);
  EXPECT_FALSE(fs::exists(dir_ / "x"));
}


TEST_F(DatasetDir, WideHeaderIsCheckedForDuplicatesInLinearTime) {
  // Regression (found by fuzzing): the duplicate-column check compared every pair of columns, so
  // a header of 200k columns took minutes. Now a set: well under a second (seconds under ASan).
  std::string header;
  for (int i = 0; i < 200000; ++i) header += (i ? ",c" : "c") + std::to_string(i);
  Write("wide.csv", header + "\n");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(ReadCsv((dir_ / "wide.csv").string()).header.size(), 200000u);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
  Write("dup.csv", header + ",c7\n");
  try {
    ReadCsv((dir_ / "dup.csv").string());
    ADD_FAILURE() << "accepted";
  } catch (const touchdown::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 1, column 200001: duplicate column 'c7'"), std::string::npos)
        << e.what();
  }
}

}  // namespace

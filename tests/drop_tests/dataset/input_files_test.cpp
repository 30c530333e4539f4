// Every input file opens through one helper that says what is wrong
// with a path; YAML files refuse duplicate keys and text that is not UTF-8; dataset CSVs read as
// RFC 4180 (Excel and pandas exports); drop ids must be file names; soil files take the fields
// the README documents; compare reports drops whose relative errors are undefined.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/dataset/compare.h"
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/input_file.h"

namespace {

namespace fs = std::filesystem;
using touchdown::InputError;
using namespace touchdown::dataset;
using namespace touchdown::io;

class InputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_inputs_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  template <typename F>
  static std::string ErrorOf(F f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

TEST_F(InputFiles, APathThatIsNotAReadableFileSaysWhatItIs) {
  using touchdown::ReadInputFile;
  EXPECT_EQ(ErrorOf([&] { ReadInputFile(Path("none.yaml")); }), Path("none.yaml") + ": file not found");
  EXPECT_EQ(ErrorOf([&] { ReadInputFile(Path("none.stl"), "mesh file"); }), Path("none.stl") + ": mesh file not found");
  fs::create_directories(dir_ / "dir.yaml");
  EXPECT_EQ(ErrorOf([&] { ReadInputFile(Path("dir.yaml")); }), Path("dir.yaml") + ": is a directory, not a file");
  ASSERT_EQ(::mkfifo(Path("pipe.yaml").c_str(), 0600), 0);
  EXPECT_EQ(ErrorOf([&] { ReadInputFile(Path("pipe.yaml")); }),
            Path("pipe.yaml") + ": is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(ErrorOf([&] { ReadInputFile("/dev/null"); }), "/dev/null: is a device, not a regular file");
  fs::create_symlink("loop.yaml", dir_ / "loop.yaml");
  EXPECT_EQ(ErrorOf([&] { ReadInputFile(Path("loop.yaml")); }),
            Path("loop.yaml") + ": symbolic link loop (too many levels of symbolic links)");
  Write("file.yaml", "a: 1\n");
  EXPECT_EQ(ErrorOf([&] { ReadInputFile(Path("file.yaml/x.yaml")); }),
            Path("file.yaml/x.yaml") + ": file not found (a part of the path is not a directory)");
  EXPECT_EQ(ReadInputFile(Path("file.yaml")), "a: 1\n");
}

TEST_F(InputFiles, AnUnreadableFileIsPermissionDeniedNotMalformedYaml) {
  const std::string path = Write("secret.yaml", "schema_version: 1\n");
  fs::permissions(path, fs::perms::none);
  // root reads any file (CAP_DAC_OVERRIDE); everyone else is told why the file cannot be read.
  const bool readable = ::access(path.c_str(), R_OK) == 0;
  const std::string error = ErrorOf([&] { YamlFields::LoadFile(path); });
  if (readable) {
    EXPECT_EQ(error, "(no error)");
  } else {
    EXPECT_EQ(error, path + ": permission denied");
  }
}

TEST(InputText, Utf8IsCheckedStrictly) {
  using touchdown::IsValidUtf8;
  EXPECT_TRUE(IsValidUtf8("plain ascii"));
  EXPECT_TRUE(IsValidUtf8("Tr\xC3\xA9" "ers \xE2\x80\x93 \xF0\x9F\x9A\x80"));  // é, en dash, a rocket
  EXPECT_FALSE(IsValidUtf8("pad\xE9"));            // Latin-1 é
  EXPECT_FALSE(IsValidUtf8("\xC0\xAF"));           // overlong '/'
  EXPECT_FALSE(IsValidUtf8("\xED\xA0\x80"));       // a surrogate
  EXPECT_FALSE(IsValidUtf8("\xF4\x90\x80\x80"));   // above U+10FFFF
  EXPECT_FALSE(IsValidUtf8("\xE2\x80"));           // cut short
  EXPECT_FALSE(IsValidUtf8("\x80"));               // a stray continuation byte
}

TEST_F(InputFiles, YamlDuplicateKeysAreRefusedAtAnyDepthWithTheirLines) {
  const std::string top = Write("top.yaml", "mass_kg: 1.6\nname: a\nmass_kg: 2\n");
  EXPECT_EQ(ErrorOf([&] { YamlFields::LoadFile(top); }), top + ": mass_kg: duplicate key (line 3; first at line 1)");
  const std::string nested =
      Write("nested.yaml", "grid:\n  speeds:\n    - {a: 1}\n    - {a: 1, b: 2, a: 3}\n");
  EXPECT_EQ(ErrorOf([&] { YamlFields::LoadFile(nested); }),
            nested + ": grid.speeds[1].a: duplicate key (line 4; first at line 4)");
  const std::string fine = Write("fine.yaml", "a: {x: 1}\nb: {x: 2}\n");
  EXPECT_EQ(ErrorOf([&] { YamlFields::LoadFile(fine); }), "(no error)");
}

TEST_F(InputFiles, YamlTextMustBeUtf8AndMayStartWithABom) {
  const std::string latin1 = Write("latin1.yaml", "name: caf\xE9\nmass_kg: 1\n");
  EXPECT_EQ(ErrorOf([&] { YamlFields::LoadFile(latin1); }), latin1 + ": name: not valid UTF-8 text (line 1)");
  const std::string bom = Write("bom.yaml", "\xEF\xBB\xBFmass_kg: 1.5\n");
  EXPECT_EQ(YamlFields::LoadFile(bom).Number("mass_kg"), 1.5);
}

TEST_F(InputFiles, WholeNumberCapIsNamed) {
  const std::string path = Write("n.yaml", "samples: 1099511627775\ncount: 2.5\n");
  const YamlFields f = YamlFields::LoadFile(path);
  EXPECT_EQ(ErrorOf([&] { f.PositiveInt("samples"); }),
            path + ": samples: must be at most 1000000000 (1e9), got '1099511627775'");
  EXPECT_EQ(ErrorOf([&] { f.PositiveInt("count"); }), path + ": count: must be a whole number, got '2.5'");
}

TEST_F(InputFiles, CsvReadsRfc4180AsExcelAndPandasWriteIt) {
  // UTF-8 BOM, CRLF, every field quoted, a comma, a doubled quote and a line break inside quotes.
  const std::string path = Write("t.csv",
                                 "\xEF\xBB\xBF\"name\",\"note\",\"x\"\r\n"
                                 "\"a\",\"one, two\",\"1.5\"\r\n"
                                 "\"b\",\"say \"\"hi\"\"\",\"2\"\r\n"
                                 "\"c\",\"two\nlines\",\"3\"\r\n"
                                 " d , plain ,4\r\n"
                                 "\r\n");
  const CsvTable t = ReadCsv(path);
  ASSERT_EQ(t.header, (std::vector<std::string>{"name", "note", "x"}));
  ASSERT_EQ(t.rows.size(), 4u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"a", "one, two", "1.5"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"b", "say \"hi\"", "2"}));
  EXPECT_EQ(t.rows[2], (std::vector<std::string>{"c", "two\nlines", "3"}));
  EXPECT_EQ(t.rows[3], (std::vector<std::string>{"d", "plain", "4"}));  // blanks around unquoted cells dropped
  EXPECT_EQ(t.row_lines, (std::vector<int>{2, 3, 4, 6}));  // the quoted line break counts
  EXPECT_EQ(t.Number(0, 2), 1.5);
}

TEST_F(InputFiles, CsvQuotingErrorsNameTheLine) {
  const std::string open = Write("open.csv", "a,b\n1,\"2\n3,4\n");
  EXPECT_EQ(ErrorOf([&] { ReadCsv(open); }), open + ": line 2: a quoted field is not closed (missing \")");
  const std::string after = Write("after.csv", "a,b\n1,\"2\"x\n");
  EXPECT_EQ(ErrorOf([&] { ReadCsv(after); }),
            after + ": line 2: unexpected text after a closing quote (a quote inside a quoted field is written \"\")");
  const std::string inside = Write("inside.csv", "a,b\n1,2\"\n");
  EXPECT_EQ(ErrorOf([&] { ReadCsv(inside); }), inside + ": line 2: a quote inside an unquoted field (quote the whole field)");
  const std::string latin1 = Write("latin1.csv", "a,b\n1,caf\xE9\n");
  EXPECT_EQ(ErrorOf([&] { ReadCsv(latin1); }), latin1 + ": line 2, column 2: not valid UTF-8 text");
}

TEST(DropIds, MustBeFileNames) {
  EXPECT_EQ(DropIdProblem("flat_fjs1_lp_v1.00"), "");
  EXPECT_EQ(DropIdProblem("caf\xC3\xA9"), "");
  EXPECT_EQ(DropIdProblem("a/b"), "drop id 'a/b' contains '/' (it names files)");
  EXPECT_EQ(DropIdProblem(".."), "drop id '..' cannot be a file name");
  EXPECT_EQ(DropIdProblem(""), "empty drop id");
  EXPECT_NE(DropIdProblem("tab\there"), "");
  EXPECT_NE(DropIdProblem(std::string(201, 'x')), "");
  EXPECT_EQ(DropIdProblem("caf\xE9"), "drop id is not valid UTF-8 text");
}

TEST_F(InputFiles, SoilFieldsTheReadmeDocumentsAreRead) {
  const std::string path = Write("dyn.yaml",
                                 "schema_version: 1\nzeta_N_cm3: 3\nbulk_density_kg_m3: 1600\n"
                                 "internal_friction_angle_deg: 37\nmu_surf: 0.3\ndynamic_term: true\n"
                                 "dynamic_lambda: 1.2\ndynamic_density_kg_m3: 1500\n");
  const touchdown::rft::SoilParameters soil = LoadSoil(path);
  EXPECT_EQ(soil.surface_friction_coefficient, 0.3);
  EXPECT_TRUE(soil.dynamic_term);
  EXPECT_EQ(soil.dynamic_lambda, 1.2);
  EXPECT_EQ(soil.dynamic_density_kg_m3, 1500.0);
  const std::string no_density = Write("nodens.yaml", "schema_version: 1\nzeta_N_cm3: 3\ndynamic_term: true\n");
  EXPECT_EQ(ErrorOf([&] { LoadSoil(no_density); }),
            no_density + ": dynamic_term: needs the soil's bulk_density_kg_m3");
  const std::string bad = Write("bad.yaml", "schema_version: 1\nzeta_N_cm3: 3\ndynamic_term: maybe\n");
  EXPECT_EQ(ErrorOf([&] { LoadSoil(bad); }), bad + ": dynamic_term: must be true or false, got 'maybe'");
  const std::string huge = Write("huge.yaml", "schema_version: 1\nzeta_N_cm3: 1e308\n");
  EXPECT_EQ(ErrorOf([&] { LoadSoil(huge); }),
            huge + ": zeta_N_cm3: must be above 0 and at most 10000 N/cm^3, got 1e+308");
}

// A measured drop at rest on the surface (peak force and final penetration 0) has no relative
// error: it is listed, and the means say over how many drops they were taken.
TEST(CompareZeroMeasured, DropsWithUndefinedRelativeErrorsAreReportedNotCounted) {
  auto drop = [](const std::string& id, double scale) {
    DatasetDrop d;
    d.drop_id = id;
    d.trace.t_s = {0.0, 0.001, 0.002};
    d.trace.penetration_m = {0.0, 0.001 * scale, 0.002 * scale};
    d.trace.force_N = {0.0, 10.0 * scale, 20.0 * scale};
    return d;
  };
  Dataset measured, simulated;
  measured.drops = {drop("moving", 1.0), drop("resting", 0.0)};
  simulated.drops = {drop("moving_sim", 1.1), drop("resting_sim", 1.0)};
  const Comparison c = CompareDrops(measured, {&simulated.drops[0], &simulated.drops[1]});
  EXPECT_EQ(c.zero_final_penetration_drops, std::vector<std::string>{"resting"});
  EXPECT_EQ(c.zero_peak_force_drops, std::vector<std::string>{"resting"});
  EXPECT_EQ(c.final_penetration_drops_used, 1u);
  EXPECT_EQ(c.peak_force_drops_used, 1u);
  EXPECT_NEAR(c.peak_force_rel_error, 0.1, 1e-12);
  const nlohmann::json j = ComparisonJson(c);
  EXPECT_EQ(j["drops_compared"], 2);
  EXPECT_EQ(j["drops_used"]["peak_force_rel_error"], 1);
  EXPECT_EQ(j["drops_measured_zero"]["peak_force"], nlohmann::json::array({"resting"}));
  // No null or NaN anywhere: an undefined value is left out.
  std::function<void(const nlohmann::json&)> no_null = [&](const nlohmann::json& v) {
    EXPECT_FALSE(v.is_null()) << j.dump();
    if (v.is_number_float()) {
      EXPECT_TRUE(std::isfinite(v.get<double>()));
    }
    if (v.is_structured())
      for (const auto& x : v) no_null(x);
  };
  no_null(j);
  EXPECT_FALSE(j["drops"][1].contains("peak_force_rel_error"));
}

}  // namespace

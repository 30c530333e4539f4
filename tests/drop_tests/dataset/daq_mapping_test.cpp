// The mapping file: every field read, defaults, paths relative to the mapping, and each mistake
// answered with one line naming the file, the field and the value.
#include "drop_tests/dataset/daq_mapping.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "rft/input_error.h"
#include "tests/drop_tests/dataset/daq_test_files.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::dataset {
namespace {

using testing_drop::DropLine;
using testing_drop::MappingText;

class DaqMappingFile : public testing_scratch::ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    std::filesystem::create_directories(dir_ / "raw");
    Write("raw/a.csv", "t;Fz;Pos\n");
    Write("raw/b.csv", "t;Fz;Pos\n");
  }
  std::string Base() const {
    return MappingText(false, "{column: Time, unit: ms}", DropLine("a", "flat", 1.0, ", replicate: 1") + DropLine("b", "c4", 1.2));
  }
  // The message of the mapping `text` (Base() with `from` replaced by `to`), or "accepted".
  std::string ErrorOf(const std::string& from, const std::string& to) {
    std::string text = Base();
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    const std::string path = Write("import.yaml", text);
    try {
      LoadDaqMapping(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  }
};

TEST_F(DaqMappingFile, ReadsEveryFieldWithItsDefaults) {
  const DaqMapping m = LoadDaqMapping(Write("import.yaml", Base()));
  EXPECT_EQ(m.name, "unit_rig");
  EXPECT_EQ(m.text.delimiter, ';');
  EXPECT_EQ(m.text.decimal, '.');
  EXPECT_EQ(m.time_column, "Time");
  EXPECT_DOUBLE_EQ(m.time_unit_s, 1e-3);
  EXPECT_EQ(m.force.zero, ChannelZero::kPreTrigger);  // the force's default
  EXPECT_EQ(m.motion.zero, ChannelZero::kNone);
  EXPECT_EQ(m.motion_kind, MotionChannel::kDisplacement);
  EXPECT_DOUBLE_EQ(m.motion.gain, -1e-5);
  EXPECT_EQ(m.force.filter, ChannelFilter::kNone);
  EXPECT_EQ(m.extra_columns, std::vector<std::string>{"replicate"});
  ASSERT_EQ(m.drops.size(), 2u);
  EXPECT_EQ(m.drops[1].extra, std::vector<std::string>{""});
  EXPECT_EQ(m.drops[0].path, Path("raw/a.csv"));
  EXPECT_EQ(m.drops[1].pad, "c4");
  EXPECT_DOUBLE_EQ(m.drops[1].impact_speed_m_s, 1.2);
}

TEST_F(DaqMappingFile, EachMistakeIsNamed) {
  const std::string file = Path("import.yaml") + ": ";
  struct Case {
    const char* from;
    const char* to;
    std::string expected;  // the message's start after the file
  };
  const std::vector<Case> cases = {
      {"type: import", "type: sweep", "type: must be 'import' for a mapping of raw drop files, got 'sweep'"},
      {"name: unit_rig", "name: a/b", "name: 'a/b' contains '/'"},
      {"comment: \"#\"", "coment: \"#\"", "daq.coment: unknown field (did you mean 'comment'?)"},
      {"delimiter: \";\"", "delimiter: \";;\"", "daq.delimiter: must be one character, got ';;'"},
      {"delimiter: \";\"", "delimiter: \".\"", "daq.delimiter: cannot be '.'"},
      {"{column: Time, unit: ms}", "{column: Time, unit: min}", "daq.time.unit: must be s, ms or us, got 'min'"},
      {"{column: Time, unit: ms}", "{column: Time, sample_rate_hz: 100}", "daq.time: give either"},
      {"{column: Time, unit: ms}", "{sample_rate_hz: -5}", "daq.time.sample_rate_hz: must be positive"},
      {"gain: 0.05,", "gain: 0,", "channels.force.gain: must not be 0"},
      {"offset: 2048}", "offset: 2048, filter: cfc100}", "channels.force.filter: must be cfc60, cfc180, cfc600, cfc1000 or none, got 'cfc100'"},
      {"offset: 2048}", "offset: 2048, zero: free_fall}", "channels.force.zero: must be pre_trigger or none, got 'free_fall'"},
      {"  displacement: {column: Pos, gain: -1e-5, offset: 1000}\n", "",
       "channels: give one of displacement or acceleration"},
      {"  displacement: {column: Pos,", "  acceleration: {column: Acc}\n  displacement: {column: Pos,",
       "channels: give one of displacement or acceleration"},
      {"column: Pos,", "column: Fz,", "channels: time, force and displacement must be three different columns"},
      {"raw/a.csv", "raw/missing.csv", "drops[0].file: " + Path("raw/missing.csv") + ": "},
      {"drop_id: b,", "drop_id: a,", "drops[1].drop_id: 'a' is drops[0]'s id too"},
      {"file: raw/b.csv", "file: raw/a.csv", "drops[1].file: 'raw/a.csv' is drops[0]'s raw file too"},
      {"pad: c4", "pad: hexx", "drops[1].pad: unknown pad 'hexx'"},
      {"atmosphere: vacuum, impact_speed_m_s: 1.2", "atmosphere: argon, impact_speed_m_s: 1.2",
       "drops[1].atmosphere: must be vacuum or air, got 'argon'"},
      {"impact_speed_m_s: 1.2", "impact_speed_m_s: -1", "drops[1].impact_speed_m_s: must be between 0 and 100 m/s"},
      {"replicate: 1", "force_filter: x", "drops[0].force_filter: is a column touchdown writes itself"},
      {"replicate: 1", "replicate: [1, 2]", "drops[0].replicate: a further key becomes a cell of drops.csv"},
      {"replicate: 1", "replicate: \"1,2\"", "drops[0].replicate: '1,2' holds a comma"},
      {"drop_id: b,", "drop_id: ../b,", "drops[1].drop_id: drop id '../b' contains '/'"},
      {"drops:\n", "touchdown: {channel: displacement}\ndrops:\n", "touchdown.channel: must be force"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.to);
    const std::string message = ErrorOf(c.from, c.to);
    EXPECT_EQ(message.rfind(file + c.expected, 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST_F(DaqMappingFile, AccelerationTakesFreeFallAndAFixedTrigger) {
  std::string text = Base();
  text.replace(text.find("  displacement: {column: Pos, gain: -1e-5, offset: 1000}"), 56,
               "  acceleration: {column: Pos, gain: 0.01, zero: free_fall, filter: cfc180}");
  text.replace(text.find("drops:"), 6, "touchdown: {threshold_N: 12}\ndrops:");
  const DaqMapping m = LoadDaqMapping(Write("import.yaml", text));
  EXPECT_EQ(m.motion_kind, MotionChannel::kAcceleration);
  EXPECT_EQ(m.motion.zero, ChannelZero::kFreeFall);
  EXPECT_EQ(m.motion.filter, ChannelFilter::kCfc180);
  EXPECT_DOUBLE_EQ(m.motion.offset, 0.0);
  EXPECT_DOUBLE_EQ(m.threshold_N, 12.0);
}

}  // namespace
}  // namespace touchdown::dataset

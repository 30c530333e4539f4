// A DAQ's text export read as import reads it: metadata comments, delimiters, quotes, a decimal
// comma, text in unused columns; and each malformed file answered with one line naming its file,
// line and column.
#include "drop_tests/dataset/daq_csv.h"

#include <gtest/gtest.h>

#include <string>

#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::dataset {
namespace {

class DaqCsv : public testing_scratch::ScratchDirTest {
 protected:
  DaqColumns Read(const std::string& text, const DaqTextFormat& format = {}, std::vector<std::string> columns = {"t", "F"}) {
    return ReadDaqColumns(Write("raw.csv", text), format, columns);
  }
  std::string ErrorOf(const std::string& text, const DaqTextFormat& format = {}, std::vector<std::string> columns = {"t", "F"}) {
    try {
      Read(text, format, columns);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  }
};

TEST_F(DaqCsv, ReadsTheRequestedColumnsPastMetadata) {
  const DaqColumns c = Read("\xEF\xBB\xBF# rig 3\n# units: V\n\nstatus,t,F\r\nok,0.0,1.5\r\n  # a note\nwarn, 0.5 ,+2e1\n\n");
  EXPECT_EQ(c.header, (std::vector<std::string>{"status", "t", "F"}));
  EXPECT_EQ(c.values[0], (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(c.values[1], (std::vector<double>{1.5, 20.0}));
  EXPECT_EQ(c.lines, (std::vector<int>{5, 7}));
}

TEST_F(DaqCsv, DelimitersQuotesAndADecimalComma) {
  DaqTextFormat tab;
  tab.delimiter = '\t';
  EXPECT_EQ(Read("t\tF\n1\t2\n", tab).values[1][0], 2.0);
  DaqTextFormat blanks;
  blanks.delimiter = ' ';
  EXPECT_EQ(Read("  t    F\n  1   2.5\n", blanks).values[1][0], 2.5);
  DaqTextFormat european;
  european.delimiter = ';';
  european.decimal = ',';
  const DaqColumns e = Read("\"t\";\"F [N]\"\n0,25;\"1,5\"\n", european, {"t", "F [N]"});
  EXPECT_EQ(e.values[0][0], 0.25);
  EXPECT_EQ(e.values[1][0], 1.5);
}

TEST_F(DaqCsv, EachProblemIsOneLineWithFileLineAndColumn) {
  const std::string file = Path("raw.csv");
  EXPECT_EQ(ErrorOf("t,F\n0,1\n1,abc\n"), file + ": line 3, column 2 (F): not a finite number: 'abc'");
  EXPECT_EQ(ErrorOf("t,F\n0,1\n1,nan\n"), file + ": line 3, column 2 (F): not a finite number: 'nan'");
  EXPECT_EQ(ErrorOf("t,F\n0,1\n1\n"), file + ": line 3: expected 2 cells as in the header (line 1), got 1");
  EXPECT_EQ(ErrorOf("time,Forc\n0,1\n", {}, {"time", "Force"}),
            file + ": line 1: missing column 'Force' (did you mean 'Forc'?); the header holds 'time', 'Forc' (delimiter ',')");
  EXPECT_EQ(ErrorOf("t,F\n0,1\n\n1,2\n"), file + ": line 4: data after a blank line (line 3)");
  EXPECT_EQ(ErrorOf("# only\n"), file + ": no header line (every line is blank or a comment)");
  EXPECT_EQ(ErrorOf("t,F\n"), file + ": line 1: no samples after the header");
  EXPECT_EQ(ErrorOf("t,F,t\n0,1,2\n"), file + ": line 1: column 't' appears twice in the header");
  EXPECT_EQ(ErrorOf("t,F\n\"0,1\n"), file + ": line 2: a quoted cell is not closed (missing \")");
  EXPECT_NE(ErrorOf("", {}, {"t"}).find("no header line"), std::string::npos);
  // Text in a column import does not use is fine; in a used one it is not.
  EXPECT_EQ(Read("t,F,note\n0,1,anything at all\n").values[1][0], 1.0);
}

TEST_F(DaqCsv, AMissingFileIsNamed) {
  try {
    ReadDaqColumns(Path("absent.csv"), {}, {"t"});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.csv"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace touchdown::dataset

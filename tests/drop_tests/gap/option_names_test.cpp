// The names diagnose's --base and calibrate's --law take, parsed by one function each for the
// command line and Python: every name round-trips, any other text is an InputError naming the
// option and the value.
#include <gtest/gtest.h>

#include "drop_tests/dataset/calibration_run.h"
#include "drop_tests/gap/diagnose.h"
#include "rft/input_error.h"

namespace touchdown::gap {
namespace {

TEST(OptionNames, DiagnoseBaseNamesParseInEnumOrder) {
  const std::vector<std::string> names = DiagnoseBaseNames();
  ASSERT_EQ(names, (std::vector<std::string>{"rft", "bekker"}));
  EXPECT_EQ(ParseDiagnoseBase(names[0], "", ""), DiagnoseBase::kRft);
  EXPECT_EQ(ParseDiagnoseBase(names[1], "", ""), DiagnoseBase::kBekker);
  try {
    ParseDiagnoseBase("Bekker", "command line", "--base");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "command line: --base: must be rft or bekker, got 'Bekker'");
  }
}

TEST(OptionNames, CalibrationLawNamesParseInEnumOrder) {
  const std::vector<std::string> names = dataset::CalibrationLawNames();
  ASSERT_EQ(names, (std::vector<std::string>{"rft", "bekker"}));
  EXPECT_EQ(dataset::ParseCalibrationLaw(names[0], "", ""), dataset::CalibrationLaw::kRft);
  EXPECT_EQ(dataset::ParseCalibrationLaw(names[1], "", ""), dataset::CalibrationLaw::kBekker);
  try {
    dataset::ParseCalibrationLaw("li2013", "touchdown.calibrate", "law");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "touchdown.calibrate: law: must be rft or bekker, got 'li2013'");
  }
}

}  // namespace
}  // namespace touchdown::gap

// Every confidence interval takes its Student t factor from one function
// (drop_tests/util/student_t.h, Boost.Math). The diagnose fitter's own table skipped df = 3 (2.776, the
// df 4 value, instead of 3.182) and shifted every df from 3 to 29.
#include "drop_tests/util/student_t.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace touchdown::io {
namespace {

TEST(StudentT, KnownQuantilesAt95Percent) {
  // Two-sided 95 % (the 97.5 % quantile), from any t table to three decimals.
  EXPECT_NEAR(StudentTTwoSided(0.95, 1), 12.706, 5e-4);
  EXPECT_NEAR(StudentTTwoSided(0.95, 2), 4.303, 5e-4);
  EXPECT_NEAR(StudentTTwoSided(0.95, 3), 3.182, 5e-4);
  EXPECT_NEAR(StudentTTwoSided(0.95, 4), 2.776, 5e-4);
  EXPECT_NEAR(StudentTTwoSided(0.95, 10), 2.228, 5e-4);
  EXPECT_NEAR(StudentTTwoSided(0.95, 30), 2.042, 5e-4);
  EXPECT_NEAR(StudentTTwoSided(0.95, 1e9), 1.95996, 1e-5);  // the normal limit
}

TEST(StudentT, OtherConfidenceLevels) {
  EXPECT_NEAR(StudentTTwoSided(0.90, 10), 1.812, 5e-4);
  EXPECT_NEAR(StudentTTwoSided(0.99, 10), 3.169, 5e-4);
}

TEST(StudentT, RefusesMeaninglessArguments) {
  EXPECT_THROW(StudentTTwoSided(0.95, 0.0), std::invalid_argument);
  EXPECT_THROW(StudentTTwoSided(0.95, -1.0), std::invalid_argument);
  EXPECT_THROW(StudentTTwoSided(1.0, 5.0), std::invalid_argument);
  EXPECT_THROW(StudentTTwoSided(0.0, 5.0), std::invalid_argument);
}

}  // namespace
}  // namespace touchdown::io

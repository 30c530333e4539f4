#include "drop_tests/util/percentile.h"

#include <cmath>

#include <gtest/gtest.h>

namespace touchdown::io {
namespace {

TEST(Percentile, InterpolatesBetweenOrderStatistics) {
  const std::vector<double> v{5.0, 1.0, 4.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(Percentile(v, 50), 3.0);
  EXPECT_DOUBLE_EQ(Percentile(v, 95), 4.8);   // h = 4 x 0.95 = 3.8: 4 + 0.8 (5 - 4)
  EXPECT_DOUBLE_EQ(Percentile(v, 99), 4.96);  // h = 3.96
  EXPECT_DOUBLE_EQ(Percentile(v, 100), 5.0);
  EXPECT_DOUBLE_EQ(Percentile(v, 0), 1.0);
  EXPECT_DOUBLE_EQ(Percentile({7.5}, 95), 7.5);
  EXPECT_DOUBLE_EQ(Percentile({4.0, 1.0, 3.0, 2.0}, 50), 2.5);  // an even count: the middle two's mean
  EXPECT_TRUE(std::isnan(Percentile({}, 50)));
  EXPECT_TRUE(std::isnan(Percentile({std::nan("")}, 50)));
  EXPECT_DOUBLE_EQ(Percentile({std::nan(""), 2.0, 1.0}, 100), 2.0);  // NaNs ignored
  // numpy.percentile([0, 10, 20, 30], 95) = 28.5
  EXPECT_DOUBLE_EQ(Percentile({30, 0, 20, 10}, 95), 28.5);
}

}  // namespace
}  // namespace touchdown::io

// The study's statistics against answers known by hand: percentiles (definition 7), the exact
// binomial interval (closed forms at 0 of n and n of n, a textbook value, and its defining tail
// probabilities), exceedance curves, histograms and the p = 0.5 contour.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "drop_tests/stability/study_statistics.h"

namespace touchdown::stability {
namespace {

// P[X >= k] and P[X <= k] of Binomial(n, p), summed term by term.
double UpperTail(int k, int n, double p) {
  double sum = 0.0;
  for (int j = k; j <= n; ++j) sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(j + 1.0) - std::lgamma(n - j + 1.0)) *
                                      std::pow(p, j) * std::pow(1.0 - p, n - j);
  return sum;
}
double LowerTail(int k, int n, double p) { return 1.0 - UpperTail(k + 1, n, p); }

TEST(StudyStatistics, ClopperPearsonMatchesClosedFormsAndItsDefinition) {
  for (int n : {1, 2, 10, 100, 10000}) {
    SCOPED_TRACE(n);
    const BinomialInterval none = ClopperPearson(0, n);
    EXPECT_EQ(none.low, 0.0);
    EXPECT_NEAR(none.high, 1.0 - std::pow(0.025, 1.0 / n), 1e-12);
    const BinomialInterval all = ClopperPearson(n, n);
    EXPECT_NEAR(all.low, std::pow(0.025, 1.0 / n), 1e-12);
    EXPECT_EQ(all.high, 1.0);
  }
  // 5 of 10: [0.187086, 0.812914] (e.g. Agresti & Coull 1998; R binom.test(5, 10)).
  const BinomialInterval half = ClopperPearson(5, 10);
  EXPECT_NEAR(half.low, 0.187086, 1e-6);
  EXPECT_NEAR(half.high, 0.812914, 1e-6);
  // The definition: each bound leaves 2.5 % in its tail.
  for (auto [k, n] : {std::pair{3, 10}, std::pair{1, 40}, std::pair{17, 20}}) {
    const BinomialInterval i = ClopperPearson(k, n);
    EXPECT_NEAR(UpperTail(k, n, i.low), 0.025, 1e-9) << k << "/" << n;
    EXPECT_NEAR(LowerTail(k, n, i.high), 0.025, 1e-9) << k << "/" << n;
  }
  const BinomialInterval nothing = ClopperPearson(0, 0);
  EXPECT_EQ(nothing.low, 0.0);
  EXPECT_EQ(nothing.high, 1.0);
}

TEST(StudyStatistics, ExceedanceIsTheFractionStrictlyAbove) {
  const std::vector<ExceedancePoint> e = Exceedance({2, 1, 3, 2, std::nan("")});
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].x, 1.0);
  EXPECT_DOUBLE_EQ(e[0].probability, 0.75);
  EXPECT_EQ(e[1].x, 2.0);
  EXPECT_DOUBLE_EQ(e[1].probability, 0.25);
  EXPECT_EQ(e[2].x, 3.0);
  EXPECT_EQ(e[2].probability, 0.0);
}

TEST(StudyStatistics, HistogramBinsCoverMinToMax) {
  const Histogram h = MakeHistogram({0, 1, 2, 3, 4, 10}, 5);
  EXPECT_EQ(h.low, 0.0);
  EXPECT_EQ(h.width, 2.0);
  EXPECT_EQ(h.counts, (std::vector<int64_t>{2, 2, 1, 0, 1}));  // 10 in the last, closed bin
  const Histogram one = MakeHistogram({3, 3}, 5);
  EXPECT_EQ(one.counts, (std::vector<int64_t>{2}));
  EXPECT_EQ(one.low, 2.5);
}

TEST(StudyStatistics, ContourRunsWhereTheFieldCrossesTheLevel) {
  // 3 x 2 cells (x major): probability 0, 0.25 | 1, 0.75 | 1, 1 -> the 0.5 line between x columns 0 and 1.
  const std::vector<double> p = {0.0, 0.25, 1.0, 0.75, 1.0, 1.0};
  const auto segments = ContourSegments(p, 3, 2, {1.0, 3.0, 5.0}, {10.0, 20.0}, 0.5);
  ASSERT_EQ(segments.size(), 1u);
  // Bottom side: 0 -> 1 crosses at the middle (x = 2); top side: 0.25 -> 0.75 crosses at x = 2 too.
  for (const MapPoint& point : segments[0]) EXPECT_NEAR(point.x, 2.0, 1e-12);
  EXPECT_NEAR(std::min(segments[0][0].y, segments[0][1].y), 10.0, 1e-12);
  EXPECT_NEAR(std::max(segments[0][0].y, segments[0][1].y), 20.0, 1e-12);
  // A cell without data breaks the line; a field that never crosses has none.
  EXPECT_TRUE(ContourSegments({0.0, std::nan(""), 1.0, 1.0}, 2, 2, {0, 1}, {0, 1}, 0.5).empty());
  EXPECT_TRUE(ContourSegments({0.0, 0.0, 0.2, 0.4}, 2, 2, {0, 1}, {0, 1}, 0.5).empty());
}

}  // namespace
}  // namespace touchdown::stability

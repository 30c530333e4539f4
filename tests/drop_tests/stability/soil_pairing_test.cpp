// The soil pairing's comparison on hand-made records, against its closed forms: the flips named,
// P(tip) on both sides, and each outcome's share var(drawn - best) / var(drawn).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "drop_tests/stability/soil_pairing.h"

namespace touchdown::stability {
namespace {

sweep::DropRecord PairLanding(int64_t i, bool tipped, double max_tilt_deg) {
  sweep::DropRecord r;
  r.index = i;
  r.drop_id = "d" + std::to_string(i);
  r.ok = true;
  r.tipped_over = tipped ? 1.0 : 0.0;
  r.time_to_rest_s = tipped ? std::nan("") : 1.0;
  r.max_tilt_deg = max_tilt_deg;
  r.final_penetration_m = 0.1;
  return r;
}

TEST(SoilPairing, NamesTheFlipsAndSharesTheVarianceAsTheClosedFormSays) {
  // 100 landings; drawn: every tenth tips (0, 10, ... 90); at the best values 10-90 and 5 tip, so
  // the soil flips d0 (tips only drawn) and d5 (only at the best values). Standing in both: drawn
  // max tilt twice the best value's, so drawn - best = best and the share is var(b) / var(2 b) = 1/4.
  std::vector<int64_t> indices;
  std::vector<sweep::DropRecord> drawn;
  std::vector<sweep::DropRecord> best;
  for (int64_t i = 0; i < 100; ++i) {
    indices.push_back(i);
    const double tilt = 1.0 + 0.1 * double(i);
    drawn.push_back(PairLanding(i, i % 10 == 0, 2.0 * tilt));
    best.push_back(PairLanding(i, (i % 10 == 0 && i != 0) || i == 5, tilt));
  }
  const SoilPairingReport p = PairBySoil(indices, drawn, best);
  EXPECT_EQ(p.landings, 100);
  EXPECT_EQ(p.failed, 0);
  EXPECT_EQ(p.tipped_drawn, 10);
  EXPECT_EQ(p.tipped_best, 10);
  EXPECT_EQ(p.tipped_only_drawn, std::vector<std::string>{"d0"});
  EXPECT_EQ(p.tipped_only_best, std::vector<std::string>{"d5"});
  ASSERT_GE(p.outcomes.size(), 2u);
  const PairedOutcome& tip = p.outcomes[0];
  EXPECT_EQ(tip.outcome, "tipped_over");
  // Differences +1 (d0), -1 (d5), else 0: variance 2 / 99; the indicator's 10 x 90 / 100 / 99.
  EXPECT_NEAR(tip.difference_variance, 2.0 / 99.0, 1e-15);
  EXPECT_NEAR(tip.variance, 9.0 / 99.0, 1e-15);
  EXPECT_NEAR(tip.share, 2.0 / 9.0, 1e-14);
  const PairedOutcome* tilt = nullptr;
  for (const PairedOutcome& o : p.outcomes)
    if (o.outcome == "max_tilt_deg") tilt = &o;
  ASSERT_NE(tilt, nullptr);
  EXPECT_EQ(tilt->landings, 89);  // not d5 nor the ten drawn tip-overs
  EXPECT_NEAR(tilt->share, 0.25, 1e-14);
  EXPECT_NEAR(tilt->abs_difference_max, 1.0 + 0.1 * 99.0, 1e-12);  // d99's best-value tilt
}

TEST(SoilPairing, ALandingFailedOnEitherSideIsNotPaired) {
  std::vector<sweep::DropRecord> drawn{PairLanding(0, false, 3.0), PairLanding(1, true, 50.0), PairLanding(2, false, 4.0)};
  std::vector<sweep::DropRecord> best{PairLanding(0, false, 3.0), PairLanding(1, false, 30.0)};
  drawn[2].ok = false;
  const SoilPairingReport p = PairBySoil({0, 1, 2}, drawn, best);
  EXPECT_EQ(p.landings, 2);
  EXPECT_EQ(p.failed, 1);
  EXPECT_EQ(p.tipped_only_drawn, std::vector<std::string>{"d1"});
  EXPECT_EQ(p.interval_best.low, 0.0);  // 0 of 2 at the best values
}

}  // namespace
}  // namespace touchdown::stability

#include <gtest/gtest.h>

#include <cmath>

#include "drop_tests/validation/power_law_fit.h"

namespace touchdown::validation {
namespace {

TEST(PowerLawFit, RecoversASyntheticPowerLaw) {
  std::vector<double> x, y;
  for (const double xi : {0.02, 0.05, 0.11, 0.3, 0.4, 2.5}) x.push_back(xi), y.push_back(3.7 * std::pow(xi, 0.3712));
  const PowerLaw fit = FitPowerLaw(x, y);
  EXPECT_NEAR(fit.exponent, 0.3712, 1e-12);
  EXPECT_NEAR(fit.prefactor, 3.7, 1e-12);
}

TEST(PowerLawFit, IsTheLeastSquaresSlopeInLogLog) {
  // Two points: the slope through them; three with noise: the closed-form least-squares slope.
  EXPECT_NEAR(FitPowerLaw({1.0, 4.0}, {2.0, 1.0}).exponent, -0.5, 1e-14);
  const std::vector<double> x{1.0, 2.0, 4.0}, y{1.0, 2.5, 3.5};
  double mx = 0, my = 0;
  for (int i = 0; i < 3; ++i) mx += std::log(x[i]) / 3, my += std::log(y[i]) / 3;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < 3; ++i)
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my), sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  EXPECT_NEAR(FitPowerLaw(x, y).exponent, sxy / sxx, 1e-13);
}

TEST(PowerLawFit, RefusesWhatHasNoSlope) {
  EXPECT_THROW(FitPowerLaw({1.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(FitPowerLaw({1.0, 1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(FitPowerLaw({1.0, 2.0}, {0.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(FitPowerLaw({1.0, 2.0}, {1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace touchdown::validation

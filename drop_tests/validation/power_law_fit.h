#pragma once
// A power law y = c x^p fitted by least squares on log y against log x (Eigen), the way a
// measured scaling exponent is read off a log-log plot: the simulated exponent of a trend is
// this fit over the measured range.
#include <vector>

namespace touchdown::validation {

struct PowerLaw {
  double exponent = 0.0;
  double prefactor = 0.0;  // c
};

// Throws std::invalid_argument unless x and y have the same size >= 2, every value is positive
// and finite, and x holds at least two distinct values.
PowerLaw FitPowerLaw(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace touchdown::validation

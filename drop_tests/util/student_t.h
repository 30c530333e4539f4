#pragma once
// Student's t quantiles for every confidence interval touchdown reports (calibrate's zeta,
// diagnose's effect parameters): one place, from Boost.Math's students_t, for any degrees of
// freedom (fractional ones too).

namespace touchdown::io {

// The half-width factor of a two-sided interval at `confidence` (0.95: the 97.5 % quantile) with
// `degrees_of_freedom` > 0. Throws std::invalid_argument outside those ranges.
double StudentTTwoSided(double confidence, double degrees_of_freedom);

}  // namespace touchdown::io

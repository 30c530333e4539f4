#pragma once
// Percentiles, one definition for every study, trade and diagnosis figure and summary.
#include <vector>

namespace touchdown::io {

// The q-th percentile (q in [0, 100]) of `values` (NaNs ignored; NaN when none is left): linear
// interpolation between order statistics, x(h) with h = (n - 1) q / 100 on the sorted values
// x(0) <= ... <= x(n-1) (Hyndman & Fan's definition 7, numpy's and R's default); the 100th is the
// largest value, the 50th the median (the mean of the middle two of an even count).
double Percentile(std::vector<double> values, double q);

}  // namespace touchdown::io

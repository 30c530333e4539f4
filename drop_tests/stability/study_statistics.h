#pragma once
// The statistics of a stability study, each with its definition (docs/stability_studies.md):
// percentiles, the exact binomial interval of a probability, exceedance curves, histograms, and
// the contours of a binned probability map.
#include <array>
#include <cstdint>
#include <vector>

#include "drop_tests/util/percentile.h"

namespace touchdown::stability {

using io::Percentile;  // drop_tests/util/percentile.h

struct BinomialInterval {
  double low = 0.0, high = 1.0;
};
// The exact (Clopper-Pearson) two-sided interval of a probability from `successes` out of
// `trials` at `confidence` (e.g. 0.95): each tail alpha/2 (Boost.Math). 0 of n gives
// [0, 1 - (alpha/2)^(1/n)], n of n [(alpha/2)^(1/n), 1]; no trials gives [0, 1].
BinomialInterval ClopperPearson(int64_t successes, int64_t trials, double confidence = 0.95);

struct ExceedancePoint {
  double x = 0.0;
  double probability = 0.0;  // P[X > x], the fraction of values above x
};
// The empirical exceedance curve: one point per distinct value (NaNs ignored), ascending, with
// the fraction of values strictly greater than it (the last point's is 0).
std::vector<ExceedancePoint> Exceedance(std::vector<double> values);

struct Histogram {
  double low = 0.0, width = 1.0;
  std::vector<int64_t> counts;  // bin k: [low + k width, low + (k + 1) width), the last one closed
};
// `bins` equal bins over [min, max] of the values (NaNs ignored); a single value gets one bin of
// width 1 around it.
Histogram MakeHistogram(const std::vector<double>& values, int bins);

// A point on a map's plane, in its axes' units.
struct MapPoint {
  double x = 0.0, y = 0.0;
};
// The p = level contour of a field sampled at the centres of an nx by ny grid of cells (value
// index ix * ny + iy; NaN: no data): marching squares on the cell centres with linear
// interpolation along each side, as line segments (pairs of points). Squares with a corner
// without data are skipped; a saddle square joins the crossings pairwise in a fixed order.
std::vector<std::array<MapPoint, 2>> ContourSegments(const std::vector<double>& value, int nx, int ny,
                                                     const std::vector<double>& x_centres,
                                                     const std::vector<double>& y_centres, double level);

}  // namespace touchdown::stability

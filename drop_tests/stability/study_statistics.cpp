#include "drop_tests/stability/study_statistics.h"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/binomial.hpp>

namespace touchdown::stability {

namespace {
std::vector<double> Finite(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }), values.end());
  return values;
}
}  // namespace

BinomialInterval ClopperPearson(int64_t successes, int64_t trials, double confidence) {
  using Binomial = boost::math::binomial_distribution<double>;
  if (trials <= 0) return {};
  const double tail = (1.0 - confidence) / 2.0;
  const double n = static_cast<double>(trials), k = static_cast<double>(successes);
  return {Binomial::find_lower_bound_on_p(n, k, tail, Binomial::clopper_pearson_exact_interval),
          Binomial::find_upper_bound_on_p(n, k, tail, Binomial::clopper_pearson_exact_interval)};
}

std::vector<ExceedancePoint> Exceedance(std::vector<double> values) {
  values = Finite(std::move(values));
  std::sort(values.begin(), values.end());
  std::vector<ExceedancePoint> curve;
  const double n = static_cast<double>(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    if (i + 1 < values.size() && values[i + 1] == values[i]) continue;  // the last of equal values
    curve.push_back({values[i], static_cast<double>(values.size() - 1 - i) / n});
  }
  return curve;
}

Histogram MakeHistogram(const std::vector<double>& values, int bins) {
  const std::vector<double> v = Finite(values);
  Histogram h;
  if (v.empty() || bins < 1) return h;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  if (*hi > *lo) {
    h.low = *lo;
    h.width = (*hi - *lo) / bins;
    h.counts.assign(static_cast<size_t>(bins), 0);
  } else {
    h.low = *lo - 0.5;
    h.width = 1.0;
    h.counts.assign(1, 0);
  }
  const int last = static_cast<int>(h.counts.size()) - 1;
  for (double x : v) ++h.counts[std::clamp(static_cast<int>((x - h.low) / h.width), 0, last)];
  return h;
}

std::vector<std::array<MapPoint, 2>> ContourSegments(const std::vector<double>& value, int nx, int ny,
                                                     const std::vector<double>& xc, const std::vector<double>& yc,
                                                     double level) {
  std::vector<std::array<MapPoint, 2>> segments;
  auto at = [&](int ix, int iy) { return value[static_cast<size_t>(ix) * ny + iy]; };
  for (int ix = 0; ix + 1 < nx; ++ix)
    for (int iy = 0; iy + 1 < ny; ++iy) {
      // Corners counter-clockwise from the lower left; a side crosses where the sign changes.
      const int cx[4] = {ix, ix + 1, ix + 1, ix}, cy[4] = {iy, iy, iy + 1, iy + 1};
      double d[4];
      bool complete = true;
      for (int c = 0; c < 4; ++c) {
        d[c] = at(cx[c], cy[c]) - level;
        complete = complete && !std::isnan(d[c]);
      }
      if (!complete) continue;
      std::vector<MapPoint> crossings;
      for (int c = 0; c < 4; ++c) {
        const int e = (c + 1) % 4;
        if ((d[c] < 0.0) == (d[e] < 0.0)) continue;
        const double t = d[c] / (d[c] - d[e]);
        crossings.push_back({xc[cx[c]] + t * (xc[cx[e]] - xc[cx[c]]), yc[cy[c]] + t * (yc[cy[e]] - yc[cy[c]])});
      }
      for (size_t k = 0; k + 1 < crossings.size(); k += 2) segments.push_back({crossings[k], crossings[k + 1]});
    }
  return segments;
}

}  // namespace touchdown::stability

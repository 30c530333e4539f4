#include "drop_tests/dataset/channel_filter.h"

#include <cmath>

namespace touchdown::dataset {

namespace {
struct FilterClassRow {
  ChannelFilter filter;
  double cfc;
};
constexpr FilterClassRow kFilterClasses[] = {{ChannelFilter::kNone, 0.0},
                                             {ChannelFilter::kCfc60, 60.0},
                                             {ChannelFilter::kCfc180, 180.0},
                                             {ChannelFilter::kCfc600, 600.0},
                                             {ChannelFilter::kCfc1000, 1000.0}};

// One pass of the standard's difference equation over x[first], x[first + step], ... (step +1 or
// -1), started in the steady state of its first sample (the DC gain a0 + a1 + a2 = 1 - b1 - b2).
void CfcPass(const std::vector<double>& x, std::vector<double>& y, const CfcCoefficients& c, bool backward) {
  const long n = static_cast<long>(x.size());
  const long first = backward ? n - 1 : 0, step = backward ? -1 : 1;
  double x1 = x[first], x2 = x[first], y1 = x[first], y2 = x[first];
  for (long k = 0, i = first; k < n; ++k, i += step) {
    const double out = c.a0 * x[i] + c.a1 * x1 + c.a2 * x2 + c.b1 * y1 + c.b2 * y2;
    x2 = x1, x1 = x[i];
    y2 = y1, y1 = out;
    y[i] = out;
  }
}
}  // namespace

const char* ChannelFilterName(ChannelFilter filter) { return NameIn(kChannelFilterNames, filter); }

std::optional<ChannelFilter> ParseChannelFilter(const std::string& name) { return FindName(kChannelFilterNames, name); }

std::string ChannelFilterChoices() { return NameChoices(kChannelFilterNames); }

double ChannelFrequencyClass(ChannelFilter filter) {
  for (const FilterClassRow& row : kFilterClasses)
    if (row.filter == filter) return row.cfc;
  return 0.0;
}

double MinSampleRateHz(ChannelFilter filter) { return 10.0 * ChannelFrequencyClass(filter); }

CfcCoefficients CfcCoefficientsFor(double cfc, double period_s) {
  const double wd = 2.0 * M_PI * cfc * 2.0775;
  const double wa = std::sin(wd * period_s / 2.0) / std::cos(wd * period_s / 2.0);
  const double d = 1.0 + std::sqrt(2.0) * wa + wa * wa;
  CfcCoefficients c;
  c.a0 = wa * wa / d;
  c.a1 = 2.0 * c.a0;
  c.a2 = c.a0;
  c.b1 = -2.0 * (wa * wa - 1.0) / d;
  c.b2 = (-1.0 + std::sqrt(2.0) * wa - wa * wa) / d;
  return c;
}

std::vector<double> ApplyChannelFilter(const std::vector<double>& x, ChannelFilter filter, double period_s) {
  if (filter == ChannelFilter::kNone || x.empty()) return x;
  const CfcCoefficients c = CfcCoefficientsFor(ChannelFrequencyClass(filter), period_s);
  std::vector<double> forward(x.size()), both(x.size());
  CfcPass(x, forward, c, false);
  CfcPass(forward, both, c, true);
  return both;
}

}  // namespace touchdown::dataset

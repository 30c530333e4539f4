#include "drop_tests/dataset/daq_penetration.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "drop_tests/formats/dataset_csv.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::dataset {

namespace {

constexpr double kFreeFallFitWindow_s = 0.020;  // the pre-trigger's last 20 ms, for the surface
constexpr size_t kMinRestSamples = 10;  // averaged for the bias, after the rest's first fifth

// int_t0^t_i y dt for every sample, y linear between samples (the trapezoid rule), t0 anywhere
// in [t_0, t_n-1].
std::vector<double> IntegralFromTouchdown(const std::vector<double>& t, const std::vector<double>& y, double t0) {
  const size_t n = t.size();
  std::vector<double> c(n, 0.0);
  for (size_t i = 1; i < n; ++i) c[i] = c[i - 1] + 0.5 * (t[i] - t[i - 1]) * (y[i] + y[i - 1]);
  const size_t after = std::upper_bound(t.begin(), t.end(), t0) - t.begin();  // the first sample past t0
  const size_t j = std::min(n - 2, after == 0 ? 0 : after - 1);
  const double y0 = y[j] + (y[j + 1] - y[j]) * (t0 - t[j]) / (t[j + 1] - t[j]);
  const double at_t0 = c[j] + 0.5 * (t0 - t[j]) * (y[j] + y0);
  for (double& value : c) value -= at_t0;
  return c;
}

}  // namespace

DisplacementPenetration PenetrationFromDisplacement(const std::vector<double>& t, const std::vector<double>& x, double t0,
                                                    size_t pretrigger_end, const std::string& source) {
  const double period = (t.back() - t.front()) / double(t.size() - 1);
  const size_t window = std::min(pretrigger_end, std::max<size_t>(3, std::lround(kFreeFallFitWindow_s / period)));
  const size_t first = pretrigger_end - window;
  // Scaled time, for a well-conditioned fit: tau = (t - t0) / window length.
  const double scale = std::max(t[pretrigger_end - 1] - t[first], period);
  Eigen::MatrixXd design(window, 3);
  Eigen::VectorXd values(window);
  for (size_t i = 0; i < window; ++i) {
    const double tau = (t[first + i] - t0) / scale;
    design(i, 0) = 1.0, design(i, 1) = tau, design(i, 2) = tau * tau;
    values(i) = x[first + i];
  }
  const Eigen::Vector3d c = design.colPivHouseholderQr().solve(values);
  DisplacementPenetration out;
  out.at_touchdown_m = c(0);
  out.speed_m_s = c(1) / scale;
  out.penetration_m.resize(x.size());
  for (size_t i = 0; i < x.size(); ++i) out.penetration_m[i] = x[i] - out.at_touchdown_m;
  if (out.speed_m_s < 0 && out.penetration_m.back() < 0)
    throw MakeInputError(source, "displacement",
                         "moves up through the drop (" + io::FormatNumber(out.speed_m_s) + " m/s before touchdown, and it ends " +
                             io::FormatNumber(-out.penetration_m.back() * units::kMmPerM) +
                             " mm above where it touched down): positive must be down after the gain (flip its sign?)");
  return out;
}

size_t RestStart(const std::vector<double>& x, double noise, const std::string& source, const std::string& channel) {
  const size_t n = x.size();
  std::vector<double> tail(x.end() - n / 5 - 1, x.end());
  std::nth_element(tail.begin(), tail.begin() + tail.size() / 2, tail.end());
  const double final_level = tail[tail.size() / 2];
  size_t top = 0;
  for (size_t i = 0; i < n; ++i)
    if (std::abs(x[i] - final_level) > std::abs(x[top] - final_level)) top = i;
  const double band = std::max(5.0 * noise, 0.02 * std::abs(x[top] - final_level));
  size_t start = n;
  while (start > top && std::abs(x[start - 1] - final_level) < band) --start;
  if (n - start < kMinRestSamples * 5 / 4 + 1)
    throw MakeInputError(source, channel,
                         "does not settle before the record ends (" + std::to_string(n - start) + " samples within " +
                             io::FormatNumber(band) + " of its final level after its largest excursion): the pad's rest "
                             "after the stop is needed, " + std::to_string(kMinRestSamples * 5 / 4 + 1) + " samples at least");
  return start;
}

AccelerationPenetration PenetrationFromAcceleration(const std::vector<double>& t, const std::vector<double>& a, double t0,
                                                    double v0, size_t pretrigger_end, const std::string& source) {
  const size_t n = t.size();
  // The accelerometer's noise, from the pre-trigger's first differences (a drift cancels).
  std::vector<double> steps;
  for (size_t i = 1; i < pretrigger_end; ++i) steps.push_back(std::abs(a[i] - a[i - 1]));
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double noise = steps.empty() ? 0.0 : 1.4826 * steps[steps.size() / 2] / std::sqrt(2.0);
  const size_t rest = RestStart(a, noise, source, "acceleration");
  const size_t averaged = rest + (n - rest) / 5;  // RestStart leaves 10 samples at least here
  AccelerationPenetration out;
  for (size_t i = averaged; i < n; ++i) out.bias_m_s2 += a[i];
  out.bias_m_s2 /= double(n - averaged);
  std::vector<double> corrected(n);
  for (size_t i = 0; i < n; ++i) corrected[i] = a[i] - out.bias_m_s2;
  std::vector<double> v = IntegralFromTouchdown(t, corrected, t0);
  for (double& value : v) value += v0;
  out.rest_velocity_m_s = v[rest];
  // Where the pad rests its velocity is 0: a quarter of the impact speed left there is no drift
  // but a sign, a gain or a speed that is wrong (a 2 % error in v0 leaves 2 %).
  if (std::abs(out.rest_velocity_m_s) > 0.25 * std::max(std::abs(v0), 0.1))
    throw MakeInputError(source, "acceleration",
                         "v0 + int (a - bias) dt is " + io::FormatNumber(out.rest_velocity_m_s) + " m/s where the pad rests (" +
                             io::FormatNumber((t[rest] - t0) * units::kMsPerS) + " ms after touchdown), not 0: the acceleration must be "
                             "the pad's, positive down (+g in free fall), in m/s^2 after the gain, and impact_speed_m_s its speed "
                             "at touchdown");
  size_t stop = std::upper_bound(t.begin(), t.end(), t0) - t.begin();
  while (stop < rest && v[stop] > 0) ++stop;
  // From the stop on the pad rests; at a crossing, the sample after it holds the interpolated
  // stop instant's zero velocity, so the trapezoid before it ends there.
  double stop_time = t[stop];
  if (stop > 0 && v[stop] <= 0 && v[stop - 1] > 0) stop_time = t[stop - 1] + (t[stop] - t[stop - 1]) * v[stop - 1] / (v[stop - 1] - v[stop]);
  out.stop_s = stop_time - t0;
  for (size_t i = stop; i < n; ++i) v[i] = 0.0;
  out.penetration_m = IntegralFromTouchdown(t, v, t0);
  if (stop > 0 && stop < n && stop_time < t[stop]) {
    // The trapezoid over [t[stop-1], t[stop]] took v linear from v[stop-1] to 0 at t[stop]; the pad
    // stopped at stop_time: the area it covered is v[stop-1] (stop_time - t[stop-1]) / 2.
    const double covered = 0.5 * v[stop - 1] * (stop_time - t[stop - 1]);
    const double taken = 0.5 * v[stop - 1] * (t[stop] - t[stop - 1]);
    for (size_t i = stop; i < n; ++i) out.penetration_m[i] += covered - taken;
  }
  double mean = 0;
  for (size_t i = 0; i < pretrigger_end; ++i) mean += a[i];
  out.pretrigger_acceleration_m_s2 = mean / double(std::max<size_t>(1, pretrigger_end)) - out.bias_m_s2;
  return out;
}

}  // namespace touchdown::dataset

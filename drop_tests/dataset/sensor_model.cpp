#include "drop_tests/dataset/sensor_model.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "drop_tests/dataset/sensor_sampling.h"

namespace touchdown::dataset {

namespace {
constexpr double kPi = std::numbers::pi;

// One second-order section in direct form II transposed: y = b0 x + s1; s1 = b1 x - a1 y + s2;
// s2 = b2 x - a2 y.
struct Biquad {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;
  double s1 = 0.0, s2 = 0.0;
  // Steady state for a constant input x0 (every section here passes a constant unchanged).
  void Settle(double x0) {
    s2 = (b2 - a2) * x0;
    s1 = (b1 - a1) * x0 + s2;
  }
  double Step(double x) {
    const double y = b0 * x + s1;
    s1 = b1 * x - a1 * y + s2;
    s2 = b2 * x - a2 * y;
    return y;
  }
};

// The bilinear transform of w^2 / (s^2 + 2 zeta w s + w^2), pre-warped at w, at grid step h.
Biquad LowPassSection(double f_hz, double zeta, double h) {
  const double k = std::tan(kPi * f_hz * h);  // w_warped h / 2
  const double k2 = k * k, d = 1.0 + 2.0 * zeta * k + k2;
  Biquad q;
  q.b0 = k2 / d;
  q.b1 = 2.0 * k2 / d;
  q.b2 = k2 / d;
  q.a1 = 2.0 * (k2 - 1.0) / d;
  q.a2 = (1.0 - 2.0 * zeta * k + k2) / d;
  return q;
}

// A Butterworth low-pass of even order n as n/2 sections: damping ratios sin(pi (2j - 1) / (2n)).
std::vector<Biquad> Butterworth(int order, double f_hz, double h) {
  std::vector<Biquad> out;
  for (int j = 1; j <= order / 2; ++j) out.push_back(LowPassSection(f_hz, std::sin(kPi * (2 * j - 1) / (2.0 * order)), h));
  return out;
}

double HighestFrequency(const SensorModel& s) { return std::max(s.lowpass_order > 0 ? s.lowpass_cutoff_hz : 0.0, s.load_cell_hz); }

// The time a filter takes to forget its start: ten of its slowest time constants, 1 / (zeta w).
double SettleTime(const SensorModel& s) {
  double t = 0.0;
  if (s.lowpass_order > 0) t = std::max(t, 10.0 / (std::sin(kPi / (2.0 * s.lowpass_order)) * 2 * kPi * s.lowpass_cutoff_hz));
  if (s.load_cell_hz > 0.0) t = std::max(t, 10.0 / (std::max(s.load_cell_damping, 0.01) * 2 * kPi * s.load_cell_hz));
  return t;
}

// Filters x in place through `sections`, each started at rest for x's first value.
void Filter(std::vector<Biquad> sections, std::vector<double>& x) {
  if (x.empty()) return;
  for (Biquad& q : sections) {
    q.Settle(x.front());
    for (double& v : x) v = q.Step(v);
  }
}

// y on the grid t0 + j h, sampled at t: linear interpolation; or its mean over [t - T/2, t + T/2]
// (trapezoids, the ends interpolated).
double Sample(const std::vector<double>& y, double t0, double h, double t, bool mean, double T) {
  const auto at = [&](double tau) {
    const double u = std::clamp((tau - t0) / h, 0.0, double(y.size() - 1));
    const size_t j = std::min(static_cast<size_t>(u), y.size() - 2);
    const double w = u - double(j);
    return y[j] + w * (y[j + 1] - y[j]);
  };
  if (!mean) return at(t);
  const double a = t - 0.5 * T, b = t + 0.5 * T;
  const size_t ja = static_cast<size_t>(std::clamp(std::ceil((a - t0) / h), 0.0, double(y.size() - 1)));
  const size_t jb = static_cast<size_t>(std::clamp(std::floor((b - t0) / h), 0.0, double(y.size() - 1)));
  if (jb < ja) return at(t);
  double sum = 0.0, prev_t = a, prev_y = at(a);
  for (size_t j = ja; j <= jb; ++j) {
    const double tj = t0 + double(j) * h;
    sum += 0.5 * (prev_y + y[j]) * (tj - prev_t);
    prev_t = tj, prev_y = y[j];
  }
  sum += 0.5 * (prev_y + at(b)) * (b - prev_t);
  return sum / T;
}
}  // namespace

std::string DescribeSensor(const SensorModel& s) {
  std::ostringstream out;
  out << std::setprecision(3);
  if (s.lowpass_order > 0)
    out << "instantaneous behind a Butterworth low-pass of order " << s.lowpass_order << " at " << s.lowpass_cutoff_hz
        << " Hz";
  else
    out << SensorSamplingName(s.sampling);
  if (s.load_cell_hz > 0.0) out << ", load cell ringing at " << s.load_cell_hz << " Hz, damping " << s.load_cell_damping;
  return out.str();
}

double FilterGridStep(const SensorModel& s, double sample_period_s) {
  const double f = HighestFrequency(s);
  double h = sample_period_s > 0.0 ? sample_period_s / 10.0 : 1e-5;
  if (f > 0.0) h = std::min(h, 1.0 / (40.0 * f));  // 40 points a period of the fastest filter
  return h;
}

DatasetTrace RecordedTrace(const pad::RigDropResult& result, double g, const rft::EffectTerms& terms,
                           const std::vector<double>& t_s, const SensorModel& s, double sample_period_s) {
  if (!s.HasFilters() || t_s.empty() || result.trace.empty())
    return RecordedTrace(result, g, terms, t_s, s.sampling, sample_period_s);
  const bool mean = s.lowpass_order == 0 && s.sampling == pad::SensorSampling::kPeriodMean && sample_period_s > 0.0;
  const double h = FilterGridStep(s, sample_period_s);
  const double t0 = t_s.front() - SettleTime(s) - (mean ? sample_period_s : 0.0);
  const double t1 = t_s.back() + (mean ? sample_period_s : 0.0) + h;
  const size_t n = static_cast<size_t>(std::ceil((t1 - t0) / h)) + 2;
  std::vector<double> force(n), depth(n);
  for (size_t j = 0; j < n; ++j) {
    const pad::RecordedSample r = pad::RecordedAt(result, g, terms, t0 + double(j) * h);
    force[j] = r.force_N;
    depth[j] = r.penetration_m;
  }
  std::vector<Biquad> both = s.lowpass_order > 0 ? Butterworth(s.lowpass_order, s.lowpass_cutoff_hz, h) : std::vector<Biquad>{};
  std::vector<Biquad> force_chain;
  if (s.load_cell_hz > 0.0) force_chain.push_back(LowPassSection(s.load_cell_hz, s.load_cell_damping, h));
  force_chain.insert(force_chain.end(), both.begin(), both.end());
  Filter(force_chain, force);
  Filter(both, depth);
  DatasetTrace out;
  out.t_s = t_s;
  out.force_N.reserve(t_s.size());
  out.penetration_m.reserve(t_s.size());
  for (const double t : t_s) {
    out.force_N.push_back(Sample(force, t0, h, t, mean, sample_period_s));
    out.penetration_m.push_back(Sample(depth, t0, h, t, mean, sample_period_s));
  }
  return out;
}

double SimulationRateFor_Hz(double sample_rate_hz) { return std::clamp(2.0 * sample_rate_hz, 4e3, 2e4); }

}  // namespace touchdown::dataset

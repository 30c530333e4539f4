#include "drop_tests/dataset/touchdown_onset.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "drop_tests/formats/dataset_csv.h"
#include "rft/input_error.h"

namespace touchdown::dataset {

namespace {

constexpr size_t kOnsetMinPretrigger = 8;   // samples before touchdown, for a baseline at all
constexpr size_t kOnsetMinSamples = 32;
constexpr double kOnsetSearchBack_s = 0.010;  // how far before the last noise-band sample t0 may lie
// k: below 0.7 the jump takes over; a convex pad's force grows as d^3 at most (a profile u ~ r^p
// submerges an area ~ d^(2/p) and a force ~ d^(1 + 2/p): a cone 3, a sphere 2, a flat face 1),
// and d a little faster than t while gravity still accelerates the pad: 3.5 (4 let gapbench's
// slowest curved drop at 1 kHz fit a rise 4.5 ms early).
constexpr double kOnsetMinExponent = 0.7, kOnsetMaxExponent = 3.5;
constexpr int kOnsetExponents = 17;           // log-spaced, 9 % apart (refined by a parabola)
constexpr int kOnsetFineSteps = 20;           // t0 resolved to 1/20 of a sample

double OnsetMedian(std::vector<double> v) {
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

// The rms of y[0..n) about its least-squares line in t: noise without a slow drift.
double RmsAboutLine(const std::vector<double>& t, const std::vector<double>& y, size_t n) {
  if (n < 3) return 0.0;
  double st = 0, sy = 0;
  for (size_t i = 0; i < n; ++i) st += t[i], sy += y[i];
  const double mt = st / n, my = sy / n;
  double stt = 0, sty = 0;
  for (size_t i = 0; i < n; ++i) stt += (t[i] - mt) * (t[i] - mt), sty += (t[i] - mt) * (y[i] - my);
  const double slope = stt > 0 ? sty / stt : 0.0;
  double ss = 0;
  for (size_t i = 0; i < n; ++i) {
    const double r = y[i] - my - slope * (t[i] - mt);
    ss += r * r;
  }
  return std::sqrt(ss / (n - 2));
}

struct RiseFit {
  double t0 = 0, exponent = 1, cost = 0, halfwidth = 0, jump = 0;
  double least_cost = 0;  // the profile's least value (cost is the one at t0, the interval's middle)
};

// min over J >= 0, A >= 0 of sum over the samples after t0 of (y - J - A g)^2, less the
// constant sum of y^2 (the caller adds it): the normal equations, or a bound when one is active.
double JumpAndRiseReduction(double m, double sg, double sgg, double sy, double sgy) {
  double best = 0.0;  // J = A = 0
  auto consider = [&](double jump, double rise) {
    if (jump < 0 || rise < 0) return;
    best = std::min(best, -2 * (jump * sy + rise * sgy) + jump * jump * m + 2 * jump * rise * sg + rise * rise * sgg);
  };
  if (m > 0) consider(sy / m, 0.0);
  if (sgg > 0) consider(0.0, sgy / sgg);
  const double det = m * sgg - sg * sg;
  if (det > 1e-12 * m * sgg) consider((sy * sgg - sg * sgy) / det, (m * sgy - sg * sy) / det);
  return best;
}

// The rise after t0 fitted to y[a..b] with t0 in [lo, hi]: either A (t - t0)^k, a power of the
// time since contact (k on a log grid, refined by a parabola in log k), or J + A (t - t0), a jump
// at contact and then a straight rise (a flat face: its dynamic term, then its force growing with
// depth at a constant area). J and A >= 0 in closed form; t0 on a grid of one sample, then of
// 1/20 sample around the best. Between two samples the jump's place is not in the samples (J and
// t0 trade off exactly along a straight rise): the profile is flat there, and the estimate (the
// middle of its low interval, below) lands between them.
class RiseFitter {
 public:
  RiseFitter(const std::vector<double>& t, const std::vector<double>& y, size_t a, size_t b, bool jump)
      : t_(t), y_(y), a_(a), b_(b), jump_(jump) {
    if (jump)
      exponents_.push_back(1.0);  // a flat face: the jump, then a force growing with depth at constant area
    else
      for (int j = 0; j < kOnsetExponents; ++j)
        exponents_.push_back(kOnsetMinExponent *
                             std::pow(kOnsetMaxExponent / kOnsetMinExponent, double(j) / (kOnsetExponents - 1)));
    for (size_t i = a; i <= b; ++i) sum_yy_ += y[i] * y[i], rise_ = std::max(rise_, std::abs(y[i]));
  }

  // The cost at t0, minimised over J, A and k; `exponent` gets the best k.
  double Profile(double t0, double* exponent) const {
    std::vector<double> costs(exponents_.size());
    logs_.clear();
    for (size_t i = a_; i <= b_; ++i) logs_.push_back(t_[i] > t0 ? std::log(t_[i] - t0) : -kHuge);
    size_t best = 0;
    for (size_t j = 0; j < exponents_.size(); ++j) {
      double m = 0, sg = 0, sgg = 0, sy = 0, sgy = 0;
      for (size_t i = a_; i <= b_; ++i) {
        const double l = logs_[i - a_];
        if (l == -kHuge) continue;
        const double g = std::exp(exponents_[j] * l);
        m += 1, sg += g, sgg += g * g, sy += y_[i], sgy += g * y_[i];
      }
      costs[j] = std::max(0.0, sum_yy_ + (jump_ ? JumpAndRiseReduction(m, sg, sgg, sy, sgy)
                                                : JumpAndRiseReduction(0.0, 0.0, sgg, 0.0, sgy)));
      if (costs[j] < costs[best]) best = j;
    }
    *exponent = exponents_[best];
    if (best == 0 || best + 1 >= exponents_.size()) return costs[best];
    // The parabola through the three costs around the best, in log k.
    const double c0 = costs[best - 1], c1 = costs[best], c2 = costs[best + 1];
    const double denominator = c0 - 2 * c1 + c2;
    if (!(denominator > 0)) return c1;
    const double shift = 0.5 * (c0 - c2) / denominator;  // in grid steps, within (-0.5, 0.5)
    *exponent = exponents_[best] * std::pow(exponents_[1] / exponents_[0], shift);
    return std::max(0.0, c1 - 0.25 * (c0 - c2) * shift);
  }

  double Parameters() const { return 3.0; }  // t0, A and J or k

  // The fitted jump J at (t0, k): the normal equations' solution, 0 where it would be negative.
  double JumpAt(double t0, double exponent) const {
    double m = 0, sg = 0, sgg = 0, sy = 0, sgy = 0;
    for (size_t i = a_; i <= b_; ++i) {
      if (t_[i] <= t0) continue;
      const double g = std::pow(t_[i] - t0, exponent);
      m += 1, sg += g, sgg += g * g, sy += y_[i], sgy += g * y_[i];
    }
    const double det = m * sgg - sg * sg;
    return det > 1e-12 * m * sgg ? std::max(0.0, (sy * sgg - sg * sgy) / det) : 0.0;
  }
  size_t Samples() const { return b_ - a_ + 1; }

  RiseFit Fit(double lo, double hi, double period) const {
    // Coarse: one sample apart over the whole range.
    auto best_on = [&](double from, double to, double step, std::vector<double>* ts, std::vector<double>* cs) {
      ts->clear(), cs->clear();
      const int steps = std::max(1, static_cast<int>(std::ceil((to - from) / step)));
      for (int s = 0; s <= steps; ++s) {
        const double t0 = from + (to - from) * s / steps;
        double k = 1;
        ts->push_back(t0);
        cs->push_back(Profile(t0, &k));
      }
      return static_cast<size_t>(std::min_element(cs->begin(), cs->end()) - cs->begin());
    };
    std::vector<double> ts, cs;
    const size_t coarse = best_on(lo, hi, period, &ts, &cs);
    const double from = std::max(lo, ts[coarse] - 1.5 * period), to = std::min(hi, ts[coarse] + 1.5 * period);
    const size_t fine = best_on(from, to, period / kOnsetFineSteps, &ts, &cs);
    RiseFit fit;
    fit.t0 = ts[fine];
    fit.cost = cs[fine];
    if (fine > 0 && fine + 1 < ts.size()) {  // the parabola's vertex between the grid's neighbours
      const double c0 = cs[fine - 1], c1 = cs[fine], c2 = cs[fine + 1], d = c0 - 2 * c1 + c2;
      if (d > 0) fit.t0 += 0.5 * (c0 - c2) / d * (ts[1] - ts[0]);
    }
    fit.cost = std::min(fit.cost, Profile(fit.t0, &fit.exponent));
    // Delta chi^2 = 1: where the cost stays within one residual variance of its minimum (at least
    // that of a 10-bit DAQ's step, 1e-3 of the rise: a noiseless record has an interval too).
    // The estimate is the interval's middle: where the samples cannot place t0 (a jump between two
    // samples with a straight rise after it fits at every t0 in between) the profile is flat, and
    // its lowest point would be wherever rounding puts it.
    const double variance =
        std::max(fit.cost / std::max<double>(1.0, double(b_ - a_ + 1) - Parameters()), std::pow(1e-3 * rise_, 2));
    fit.least_cost = fit.cost;
    const double limit = fit.cost + variance;
    const double step = period / kOnsetFineSteps;
    double left = fit.t0, right = fit.t0, k = 1;
    while (left - step >= lo && Profile(left - step, &k) <= limit && fit.t0 - left < 20 * period) left -= step;
    while (right + step <= hi && Profile(right + step, &k) <= limit && right - fit.t0 < 20 * period) right += step;
    fit.halfwidth = std::max(0.5 * (right - left), 0.5 * step);
    fit.t0 = 0.5 * (left + right);
    fit.cost = Profile(fit.t0, &fit.exponent);
    if (jump_) fit.jump = JumpAt(fit.t0, fit.exponent);
    return fit;
  }

 private:
  static constexpr double kHuge = std::numeric_limits<double>::infinity();
  const std::vector<double>& t_;
  const std::vector<double>& y_;
  size_t a_, b_;
  bool jump_;
  std::vector<double> exponents_;
  double sum_yy_ = 0, rise_ = 0;
  mutable std::vector<double> logs_;
};

[[noreturn]] void OnsetFail(const std::string& source, const std::string& message) {
  throw MakeInputError(source, "force", message);
}

std::string AtTime(double t) { return "t = " + io::FormatNumber(t) + " s in the file"; }

}  // namespace

TouchdownOnset DetectTouchdown(const std::vector<double>& t, const std::vector<double>& force,
                               const OnsetOptions& options, const std::string& source) {
  const size_t n = t.size();
  if (n < kOnsetMinSamples)
    OnsetFail(source, "only " + std::to_string(n) + " samples: a drop record holds a pre-trigger, the stroke and a rest (" +
                          std::to_string(kOnsetMinSamples) + " samples at least)");
  const double period = (t.back() - t.front()) / double(n - 1);
  const double start = OnsetMedian(std::vector<double>(force.begin(), force.begin() + kOnsetMinPretrigger));
  const size_t top = std::max_element(force.begin(), force.end()) - force.begin();
  const size_t bottom = std::min_element(force.begin(), force.end()) - force.begin();
  if (start - force[bottom] > force[top] - start)
    OnsetFail(source, "its largest excursion is negative (" + io::FormatNumber(force[bottom] - start) + " N from its start at " +
                          AtTime(t[bottom]) + "): positive must be the soil pushing the pad up (flip the gain's sign?)");
  if (!(force[top] > start)) OnsetFail(source, "never rises above its first samples: no touchdown in the record");
  size_t half = 0;
  while (force[half] - start < 0.5 * (force[top] - start)) ++half;
  if (half < kOnsetMinPretrigger)
    OnsetFail(source, "already at half its peak at " + AtTime(t[half]) + ": the record must start before touchdown (" +
                          std::to_string(kOnsetMinPretrigger) + " pre-trigger samples at least)");
  const double guard = std::max(2.0 * period, options.guard_s);

  TouchdownOnset onset;
  // Pass 0 takes a robust baseline from the first half of the samples before the half-peak
  // crossing; pass 1 the pre-trigger that pass 0 found.
  size_t pre = std::max(kOnsetMinPretrigger, half / 2);
  for (int pass = 0; pass < 2; ++pass) {
    double baseline = 0, sigma = 0;
    if (pass == 0) {
      baseline = OnsetMedian(std::vector<double>(force.begin(), force.begin() + pre));
      for (size_t i = 0; i < pre; ++i) sigma += (force[i] - baseline) * (force[i] - baseline);
      sigma = std::sqrt(sigma / pre);
    } else {
      for (size_t i = 0; i < pre; ++i) baseline += force[i];
      baseline /= pre;
      sigma = RmsAboutLine(t, force, pre);
    }
    const double peak = force[top] - baseline;
    const double threshold = options.threshold_N > 0 ? options.threshold_N : std::max(options.k_sigma * sigma, 0.01 * peak);
    if (!(peak > threshold))
      OnsetFail(source, "its peak (" + io::FormatNumber(peak) + " N above the pre-trigger) does not reach the trigger level " +
                            io::FormatNumber(threshold) + " N: no touchdown in the record");
    // The last sample in the noise band before the half-peak crossing.
    size_t last = half;
    while (last > 0 && force[last] - baseline >= threshold) --last;
    if (force[last] - baseline >= threshold || last + 1 < kOnsetMinPretrigger)
      OnsetFail(source, "rises above the trigger level (" + io::FormatNumber(threshold) + " N) at " + AtTime(t[last + 1]) +
                            ", within the first " + std::to_string(kOnsetMinPretrigger) +
                            " samples: the record must start before touchdown");
    std::vector<double> y(n);
    for (size_t i = 0; i < n; ++i) y[i] = force[i] - baseline;
    const size_t back = static_cast<size_t>(std::lround(kOnsetSearchBack_s / period));
    const size_t a = last > back ? last - back : 0;
    auto window_end = [&](double fraction) {
      size_t b = last + 1;
      while (b < top && y[b] < fraction * peak) ++b;
      return std::min(std::max(b, last + 4), std::max(top, last + 1));  // four samples of the rise for J, A, k
    };
    const double lo = t[a], hi = t[last + 1];
    double t0[3] = {0, 0, 0};
    RiseFit main;
    const double fractions[3] = {0.1, 0.2, 0.3};
    for (int w = 0; w < 3; ++w) {
      // The jump is kept only where the record shows one: Schwarz's criterion between the power
      // law and the jump with a straight rise, and a jump of 5 noise sigma at least. A curved pad
      // has none, and a jump of noise size pulled its t0 late (gapbench, docs/import.md).
      const RiseFitter plain(t, y, a, window_end(fractions[w]), false), jumped(t, y, a, window_end(fractions[w]), true);
      const RiseFit without = plain.Fit(lo, hi, period), with = jumped.Fit(lo, hi, period);
      const double samples = double(plain.Samples());
      const bool take_jump = with.jump > 5.0 * sigma &&
                             samples * std::log(std::max(without.least_cost, 1e-300) / std::max(with.least_cost, 1e-300)) >
                                 std::log(samples);
      RiseFit fit = take_jump ? with : without;
      if (!take_jump) fit.jump = 0.0;
      t0[w] = fit.t0;
      if (w == 1) main = fit;  // the fit to 20 % of the peak
    }
    const double spread = 0.5 * (*std::max_element(t0, t0 + 3) - *std::min_element(t0, t0 + 3));
    onset.t0_s = main.t0;
    onset.exponent = main.exponent;
    onset.jump_N = main.jump;
    onset.fit_spread_s = spread;
    onset.fit_halfwidth_s = main.halfwidth;
    onset.uncertainty_s = 0.5 * period + std::hypot(spread, main.halfwidth);
    onset.threshold_N = threshold;
    pre = 0;
    while (pre < n && t[pre] < main.t0 - guard) ++pre;
    if (pre < kOnsetMinPretrigger)
      OnsetFail(source, "touches down at " + AtTime(main.t0) + ", " + std::to_string(pre) +
                            " samples after the record starts: the record must start before touchdown (" +
                            std::to_string(kOnsetMinPretrigger) + " pre-trigger samples at least)");
  }
  onset.pretrigger_end = pre;
  double mean = 0;
  for (size_t i = 0; i < pre; ++i) mean += force[i];
  onset.baseline_N = mean / pre;
  onset.noise_N = RmsAboutLine(t, force, pre);
  return onset;
}

}  // namespace touchdown::dataset

#include "lander/pad/vertical_peaks.h"

#include <algorithm>

namespace touchdown::pad {

void VerticalPeaks::Observe(const integ::DenseSegment& segment) {
  constexpr int kPoints = 4;
  const double t0 = segment.t_begin(), t1 = segment.t_end();
  for (int i = 1; i <= kPoints; ++i) {
    const double t = i == kPoints ? t1 : t0 + (t1 - t0) * i / kPoints;
    segment.Derivative(t, 1, rate_);
    const double a = up_ * rate_[velocity_];
    Take(m_ * (g_ + a), a);
  }
}

void VerticalPeaks::Take(double force_N, double deceleration_m_s2) {
  peak_force_N_ = std::max(peak_force_N_, force_N);
  max_deceleration_m_s2_ = std::max(max_deceleration_m_s2_, deceleration_m_s2);
}

}  // namespace touchdown::pad

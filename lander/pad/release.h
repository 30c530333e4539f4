#pragma once
// Where a drop or a landing starts: a little above the surface, with the downward speed that
// reaches the requested touchdown speed there. The run then starts in free flight, so its events
// see the touchdown, and still touches down at the speed asked for. The rig, the free pad and the
// lander scenario all start so.
#include <algorithm>
#include <cmath>

namespace touchdown::pad {

// The rig's and the free pad's default for the most the release may lie above the surface.
inline constexpr double kDefaultApproachClearance_m = 0.005;

// The release height above the surface: at most `max_clearance_m`, and at most v^2 / (4 g), so the
// fall gains at most half the touchdown speed's square (a slow touchdown is released lower).
inline double ReleaseClearance(double max_clearance_m, double touchdown_speed_m_s, double gravity_m_s2) {
  const double v = touchdown_speed_m_s, g = gravity_m_s2;
  return g > 0.0 ? std::min(max_clearance_m, v * v / (4.0 * g)) : max_clearance_m;
}

// The downward speed at release, `clearance_m` above the surface, that becomes
// `touchdown_speed_m_s` at the surface under gravity `gravity_m_s2`.
inline double ReleaseSpeed(double touchdown_speed_m_s, double gravity_m_s2, double clearance_m) {
  const double v = touchdown_speed_m_s;
  return std::sqrt(std::max(v * v - 2.0 * gravity_m_s2 * clearance_m, 0.0));
}

}  // namespace touchdown::pad

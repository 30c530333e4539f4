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

// The touchdown speed of a body released at `release_speed_m_s` (downward) `drop_height_m` above
// the surface, in free fall under `gravity_m_s2`: sqrt(v0^2 + 2 g h) (with v0 = 0 exactly
// sqrt(2 g h), the same bits).
inline double TouchdownSpeed(double release_speed_m_s, double gravity_m_s2, double drop_height_m) {
  return std::sqrt(std::pow(release_speed_m_s, 2) + 2.0 * gravity_m_s2 * drop_height_m);
}

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

// The time the approach from a release `clearance_m` above the surface may take before the run
// calls touchdown missed: ten times the fall from rest over that height, plus a second.
inline double ApproachTimeLimit(double clearance_m, double gravity_m_s2) {
  return 10.0 * std::sqrt(2.0 * clearance_m / gravity_m_s2) + 1.0;
}

}  // namespace touchdown::pad

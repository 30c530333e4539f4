#include "drop_tests/scenario/lander_trace_columns.h"

#include "rft/units.h"

namespace touchdown::scenario {

namespace {
using units::kDeg;
using Sample = lander::LanderSample;

std::vector<LanderTraceColumn> MakeColumns() {
  std::vector<LanderTraceColumn> c = {
      {"t_s", [](const Sample& s) { return s.t_s; }},
      {"x_m", [](const Sample& s) { return s.p_WB.x(); }},
      {"y_m", [](const Sample& s) { return s.p_WB.y(); }},
      {"z_m", [](const Sample& s) { return s.p_WB.z(); }},
      {"roll_deg", [](const Sample& s) { return s.attitude.roll_rad / kDeg; }},
      {"pitch_deg", [](const Sample& s) { return s.attitude.pitch_rad / kDeg; }},
      {"yaw_deg", [](const Sample& s) { return s.attitude.yaw_rad / kDeg; }},
      {"tilt_deg", [](const Sample& s) { return s.attitude.tilt_rad / kDeg; }},
  };
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) c.push_back({std::string("v") + axes[k] + "_m_s", [k](const Sample& s) { return s.v_WB_W[k]; }});
  for (int k = 0; k < 3; ++k) c.push_back({std::string("w") + axes[k] + "_rad_s", [k](const Sample& s) { return s.w_WB_W[k]; }});
  c.push_back({"az_m_s2", [](const Sample& s) { return s.a_WB_W.z(); }});
  const int legs = lander::kNumLegs;
  auto per_pad = [&](const std::string& prefix, const std::string& suffix, auto value) {
    for (int i = 0; i < legs; ++i)
      c.push_back({prefix + std::to_string(i + 1) + suffix, [i, value](const Sample& s) { return value(s, i); }});
  };
  per_pad("depth", "_m", [](const Sample& s, int i) { return s.pad_depth_m[i]; });
  per_pad("force", "_N", [](const Sample& s, int i) { return s.pad_force_W[i].norm(); });
  per_pad("fz", "_N", [](const Sample& s, int i) { return s.pad_force_W[i].z(); });
  per_pad("held", "", [](const Sample& s, int i) { return static_cast<double>(s.pad_held[i]); });
  per_pad("stroke", "_m", [](const Sample& s, int i) { return s.stroke_m[i]; });
  c.push_back({"kinetic_J", [](const Sample& s) { return s.kinetic_J; }});
  c.push_back({"potential_J", [](const Sample& s) { return s.potential_J; }});
  c.push_back({"dissipated_J", [](const Sample& s) { return s.dissipated_J; }});
  // The poses: the body's attitude (unit quaternion), then each pad's attitude and ball-joint
  // centre, so that anything can be animated.
  const char* q[4] = {"qw", "qx", "qy", "qz"};
  for (int k = 0; k < 4; ++k) c.push_back({q[k], [k](const Sample& s) { return s.q_WB[k]; }});
  for (int i = 0; i < legs; ++i)
    for (int k = 0; k < 4; ++k)
      c.push_back({"pad" + std::to_string(i + 1) + "_" + q[k], [i, k](const Sample& s) { return s.q_WP[i][k]; }});
  for (int i = 0; i < legs; ++i)
    for (int k = 0; k < 3; ++k)
      c.push_back({"joint" + std::to_string(i + 1) + "_" + axes[k] + "_m", [i, k](const Sample& s) { return s.p_WJ[i][k]; }});
  return c;
}
}  // namespace

const std::vector<LanderTraceColumn>& LanderTraceColumns() {
  static const std::vector<LanderTraceColumn> columns = MakeColumns();
  return columns;
}

}  // namespace touchdown::scenario

#pragma once
// Shared set-up of the lander scenario tests: the paper's scenarios with a coarser pad mesh so the whole
// suite stays fast. Resolution: 16 segments around the rim (a few hundred triangles per pad,
// against about 2k in data/ and the benchmark); every check below compares runs at the same
// resolution, so the mesh size cancels.
#include <array>
#include <cstdio>
#include <string>

#include "drop_tests/scenario/lander_scenario_file.h"
#include "footpad_geom/pad_body_builder.h"
#include "footpad_geom/revolve.h"

namespace touchdown::test {

inline constexpr int kTestAngularSegments = 16;

inline std::string ScenarioPath(const std::string& name) {
  return std::string(TOUCHDOWN_SOURCE_DIR) + "/data/scenarios/" + name + ".yaml";
}

// The pad of `scenario` re-meshed at `segments`, same mass model and ball-joint centre.
inline void CoarsenPad(scenario::LanderScenario& scenario, int segments = kTestAngularSegments) {
  io::PadSpec& pad = scenario.lander.pad;
  geom::PadMassModel mass;
  mass.mass_kg = pad.body.mass_kg;
  // The pad frame's origin is the joint centre, -lowest_z_B above the lowest point on the axis.
  const Eigen::Vector3d reference(0.0, 0.0, -pad.body.lowest_z_B);
  pad.body = geom::MakePadBody(geom::RevolveProfileToMesh(pad.profile, segments), mass, reference, pad.source);
}

inline scenario::LanderScenario CoarseScenario(const std::string& name) {
  scenario::LanderScenario s = scenario::LoadLanderScenario(ScenarioPath(name));
  CoarsenPad(s);
  return s;
}

// A landing of data/studies/lunar_paper_lander.yaml rebuilt from its record in results.sqlite (its
// degrees as stored, so the last bits of its inputs may differ from the study's own), on the study's
// fast model. `soils`: each pad's, "fjs1_lp" (the ground's) or "fjs1_cp" (a patch under the pad);
// `simulation_extra`: more keys for the simulation block (", key: value").
struct LunarStudyLanding {
  std::string name;
  double slope_deg = 0.0;
  double vx_m_s = 0.0, vy_m_s = 0.0;  // horizontal touchdown velocity, x downhill
  double roll_deg = 0.0, pitch_deg = 0.0, yaw_relative_to_slope_deg = 0.0;
  std::array<std::string, 4> soils{"fjs1_lp", "fjs1_lp", "fjs1_lp", "fjs1_lp"};
  std::string simulation_extra = ", pad_spin_tolerance_factor: 10";
};

inline std::string LunarStudyLandingYaml(const LunarStudyLanding& d) {
  std::string patches;
  for (int i = 0; i < 4; ++i)
    if (d.soils[i] != "fjs1_lp")
      patches += "    - {soil: " + d.soils[i] + ", under_pad: " + std::to_string(i + 1) + ", half_width_m: 0.48}\n";
  char buf[2048];
  std::snprintf(buf, sizeof buf, R"(schema_version: 1
type: lander
name: %s
lander: sutoh2017_lander_full_scale
gravity_m_s2: 1.62
ground:
  slope_deg: %.17g
  downhill_azimuth_deg: 0
  soil: fjs1_lp
%s%sinitial:
  touchdown_speed_m_s: 1.4
  horizontal_velocity_m_s: [%.17g, %.17g]
  roll_deg: %.17g
  pitch_deg: %.17g
  yaw_relative_to_slope_deg: %.17g
simulation: {duration_s: 7.5, sample_rate_hz: 200, rtol: 1.0e-5, pad_angular_segments: 24%s}
)",
                d.name.c_str(), d.slope_deg, patches.empty() ? "" : "  patches:\n", patches.c_str(), d.vx_m_s, d.vy_m_s,
                d.roll_deg, d.pitch_deg, d.yaw_relative_to_slope_deg, d.simulation_extra.c_str());
  return buf;
}

}  // namespace touchdown::test

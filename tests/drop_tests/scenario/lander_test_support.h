#pragma once
// Shared set-up of the lander scenario tests: the paper's scenarios with a coarser pad mesh so the whole
// suite stays fast. Resolution: 16 segments around the rim (a few hundred triangles per pad,
// against about 2k in data/ and the benchmark); every check below compares runs at the same
// resolution, so the mesh size cancels.
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

}  // namespace touchdown::test

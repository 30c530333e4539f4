#pragma once
// The types of a four-legged lander drop from a scenario YAML (`touchdown lander SCENARIO.yaml --out DIR`):
// the lander (data/landers/<name>.yaml: body, legs, pads, absorbers, cone limits), the ground
// (level plane or uniform slope, default soil and soil patches), the initial conditions (drop
// height or touchdown speed, horizontal velocity, attitude, angular rate, yaw relative to the
// slope) and the run options; a run: its result and the setup (lander::LanderSetup) it ran on. Loading
// (lander_scenario_file.h) resolves and validates everything before anything runs; lander_setup.h
// builds and runs, lander_outputs.h reports. Schema: docs/lander_dynamics.md.
#include <array>
#include <map>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "drop_tests/scenario/soil_field.h"
#include "drop_tests/scenario/lander_terrain.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/scenario/paper_reading.h"
#include "lander/multibody/lander_simulation.h"
#include "rft/gravity_constants.h"
#include "rft/enum_names.h"

namespace touchdown::scenario {

struct LanderLegSpec {
  Eigen::Vector3d hip_B = Eigen::Vector3d::Zero();
  Eigen::Vector3d joint_B = Eigen::Vector3d::Zero();
  std::optional<lander::ShockAbsorber> absorber;
  std::optional<lander::ConeLimit> cone;
  // The axial load (compression or tension) past which the leg fails, buckling or breaking: a limit
  // the lander's summary checks each leg's load against. The dynamics do not change at it (the
  // landing runs on as if the leg held). Infinite: no limit stated.
  double load_limit_N = std::numeric_limits<double>::infinity();
};

// The legs as the lander file gives them, before the pad places the joints (LanderSpecWithPad).
struct LanderLegLayout {
  double joint_radius_m = 0.0, hip_radius_m = 0.0, hip_height_m = 0.0;  // heights above the pad bottoms
  std::optional<lander::ShockAbsorber> absorber;
  std::optional<lander::ConeLimit> cone;
  double load_limit_N = std::numeric_limits<double>::infinity();  // every leg's (LanderLegSpec)
};

struct LanderSpec {
  std::string name;
  std::string source;
  LanderLegLayout layout;
  double total_mass_kg = 0.0;      // body + pads (the paper's 4.3 kg)
  double body_mass_kg = 0.0;       // resolved: total - pads
  Eigen::Matrix3d body_inertia_B = Eigen::Matrix3d::Zero();
  double cog_height_m = 0.0;       // whole lander's CoG above the pad bottoms, standing level
  io::PadSpec pad;                     // the same pad on every leg
  std::array<LanderLegSpec, lander::kNumLegs> legs;
};

// A square soil patch centred below one pad's joint at release (`under_pad`); its corners are
// known only once the release pose is (ResolveLander).
struct UnderPadSquare {
  int pad_number = 1;        // 1..kNumLegs
  double half_width_m = 0.0;
};

struct LanderPatchSpec {
  std::string name;
  std::string soil;  // soil name as given
  std::variant<std::vector<Eigen::Vector2d>, UnderPadSquare> area;  // corners [m] in the world frame, or a square under a pad
};

struct LanderGroundSpec {
  double height_m = 0.0;            // surface height at the origin
  double slope_rad = 0.0;           // uniform slope angle
  double downhill_azimuth_rad = 0.0;  // direction of steepest descent, from +x towards +y
  rft::LawKind law = rft::LawKind::kLi2013;  // 3D stress law for every soil
  std::string default_soil;
  std::vector<LanderPatchSpec> patches;
  std::optional<SoilFieldSpec> soil_field;  // a random patch field, after the patches (soil_field.h)
  LanderHeightField height_field;  // a terrain raster and/or craters instead of the plane (lander_terrain.h)
  // Every soil the ground names (the default, the patches', the field's), by its reference, as
  // loaded and checked against `law` when the scenario was read: a setup takes them from here
  // instead of reading the files again. Empty for a ground built in memory (then read from files).
  std::map<std::string, rft::SoilParameters> soils;
};

// The pads' attitude at release: parallel to the body (the paper's tiltmeter), or level.
enum class PadAttitude { kBody, kLevel };
inline constexpr std::array<EnumName<PadAttitude>, 2> kPadAttitudeNames{
    {{PadAttitude::kBody, "body"}, {PadAttitude::kLevel, "level"}}};
// The file's word for each ("body", "level"), read and written.
const char* PadAttitudeName(PadAttitude attitude);

struct LanderInitialSpec {
  std::optional<double> drop_height_m;       // pad bottoms above the surface at release
  std::optional<double> touchdown_speed_m_s;  // vertical speed when the first pad touches
  double release_vertical_speed_m_s = 0.0;  // downward, with drop_height_m
  Eigen::Vector2d horizontal_velocity_m_s = Eigen::Vector2d::Zero();  // world x, y
  double roll_rad = 0.0, pitch_rad = 0.0;    // aerospace signs (docs)
  double yaw_relative_to_slope_rad = 0.0;    // body x from the downhill direction
  bool align_to_slope = false;               // body z along the slope normal before roll/pitch
  Eigen::Vector3d angular_rate_B = Eigen::Vector3d::Zero();  // body axes [rad/s]
  PadAttitude pad_attitude = PadAttitude::kBody;
};

struct LanderPaperCheck {
  double roll_pitch_within_deg = 0.0;  // the paper's +-0.5 deg in vacuum; 0 = none
  std::string source;
  bool used_for_fit = false;  // as a campaign's PaperCheck: used to fit a parameter, by `fit_by`
  std::string fit_by;
  std::optional<PaperReading> reading;  // the reading of the paper's LP/CP sentence it compares with
};

struct LanderScenario {
  std::string name;
  std::string description;
  std::string source;
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
  LanderSpec lander;
  LanderGroundSpec ground;
  LanderInitialSpec initial;
  lander::LanderRunOptions options;
  // simulation.pad_angular_segments: the lander's (revolved) pads re-meshed at this many rim
  // segments, a numerical resolution like rtol (0: as the pad file says).
  int pad_angular_segments = 0;
  int pad_file_angular_segments = 0;  // the pad file's own, when pad_angular_segments re-meshed it
  // simulation.pad_rim: the re-meshed pads' rings inscribed in their circles (the pad file's way) or
  // scaled to their circles' areas (geom::RimPolygon); only with pad_angular_segments.
  geom::RimPolygon pad_rim = geom::RimPolygon::kInscribed;
  std::optional<LanderPaperCheck> paper;
  std::string paper_ground_case;  // e.g. "CP LP LP LP" (Table II), informational
  // `touchdown lander --model`: zeta per soil and the effect terms (3D forms), for every soil
  // of the ground (drop_tests/model/contact_model.h MakeContactModel). Not part of the scenario file.
  std::optional<model::ModelFile> model;
};

struct LanderRun {
  LanderScenario scenario;
  lander::LanderSetup setup;
  lander::LanderRunResult result;
  std::array<std::string, lander::kNumLegs> soil_under_pad;  // at rest (or at the end)
};

}  // namespace touchdown::scenario

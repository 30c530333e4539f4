#pragma once
// The YAML pieces the lander file and the lander scenario file share (private to lander_file.cpp,
// lander_scenario_yaml.cpp and lander_scenario_file.cpp): lists of numbers, catalogue names
// relative to the file, the absorber's and the cone limit's fields, the scenario's number fields
// and key tables (drop_tests/formats/key_table.h: the loader's known keys and the resolved copy's
// writer from one list), and the blocks a resolved copy writes.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/scenario/lander_scenario_types.h"
#include "lander/multibody/lander_run.h"
#include "rft/enum_names.h"
#include "rft/gravity_constants.h"

namespace touchdown::scenario::file_yaml {

// A list of exactly n finite numbers (any sign).
std::vector<double> FixedList(const io::YamlFields& f, const std::string& key, size_t n);
// A pad or lander named in `f`, by catalogue name or by a path relative to `f`'s file.
std::string ResolveRelative(const io::YamlFields& f, const std::string& kind, const std::string& name);

// The absorber kinds as files name them (read and written).
// The absorber kinds as files name them (read and written).
inline constexpr std::array<EnumName<lander::ShockAbsorber::Kind>, 2> kAbsorberKindNames{
    {{lander::ShockAbsorber::Kind::kSpringDamper, "spring_damper"}, {lander::ShockAbsorber::Kind::kCrushable, "crushable"}}};
const char* AbsorberKindName(lander::ShockAbsorber::Kind kind);
// The number fields of each absorber kind and of the cone limit, read from a lander file and
// written into a resolved copy (every field, defaults included).
const io::FieldTable<lander::ShockAbsorber>& AbsorberFields(lander::ShockAbsorber::Kind kind);
const io::FieldTable<lander::ConeLimit>& ConeFields();
// An absorber block's keys for its kind, in the order a resolved copy writes them.
io::KeyTable<lander::ShockAbsorber> AbsorberKeys(lander::ShockAbsorber::Kind kind);
void WriteAbsorber(YAML::Emitter& y, const lander::ShockAbsorber& a);

// The number fields of the scenario's sections that the resolved copy writes back as given
// (in the order it writes them); fields that depend on each other stay with their readers.
const io::FieldTable<LanderGroundSpec>& GroundNumberFields();
const io::FieldTable<LanderInitialSpec>& AttitudeNumberFields();
const io::FieldTable<lander::LanderRunOptions>& RunNumberFields();
// ground.craters (lander_terrain.h) and ground.terrain's keys (`file`, `window_m`, `origin_m`).
const io::FieldTable<CraterFieldSpec>& CraterFields();
inline const std::vector<std::string> kTerrainKeys{"file", "window_m", "origin_m"};
inline constexpr const char* kReleaseBodyComKey = "release_body_com_m";
// The scenario's numbers read on their own: the loader reads and the reference documents each
// from its entry here.
inline constexpr io::NumberKey kScenarioGravityKey{"gravity_m_s2", io::Sign::kPositive, &limits::kGravity_m_s2,
                                                   nullptr, rft::kEarthGravity_m_s2};
inline constexpr io::NumberKey kDropHeightKey{"drop_height_m", io::Sign::kNonNegative, &limits::kDropHeight_m,
                                              "one of `drop_height_m`, `touchdown_speed_m_s`"};
inline constexpr io::NumberKey kTouchdownSpeedKey{"touchdown_speed_m_s", io::Sign::kNonNegative, &limits::kSpeed_m_s,
                                                  "one of `drop_height_m`, `touchdown_speed_m_s`"};
inline constexpr io::NumberKey kReleaseVerticalSpeedKey{"release_vertical_speed_m_s", io::Sign::kAny,
                                                        &limits::kAbsSpeed_m_s, nullptr, 0.0};
inline constexpr io::NumberKey kMaxStepKey{"max_step_s", io::Sign::kPositive, nullptr, "no limit"};
inline constexpr io::NumberKey kPatchHalfWidthKey{"half_width_m", io::Sign::kPositive, nullptr, "with `under_pad`"};
inline constexpr io::NumberKey kRollPitchWithinKey{"roll_pitch_within_deg", io::Sign::kPositive, nullptr, "none"};
inline constexpr io::NumberKey kCellSizeKey{"cell_size_m", io::Sign::kPositive};
inline constexpr io::NumberKey kHalfExtentKey{"half_extent_m", io::Sign::kPositive};

using FileName = std::function<std::string(const std::string&)>;

// A resolved copy to write: the scenario, the setup it resolves to, and how the files it names are
// written (relative to the folder the copy lives in).
struct ResolvedToWrite {
  const LanderScenario& s;
  const lander::LanderSetup& setup;
  FileName file;
};

struct PatchToWrite {
  const rft::SoilPatch& patch;
  const std::string& soil;
};

// A scenario's keys, block by block, in the order a resolved copy writes them; a key with no
// writer is one only the user's scenario has (the resolved copy writes what it resolves to
// instead: a patch's polygon, a soil field's cells as patches).
const io::KeyTable<PatchToWrite>& PatchKeys();
const io::KeyTable<ResolvedToWrite>& GroundKeys();
const io::KeyTable<ResolvedToWrite>& InitialKeys();
const io::KeyTable<ResolvedToWrite>& SimulationKeys();
const io::KeyTable<ResolvedToWrite>& PaperKeys();
// The top level (`source` only in a resolved copy, `provenance` only in the user's).
const io::KeyTable<ResolvedToWrite>& LanderScenarioKeys();

void WriteVector(YAML::Emitter& y, const Eigen::Vector3d& v, double scale);
// The resolved copy's `lander` block: the lander file and what it resolves to (masses, pad, legs).
void WriteLanderBlock(YAML::Emitter& y, const LanderSpec& l, const FileName& file);
// The ground's `soils` block: every soil of the terrain as the run sees it (model applied).
void WriteSoilsBlock(YAML::Emitter& y, const LanderScenario& s, const lander::LanderSetup& setup);

}  // namespace touchdown::scenario::file_yaml

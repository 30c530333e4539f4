#pragma once
// The lander scenario's files: the lander file (data/landers), the scenario file and its resolved
// copy (`scenario_resolved.yaml`, which reads back to the same landing). Schema:
// docs/lander_dynamics.md.
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/schema_doc.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/scenario/lander_scenario_types.h"

namespace touchdown::scenario {

LanderSpec LoadLanderSpec(const std::string& name_or_path);
// A lander from its file's YAML as read, possibly edited in memory first (calibrate --targets).
LanderSpec LoadLanderSpec(const io::YamlFields& f);
// The same lander on another pad (a study's pad design): the total mass and the whole lander's CoG
// height stay, so the body's mass and CoM, and the joints (the pad's joint height above its
// bottom), follow the pad. Throws InputError naming the pad file when the pad does not fit: the
// four pads heavier than the lander, or the body's CoM or the hips below the joints.
LanderSpec LanderSpecWithPad(const LanderSpec& spec, const io::PadSpec& pad);
LanderScenario LoadLanderScenario(const std::string& path);
// The reference of a lander scenario's and a lander file's keys (schema_doc.h; `touchdown schema`,
// docs/reference.md).
std::vector<io::BlockDoc> LanderScenarioSchema();
std::vector<io::BlockDoc> LanderFileSchema();
// As LoadLanderScenario; a resolved copy is checked against the files it names by building its setup, which
// comes back in `setup` so that its landing need not build it again (left empty for a scenario
// file). The setup holds for the scenario as loaded: one edited afterwards needs its own.
LanderScenario LoadLanderScenarioWithSetup(const std::string& path, std::optional<lander::LanderSetup>& setup);
// The scenario with its pads meshed as their file says (undoing simulation.pad_angular_segments): a
// study's reference model when its own landings run on coarser pads (stability re-checks).
LanderScenario AtPadFileMesh(const LanderScenario& scenario);

// The keys of a scenario's `initial` block, in the order a resolved copy writes them: the reader
// accepts these (release_body_com_m only in a resolved copy) and the writer writes from this list.
const std::vector<std::string>& LanderInitialKeys();

// The files named are written for `output_dir`, the directory the file finally lives in
// (drop_tests/catalog/paths_in_outputs.h: no absolute paths of this machine). `setup` is the
// scenario's (ResolveLander): the copy states the soils and the release position it gives.
void WriteResolvedLanderScenario(const LanderScenario& scenario, const lander::LanderSetup& setup, const std::string& path,
                                 const std::string& output_dir);
// As above, building the setup first (a copy written without running the landing).
void WriteResolvedLanderScenario(const LanderScenario& scenario, const std::string& path,
                                 const std::string& output_dir);
// The lander alone as a resolved copy's `lander` block states it (masses, pad, legs; files named as
// from `output_dir`), written to `path`: a lander resolves without a ground or a release.
void WriteResolvedLander(const LanderSpec& lander, const std::string& path, const std::string& output_dir);

}  // namespace touchdown::scenario

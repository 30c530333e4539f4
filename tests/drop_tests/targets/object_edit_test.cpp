// calibrate --targets' in-memory edits of lander and pad files keep a scenario's
// simulation.pad_angular_segments: a lander whose file or pad file is edited is read again, and its
// pads must come back at the scenario's resolution, not at the pad file's.
#include "drop_tests/targets/object_edit.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::targets {
namespace {

namespace fs = std::filesystem;

class ObjectEditPadSegments : public testing_scratch::ScratchDirTest {
 protected:
  scenario::LanderScenario Coarse() {
    return scenario::LoadLanderScenario(Write("coarse.yaml",
                                              "schema_version: 1\ntype: lander\nname: coarse\nlander: sutoh2017_lander\n"
                                              "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n"
                                              "simulation: {pad_angular_segments: 32}\n"));
  }
  static Parameter Field(ParameterKind kind, const std::string& file, const std::string& field) {
    Parameter p;
    p.name = field;
    p.kind = kind;
    p.file = fs::weakly_canonical(file).string();
    p.field = field;
    return p;
  }
};

TEST_F(ObjectEditPadSegments, EditedLandersAndPadsKeepTheScenariosResolution) {
  const scenario::LanderScenario s = Coarse();
  const int coarse_triangles = s.lander.pad.body.surface.size();
  const int file_triangles = io::LoadPad(s.lander.pad.source).body.surface.size();
  ASSERT_LT(coarse_triangles, file_triangles);

  const std::vector<Parameter> lander_only = {
      Field(ParameterKind::kLanderField, s.lander.source, "legs.joint_radius_mm")};
  const ObjectEditor lander_editor(lander_only);
  const scenario::LanderSpec wider = lander_editor.EditedLander(s.lander, {320.0}, s.pad_angular_segments);
  EXPECT_EQ(wider.pad.body.surface.size(), coarse_triangles);
  EXPECT_NEAR(wider.legs[0].joint_B.head<2>().norm(), 0.320, 1e-12);
  // Without the scenario's resolution the lander file's pad comes back as its file says.
  EXPECT_EQ(lander_editor.EditedLander(s.lander, {320.0}).pad.body.surface.size(), file_triangles);

  const std::vector<Parameter> pad_too = {Field(ParameterKind::kLanderField, s.lander.source, "legs.joint_radius_mm"),
                                          Field(ParameterKind::kPadField, s.lander.pad.source, "mass_kg")};
  const ObjectEditor pad_editor(pad_too);
  const scenario::LanderSpec heavier = pad_editor.EditedLander(s.lander, {300.0, 0.1}, s.pad_angular_segments);
  EXPECT_EQ(heavier.pad.body.surface.size(), coarse_triangles);
  EXPECT_DOUBLE_EQ(heavier.pad.mass_kg, 0.1);
}

}  // namespace
}  // namespace touchdown::targets

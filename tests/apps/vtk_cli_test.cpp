// The ParaView outputs as a user asks for them (docs/paraview.md): `drop --free --vtk DIR` and
// `force --vtk FILE.vtp` write files that read back, and never replace what touchdown did not write.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/drop_tests/formats/vtk_xml_reader.h"
#include "tests/scratch_dir_test.h"
#include "tests/touchdown_process.h"

namespace {

namespace fs = std::filesystem;

class VtkCli : public touchdown::testing_scratch::ScratchDirTest {
 protected:
  // Exit status of `touchdown args...` (stderr kept in the scratch directory).
  int RunTouchdown(const std::vector<std::string>& args) {
    const pid_t pid = touchdown::testing_process::StartTouchdown(args, "", "/dev/null", Path("stderr"));
    const int status = touchdown::testing_process::WaitForStatus(pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string Stderr() const { return Slurp(Path("stderr")); }
};

const std::vector<std::string> kVtkHexDrop = {"drop", "--pad", "hex", "--soil", "fjs1_cp", "--speed", "1.0",
                                             "--free", "--tilt-deg", "5", "--tilt-axis", "y"};

std::vector<std::string> With(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST_F(VtkCli, FreeDropWritesASeriesAndReplacesOnlyItsOwn) {
  const std::string out = Path("vtk");
  ASSERT_EQ(RunTouchdown(With(kVtkHexDrop, {"--vtk", out})), 0) << Stderr();
  const auto root = touchdown::testing_vtk::ReadXmlFile(out + "/drop.pvd");
  const auto sets = root.One("Collection").All("DataSet");
  ASSERT_GT(sets.size(), 10u);
  for (const auto& d : sets) EXPECT_TRUE(fs::is_regular_file(out + "/" + d.Attribute("file"))) << d.Attribute("file");
  // Its own earlier output is replaced; a directory of the user's is not, nor a file.
  EXPECT_EQ(RunTouchdown(With(kVtkHexDrop, {"--vtk", out})), 0) << Stderr();
  const std::string user_dir = Path("mine");
  fs::create_directories(user_dir);
  const std::string kept = Write("mine/notes.txt", "mine\n");
  EXPECT_EQ(RunTouchdown(With(kVtkHexDrop, {"--vtk", user_dir})), 2);
  const std::string refused = Stderr();
  EXPECT_NE(refused.find(user_dir), std::string::npos) << refused;
  EXPECT_EQ(std::count(refused.begin(), refused.end(), '\n'), 1) << refused;
  EXPECT_EQ(Slurp(kept), "mine\n");
  EXPECT_EQ(fs::directory_iterator(user_dir)->path().filename(), "notes.txt");
  const std::string user_file = Write("file.vtp", "mine\n");
  EXPECT_EQ(RunTouchdown(With(kVtkHexDrop, {"--vtk", user_file})), 2);
  EXPECT_EQ(Slurp(user_file), "mine\n");
  // The rig's drop draws nothing: --vtk needs --free.
  EXPECT_EQ(RunTouchdown({"drop", "--pad", "flat", "--soil", "fjs1_lp", "--speed", "1.0", "--vtk", Path("rig")}), 2);
  EXPECT_NE(Stderr().find("--free"), std::string::npos) << Stderr();
  EXPECT_FALSE(fs::exists(Path("rig")));
}

TEST_F(VtkCli, ForceWritesOnePoseAndRefusesAnExistingFile) {
  const std::string file = Path("pose.vtp");
  const std::vector<std::string> force = {"force", "--pad", "hex", "--soil", "fjs1_lp", "--depth", "0.01",
                                          "--tilt-deg", "10", "--velocity", "0.2,0,-1"};
  ASSERT_EQ(RunTouchdown(With(force, {"--vtk", file})), 0) << Stderr();
  const auto pieces = touchdown::testing_vtk::VtpPieces(touchdown::testing_vtk::ReadXmlFile(file));
  ASSERT_EQ(pieces.size(), 1u);
  const std::vector<double> normal =
      touchdown::testing_vtk::DataArray(pieces[0].One("CellData"), "normal_stress_Pa").Numbers();
  EXPECT_EQ(std::to_string(normal.size()), pieces[0].Attribute("NumberOfPolys"));
  EXPECT_GT(*std::max_element(normal.begin(), normal.end()), 0.0);
  const std::string before = Slurp(file);
  EXPECT_EQ(RunTouchdown(With(force, {"--vtk", file})), 2);
  EXPECT_EQ(Slurp(file), before);
}

}  // namespace

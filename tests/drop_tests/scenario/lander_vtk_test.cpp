// `touchdown lander ... --out DIR` writes DIR/vtk/lander.pvd (drop_tests/scenario/lander_vtk.h) and
// the pads' poses in trace.csv: the series reads back with the lander's parts at each frame, the
// stroke in full, the soil's patches, and the poses that draw it.
#include "drop_tests/scenario/lander_vtk.h"

#include <Eigen/Geometry>
#include <filesystem>
#include <gtest/gtest.h>
#include <set>
#include <sstream>

#include "drop_tests/scenario/lander_leg_load.h"
#include "tests/drop_tests/formats/vtk_xml_reader.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::scenario {
namespace {

using testing_vtk::DataArray;
using testing_vtk::ReadXmlFile;

class LanderVtkTest : public testing_scratch::ScratchDirTest {};

TEST_F(LanderVtkTest, OutputHoldsTheLandingForParaViewAndThePosesInTheTrace) {
  // Case B: pad 1 on the compacted patch, the others on loose soil.
  const LanderRun run = RunLanderScenario(test::CoarseScenario("lander_case_B"));
  const std::string out = Path("out");
  WriteLanderOutputs(run, out);
  const std::vector<lander::LanderSample>& trace = run.result.trace;

  const auto sets = ReadXmlFile(out + "/vtk/lander.pvd").One("Collection").All("DataSet");
  constexpr size_t kParts = 5;
  ASSERT_EQ(sets.size() % kParts, 0u);
  std::set<double> frame_times;
  for (size_t i = 0; i < sets.size(); i += kParts) {
    const double t = std::stod(sets[i].Attribute("timestep"));
    frame_times.insert(t);
    for (size_t p = 0; p < kParts; ++p) {
      EXPECT_EQ(std::stod(sets[i + p].Attribute("timestep")), t);
      EXPECT_EQ(sets[i + p].Attribute("name"),
                (std::vector<std::string>{"pads", "body", "legs", "crater", "soil"}[p]));
      EXPECT_TRUE(std::filesystem::is_regular_file(out + "/vtk/" + sets[i + p].Attribute("file")));
    }
  }
  // Every sample with a pad moving in the soil is a frame (the stroke in full), the first and last too.
  size_t stroke = 0;
  for (const lander::LanderSample& s : trace)
    for (int i = 0; i < lander::kNumLegs; ++i)
      if (s.pad_depth_m[i] > 0.0 && !s.pad_held[i]) {
        EXPECT_TRUE(frame_times.count(s.t_s)) << s.t_s;
        ++stroke;
        break;
      }
  EXPECT_GT(stroke, 10u);
  EXPECT_TRUE(frame_times.count(trace.front().t_s));
  EXPECT_TRUE(frame_times.count(trace.back().t_s));
  EXPECT_LT(frame_times.size(), trace.size() / 4);  // the fall thinned, the rest once

  // A frame in the stroke: four pads with stresses, legs from hip to joint.
  size_t k = 0;
  while (!(trace[k].pad_depth_m[0] > 0.005 && !trace[k].pad_held[0])) ++k;
  const lander::LanderSample& s = trace[k];
  size_t set = 0;
  while (std::stod(sets[set].Attribute("timestep")) != s.t_s) set += kParts;
  const auto pads = testing_vtk::VtpPieces(ReadXmlFile(out + "/vtk/" + sets[set].Attribute("file")));
  ASSERT_EQ(pads.size(), 4u);
  const int elements = run.setup.model.legs[0].pad->surface.size();
  EXPECT_EQ(pads[0].Attribute("NumberOfPolys"), std::to_string(elements));
  const std::vector<double> normal = DataArray(pads[0].One("CellData"), "normal_stress_Pa").Numbers();
  EXPECT_GT(*std::max_element(normal.begin(), normal.end()), 1000.0);
  EXPECT_EQ(DataArray(pads[2].One("CellData"), "pad_number").Numbers().front(), 3.0);
  // The elements' forces (the same evaluation as the stresses) sum to the pad's soil force of the trace.
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const std::vector<double> f = DataArray(pads[i].One("CellData"), "element_force_N").Numbers();
    ASSERT_EQ(f.size(), static_cast<size_t>(3 * elements));
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int e = 0; e < elements; ++e) sum += Eigen::Vector3d(f[3 * e], f[3 * e + 1], f[3 * e + 2]);
    EXPECT_LT((sum - s.pad_force_W[i]).norm(), 1e-10 * s.pad_force_W[i].norm() + 1e-12) << "pad " << i + 1;
  }
  EXPECT_GT(s.pad_force_W[0].norm(), 10.0);
  const auto legs = testing_vtk::VtpPieces(ReadXmlFile(out + "/vtk/" + sets[set + 2].Attribute("file")));
  const std::vector<double> points = DataArray(legs[0].One("Points"), "Points").Numbers();
  ASSERT_EQ(points.size(), 24u);
  for (int i = 0; i < lander::kNumLegs; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(points[6 * i + 3 + c], s.p_WJ[i][c]);
  const std::vector<double> leg_load = DataArray(legs[0].One("CellData"), "leg_force_N").Numbers();
  for (int i = 0; i < lander::kNumLegs; ++i) EXPECT_EQ(leg_load[i], LegAxialForce(run.scenario.lander, s, i));
  EXPECT_GT(leg_load[0], 1.0);
  // The crater under each pad: as deep as the pad in the soil (to the grid's resolution, below its
  // deepest point), nowhere deeper.
  const auto craters = testing_vtk::VtpPieces(ReadXmlFile(out + "/vtk/" + sets[set + 3].Attribute("file")));
  ASSERT_EQ(craters.size(), 4u);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const std::vector<double> d = DataArray(craters[i].One("PointData"), "crater_depth_m").Numbers();
    const double deepest = *std::max_element(d.begin(), d.end());
    double deepest_so_far = 0.0;
    for (size_t n = 0; n <= k; ++n) deepest_so_far = std::max(deepest_so_far, trace[n].pad_depth_m[i]);
    EXPECT_LE(deepest, deepest_so_far + 1e-12) << "pad " << i + 1;
    if (s.pad_depth_m[i] > 0.005) {
      EXPECT_GT(deepest, 0.9 * s.pad_depth_m[i]) << "pad " << i + 1;
    }
  }
  // The soil shows both soils.
  const auto soil = testing_vtk::VtpPieces(ReadXmlFile(out + "/vtk/soil.vtp"));
  const std::vector<double> soils = DataArray(soil[0].One("CellData"), "soil").Numbers();
  EXPECT_EQ(std::set<double>(soils.begin(), soils.end()).size(), 2u);

  // trace.csv: the earlier columns first, unchanged, then the poses.
  std::ifstream csv(out + "/trace.csv");
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("t_s,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg,tilt_deg,", 0), 0u);
  const size_t poses = header.find(",kinetic_J,potential_J,dissipated_J,qw,qx,qy,qz,pad1_qw,pad1_qx,pad1_qy,pad1_qz,");
  ASSERT_NE(poses, std::string::npos);
  EXPECT_EQ(header.substr(header.size() - 32), "joint4_x_m,joint4_y_m,joint4_z_m");
  for (size_t n = 0; n <= k; ++n) std::getline(csv, row);
  std::vector<double> v;
  std::stringstream cells(row);
  for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
  ASSERT_EQ(v.size(), 38u + 4u + 16u + 12u);
  EXPECT_NEAR(v[0], s.t_s, 1e-9);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const Eigen::Quaterniond q(v[42 + 4 * i], v[43 + 4 * i], v[44 + 4 * i], v[45 + 4 * i]);
    EXPECT_NEAR(q.norm(), 1.0, 1e-9);
    EXPECT_NEAR(q.angularDistance(Eigen::Quaterniond(s.q_WP[i][0], s.q_WP[i][1], s.q_WP[i][2], s.q_WP[i][3])), 0.0, 1e-8);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[58 + 3 * i + c], s.p_WJ[i][c], 1e-9);
  }
}

TEST_F(LanderVtkTest, NoVtkLeavesOutOnlyTheSeries) {
  // `touchdown lander --no-vtk`: every other output as before, no vtk/.
  const LanderRun run = RunLanderScenario(test::CoarseScenario("lander_case_A"));
  const std::string out = Path("no_vtk");
  WriteLanderOutputs(run, out, {.vtk = false});
  EXPECT_FALSE(std::filesystem::exists(out + "/vtk"));
  for (const char* file : {"summary.json", "trace.csv", "events.csv", "scenario_resolved.yaml", "plots"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + file)) << file;
}

}  // namespace
}  // namespace touchdown::scenario

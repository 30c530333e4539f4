// `drop --free --vtk DIR` (drop_tests/drop/drop_vtk.h) and the free drop's pose columns: the series
// lists every sample with its time, its frames hold the stresses the contact gives at that pose, and
// the trace carries the pose that draws it.
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/drop_vtk.h"

#include <Eigen/Geometry>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/free_drop_output.h"
#include "drop_tests/model/contact_model.h"
#include "rft/element_stresses.h"
#include "rft/input_error.h"
#include "rft/units.h"
#include "tests/drop_tests/formats/vtk_xml_reader.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::drop {
namespace {

using testing_vtk::DataArray;
using testing_vtk::ReadXmlFile;

class DropVtkTest : public testing_scratch::ScratchDirTest {
 protected:
  static void SetUpTestSuite() {
    pad_ = new io::PadSpec(io::LoadPad("hex"));
    soil_ = new rft::SoilParameters(io::LoadSoil("fjs1_cp"));
    DropConditions c;
    c.impact_speed_m_s = 1.0;
    c.free = true;
    c.tilt_rad = units::DegToRad(5.0);
    c.tilt_axis = pad::TiltAxis::kY;
    c.omega_W = Eigen::Vector3d(0.0, 0.0, 2.0);
    setup_ = new DropSetup(ResolveDrop(*pad_, *soil_, c));
    drop_ = new PadDrop(RunDrop(*setup_));
  }
  static void TearDownTestSuite() {
    delete drop_;
    delete setup_;
    delete soil_;
    delete pad_;
  }
  static io::PadSpec* pad_;
  static rft::SoilParameters* soil_;
  static DropSetup* setup_;
  static PadDrop* drop_;
};
io::PadSpec* DropVtkTest::pad_ = nullptr;
rft::SoilParameters* DropVtkTest::soil_ = nullptr;
DropSetup* DropVtkTest::setup_ = nullptr;
PadDrop* DropVtkTest::drop_ = nullptr;

TEST_F(DropVtkTest, SeriesListsEverySampleWithItsTimeAndTheStressesAtThatPose) {
  const std::string out = Path("vtk");
  WriteDropVtk(*setup_, *drop_, out);
  const std::vector<pad::FreeDropSample>& trace = drop_->free->trace;
  const auto sets = ReadXmlFile(out + "/drop.pvd").One("Collection").All("DataSet");
  // Samples at the same time (the rest event on the output grid) make one frame.
  std::vector<double> times;
  for (const pad::FreeDropSample& s : trace)
    if (times.empty() || s.t_s > times.back()) times.push_back(s.t_s);
  ASSERT_GT(times.size(), 10u);
  ASSERT_EQ(sets.size(), 3 * times.size());  // the pad, the crater and the soil at each time
  for (size_t i = 0; i < times.size(); ++i) {
    EXPECT_EQ(std::stod(sets[3 * i].Attribute("timestep")), times[i]);
    EXPECT_EQ(sets[3 * i].Attribute("name"), "pad");
    EXPECT_EQ(sets[3 * i + 1].Attribute("name"), "crater");
    EXPECT_EQ(sets[3 * i + 2].Attribute("file"), "soil.vtp");
    EXPECT_EQ(std::stod(sets[3 * i + 2].Attribute("timestep")), times[i]);
    EXPECT_TRUE(std::filesystem::is_regular_file(out + "/" + sets[3 * i].Attribute("file")));
    EXPECT_TRUE(std::filesystem::is_regular_file(out + "/" + sets[3 * i + 1].Attribute("file")));
  }

  // A frame in the stroke: its cells are the pad's elements, with the stresses at that sample's pose.
  const size_t k = trace.size() / 3;
  const pad::FreeDropSample& s = trace[k];
  const auto frame = ReadXmlFile(out + "/" + sets[3 * k].Attribute("file"));
  const auto pieces = testing_vtk::VtpPieces(frame);
  ASSERT_EQ(pieces.size(), 1u);
  const rft::SurfaceElements& surface = pad_->body.surface;
  ASSERT_EQ(pieces[0].Attribute("NumberOfPolys"), std::to_string(surface.size()));
  const DropConditions& c = drop_->conditions;
  const rft::SoilContactModel contact =
      model::MakeContactModel({.law = c.law_3d, .soil = DropSoil(*soil_, c.zeta_N_m3, c.atmosphere),
                               .gravity_m_s2 = c.gravity_m_s2, .effects = c.effects});
  const Eigen::Matrix3d R = Eigen::Quaterniond(s.q_WB[0], s.q_WB[1], s.q_WB[2], s.q_WB[3]).toRotationMatrix();
  rft::ElementStresses expected;
  rft::ComputeElementStresses(surface, {R, s.p_WB, s.v_WB_W, s.w_W}, rft::PlaneGround(), *contact.law,
                              contact.pad_terms.depth, &expected);
  const testing_vtk::XmlElement cells = pieces[0].One("CellData");
  const std::vector<double> normal = DataArray(cells, "normal_stress_Pa").Numbers();
  const std::vector<double> depth = DataArray(cells, "depth_m").Numbers();
  ASSERT_EQ(normal.size(), static_cast<size_t>(surface.size()));
  double largest = 0.0;
  for (int i = 0; i < surface.size(); ++i) {
    EXPECT_NEAR(normal[i], expected.normal_Pa[i], 1e-12 * std::abs(expected.normal_Pa[i]));
    EXPECT_NEAR(depth[i], expected.depth_m[i], 1e-12 * std::abs(expected.depth_m[i]));
    largest = std::max(largest, normal[i]);
  }
  EXPECT_GT(largest, 1000.0);  // the pad is in the soil: real stresses, not zeros
  // The elements' forces are the drop's soil force at that sample (vertical, within the contact's
  // reuse of stresses per normal class).
  EXPECT_NEAR(expected.force_W.row(2).sum(), s.force_N, 1e-9 * s.force_N);
  // The written element forces are those forces.
  const std::vector<double> force = DataArray(cells, "element_force_N").Numbers();
  ASSERT_EQ(force.size(), 3u * static_cast<size_t>(surface.size()));
  for (int i = 0; i < surface.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(force[3 * i + c], expected.force_W(c, i));
  // The crater of that frame: as deep as the pad has been (its deepest point to the grid's
  // resolution), nowhere deeper.
  const auto crater = testing_vtk::VtpPieces(ReadXmlFile(out + "/" + sets[3 * k + 1].Attribute("file")));
  const std::vector<double> crater_depth = DataArray(crater[0].One("PointData"), "crater_depth_m").Numbers();
  double deepest = 0.0;
  for (size_t n = 0; n <= k; ++n) deepest = std::max(deepest, trace[n].penetration_m);
  const double crater_deepest = *std::max_element(crater_depth.begin(), crater_depth.end());
  EXPECT_LE(crater_deepest, deepest + 1e-12);
  EXPECT_GT(crater_deepest, 0.8 * deepest);
}

// A free drop on a Bekker soil with shear (sliding): the series is written with the pad's b, and the
// samples carry Janosi's j, growing with the slip, which the frames' stresses take (docs/bekker_soil.md).
TEST_F(DropVtkTest, BekkerSoilWithShearWritesItsSeriesAndCarriesJ) {
  const io::PadSpec flat = io::LoadPad("flat");
  DropConditions c;
  c.impact_speed_m_s = 1.0;
  c.gravity_m_s2 = 1.62;
  c.free = true;
  c.horizontal_speed_m_s = 0.3;
  const DropSetup bekker_setup = ResolveDrop(flat, io::LoadSoil("lunar_nominal_bekker"), c);
  const PadDrop bekker = RunDrop(bekker_setup);
  ASSERT_TRUE(bekker.free);
  const std::vector<pad::FreeDropSample>& trace = bekker.free->trace;
  EXPECT_EQ(trace.front().shear_displacement_m, 0.0);
  EXPECT_GT(trace.back().shear_displacement_m, 0.5 * bekker.free->horizontal_travel_m);
  for (size_t i = 1; i < trace.size(); ++i) EXPECT_GE(trace[i].shear_displacement_m, trace[i - 1].shear_displacement_m);
  const std::string out = Path("bekker_vtk");
  WriteDropVtk(bekker_setup, bekker, out);
  EXPECT_GT(ReadXmlFile(out + "/drop.pvd").One("Collection").All("DataSet").size(), 10u);
}

TEST_F(DropVtkTest, RefusesADirectoryOfTheUsers) {
  std::filesystem::create_directories(Path("mine"));
  Write("mine/keep.txt", "mine\n");
  EXPECT_THROW(CheckDropVtkTarget(Path("mine")), InputError);
  EXPECT_THROW(WriteDropVtk(*setup_, *drop_, Path("mine")), InputError);
  EXPECT_EQ(Slurp(Path("mine/keep.txt")), "mine\n");
}

TEST_F(DropVtkTest, TraceCarriesThePoseAfterTheEarlierColumns) {
  std::ostringstream out;
  WriteFreeDropTraceCsv(*drop_->free, out);
  std::istringstream in(out.str());
  std::string header, row;
  std::getline(in, header);
  EXPECT_EQ(header,
            "t_s,penetration_m,velocity_m_s,force_N,force_x_N,horizontal_m,tilt_deg,"
            "x_m,y_m,z_m,qw,qx,qy,qz,wx_rad_s,wy_rad_s,wz_rad_s");
  for (const pad::FreeDropSample& s : drop_->free->trace) {
    ASSERT_TRUE(std::getline(in, row));
    std::vector<double> v;
    std::stringstream cells(row);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 17u);
    const Eigen::Quaterniond q(v[10], v[11], v[12], v[13]);
    EXPECT_NEAR(q.norm(), 1.0, 1e-9);
    // The attitude gives the tilt column (10 significant digits written).
    EXPECT_NEAR(units::RadToDeg(std::acos(std::clamp(q.toRotationMatrix()(2, 2), -1.0, 1.0))), v[6], 1e-6);
    EXPECT_NEAR(v[9], s.p_WB.z(), 1e-9 * (1.0 + std::abs(s.p_WB.z())));
    EXPECT_NEAR(v[16], s.w_W.z(), 1e-9 * (1.0 + std::abs(s.w_W.z())));
  }
}

}  // namespace
}  // namespace touchdown::drop

// The VTK XML writer (drop_tests/io/vtk_writer.h, vtk_series.h, vtk_pieces.h): what it writes reads
// back, with a small XML reader, as the numbers it was given.
#include <Eigen/Geometry>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>

#include "drop_tests/io/vtk_pieces.h"
#include "drop_tests/io/vtk_series.h"
#include "drop_tests/io/vtk_writer.h"
#include "tests/drop_tests/io/vtk_xml_reader.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::io {
namespace {
using testing_vtk::DataArray;
using testing_vtk::XmlElement;
using testing_vtk::XmlReader;

// A unit square in the pad frame's z = 0 plane as two triangles that share two corners.
rft::SurfaceElements VtkSquareElements() {
  rft::SurfaceElements e;
  e.Resize(2);
  e.p0_B.col(0) << 0, 0, 0;
  e.p1_B.col(0) << 1, 0, 0;
  e.p2_B.col(0) << 1, 1, 0;
  e.p0_B.col(1) << 0, 0, 0;
  e.p1_B.col(1) << 1, 1, 0;
  e.p2_B.col(1) << 0, 1, 0;
  e.n_B.setZero();
  e.n_B.row(2).setConstant(-1.0);
  e.area_m2.setConstant(0.5);
  return e;
}

rft::ElementStresses VtkSquareStresses() {
  rft::ElementStresses s;
  s.Resize(2);
  s.force_W.setZero();
  s.normal_Pa << 1234.5678901234567, 1.0 / 3.0;
  s.shear_Pa << 2.5e-7, 98765.4321;
  s.depth_m << 0.0123456789012345, -0.002;
  s.leading << 1, 0;
  return s;
}

void ExpectVtkRelative(double expected, double actual) {
  EXPECT_NEAR(actual, expected, 1e-12 * std::abs(expected)) << expected;
}

TEST(VtkWriter, PadPieceReadsBackAsWritten) {
  const PadSurfaceMesh mesh = MakePadSurfaceMesh(VtkSquareElements());
  ASSERT_EQ(mesh.points_B.cols(), 4);  // the shared corners merged
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d p(0.1, -0.2, 0.05);
  const rft::ElementStresses stresses = VtkSquareStresses();
  const VtkPolyData piece = PadSurfacePiece(mesh, R, p, stresses);
  std::ostringstream out;
  WriteVtp({piece}, out);

  const XmlElement root = XmlReader(out.str()).Root();
  const auto pieces = testing_vtk::VtpPieces(root);
  ASSERT_EQ(pieces.size(), 1u);
  const XmlElement& xml = pieces[0];
  EXPECT_EQ(xml.Attribute("NumberOfPoints"), "4");
  EXPECT_EQ(xml.Attribute("NumberOfPolys"), "2");
  EXPECT_EQ(xml.Attribute("NumberOfLines"), "0");
  const std::vector<double> points = DataArray(xml.One("Points"), "Points").Numbers();
  ASSERT_EQ(points.size(), 12u);
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d expected = p + R * mesh.points_B.col(i);
    for (int k = 0; k < 3; ++k) ExpectVtkRelative(expected[k], points[3 * i + k]);
  }
  EXPECT_EQ(DataArray(xml.One("Polys"), "connectivity").Numbers(), (std::vector<double>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(DataArray(xml.One("Polys"), "offsets").Numbers(), (std::vector<double>{3, 6}));

  const XmlElement cells = xml.One("CellData");
  std::vector<std::string> names;
  for (const XmlElement& a : cells.All("DataArray")) names.push_back(a.Attribute("Name"));
  EXPECT_EQ(names, (std::vector<std::string>{"normal_stress_Pa", "shear_stress_Pa", "depth_m", "leading"}));
  const std::vector<double> normal = DataArray(cells, "normal_stress_Pa").Numbers();
  const std::vector<double> shear = DataArray(cells, "shear_stress_Pa").Numbers();
  const std::vector<double> depth = DataArray(cells, "depth_m").Numbers();
  const std::vector<double> leading = DataArray(cells, "leading").Numbers();
  ASSERT_EQ(normal.size(), 2u);
  ASSERT_EQ(leading.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    ExpectVtkRelative(stresses.normal_Pa[i], normal[i]);
    ExpectVtkRelative(stresses.shear_Pa[i], shear[i]);
    ExpectVtkRelative(stresses.depth_m[i], depth[i]);
    EXPECT_EQ(leading[i], stresses.leading[i]);
  }
  // The shortest exact decimal: not only close, equal.
  EXPECT_EQ(normal[1], 1.0 / 3.0);
}

TEST(VtkWriter, LinesComeBeforePolygonsAndSizesAreChecked) {
  VtkPolyData piece;
  piece.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  piece.lines = {{0, 1}};
  piece.polygons = {{0, 1, 2}};
  piece.AddCellField("id", {7.0, 8.0});
  std::ostringstream out;
  WriteVtp({piece}, out);
  const XmlElement xml = testing_vtk::VtpPieces(XmlReader(out.str()).Root())[0];
  EXPECT_EQ(xml.Attribute("NumberOfLines"), "1");
  EXPECT_EQ(DataArray(xml.One("Lines"), "connectivity").Numbers(), (std::vector<double>{0, 1}));
  EXPECT_EQ(DataArray(xml.One("CellData"), "id").Numbers(), (std::vector<double>{7.0, 8.0}));

  piece.AddCellField("short", {1.0});
  EXPECT_THROW(WriteVtp({piece}, out), std::logic_error);
  piece.cell_fields.pop_back();
  piece.polygons.push_back({0, 1, 3});
  piece.cell_fields.clear();
  EXPECT_THROW(WriteVtp({piece}, out), std::logic_error);
}

TEST(VtkWriter, SoilSquareFollowsTheSlopeAndNamesItsSoil) {
  const rft::PlaneGround slope(0.1, 0.2, -0.05);
  const VtkPolyData soil = SoilSurfacePiece(slope, Eigen::Vector2d(1.0, 2.0), 0.5, 2,
                                            [](double x, double) { return x > 1.0 ? 1 : 0; });
  ASSERT_EQ(soil.points.size(), 9u);
  ASSERT_EQ(soil.polygons.size(), 4u);
  for (const Eigen::Vector3d& q : soil.points) EXPECT_DOUBLE_EQ(q.z(), slope.Height(q.x(), q.y()));
  EXPECT_DOUBLE_EQ(soil.points.front().x(), 0.5);
  EXPECT_DOUBLE_EQ(soil.points.back().y(), 2.5);
  ASSERT_EQ(soil.cell_fields.size(), 1u);
  EXPECT_EQ(soil.cell_fields[0].values, (std::vector<double>{0, 1, 0, 1}));
  // Quads face up: counter-clockwise seen from above.
  const auto& q = soil.polygons[0];
  const Eigen::Vector3d n = (soil.points[q[1]] - soil.points[q[0]]).cross(soil.points[q[2]] - soil.points[q[0]]);
  EXPECT_GT(n.z(), 0.0);
}

class VtkSeriesTest : public testing_scratch::ScratchDirTest {};

TEST_F(VtkSeriesTest, CollectionListsEveryFrameWithItsTimeAndTheStaticPartAtEach) {
  VtkPolyData tri;
  tri.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  tri.polygons = {{0, 1, 2}};
  VtkSeries series(dir_.string(), "run");
  const std::vector<double> times{0.0, 0.001, 0.001, 0.0025};
  for (double t : times) {
    tri.points[0].z() = t;  // the replacing frame at 0.001 is the one kept
    series.AddFrame(t, "pad", {tri});
  }
  series.AddStaticPart("soil", {tri});
  const std::string pvd = series.Finish();
  EXPECT_EQ(pvd, (dir_ / "run.pvd").string());
  EXPECT_THROW(series.AddFrame(0.002, "pad", {tri}), std::logic_error);

  const XmlElement root = testing_vtk::ReadXmlFile(pvd);
  ASSERT_EQ(root.Attribute("type"), "Collection");
  const auto sets = root.One("Collection").All("DataSet");
  ASSERT_EQ(sets.size(), 6u);  // three times, two parts each
  const std::vector<double> distinct{0.0, 0.001, 0.0025};
  for (size_t i = 0; i < sets.size(); ++i) {
    const XmlElement& d = sets[i];
    EXPECT_EQ(std::stod(d.Attribute("timestep")), distinct[i / 2]);
    const bool pad = i % 2 == 0;
    EXPECT_EQ(d.Attribute("name"), pad ? "pad" : "soil");
    EXPECT_EQ(d.Attribute("part"), pad ? "0" : "1");
    const std::string file = d.Attribute("file");
    EXPECT_EQ(file, pad ? "pad_00000" + std::to_string(i / 2) + ".vtp" : "soil.vtp");
    const XmlElement vtp = testing_vtk::ReadXmlFile((dir_ / file).string());
    const auto pieces = testing_vtk::VtpPieces(vtp);
    ASSERT_EQ(pieces.size(), 1u);
    if (pad) {
      EXPECT_EQ(DataArray(pieces[0].One("Points"), "Points").Numbers()[2], distinct[i / 2]);
    }
  }
}

}  // namespace
}  // namespace touchdown::io

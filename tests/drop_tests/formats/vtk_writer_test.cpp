// The VTK XML writer (drop_tests/formats/vtk_writer.h, vtk_series.h, vtk_pieces.h): what it writes reads
// back, with a small XML reader, as the numbers it was given.
#include <Eigen/Geometry>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>

#include "drop_tests/formats/vtk_pieces.h"
#include "drop_tests/formats/vtk_series.h"
#include "drop_tests/formats/vtk_writer.h"
#include "tests/drop_tests/formats/vtk_xml_reader.h"
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
  s.force_W.col(0) << 12.5, -3.25, 617.28394506172835;
  s.force_W.col(1) << 0.0, 0.0, 1.0 / 6.0;
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
  EXPECT_EQ(names, (std::vector<std::string>{"normal_stress_Pa", "shear_stress_Pa", "depth_m", "leading",
                                              "traction_Pa", "element_force_N"}));
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
  // The vectors, three components a cell: the element's force, and that force per its area.
  EXPECT_EQ(DataArray(cells, "element_force_N").Attribute("NumberOfComponents"), "3");
  const std::vector<double> force = DataArray(cells, "element_force_N").Numbers();
  const std::vector<double> traction = DataArray(cells, "traction_Pa").Numbers();
  ASSERT_EQ(force.size(), 6u);
  ASSERT_EQ(traction.size(), 6u);
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(force[3 * i + c], stresses.force_W(c, i));
      EXPECT_EQ(traction[3 * i + c], stresses.force_W(c, i) / 0.5);
    }
}

TEST(VtkWriter, NegativeZeroIsWrittenAsZero) {
  // -0 / A (the normal stress of an element without force) and a coordinate of -0: written "0".
  VtkPolyData piece;
  piece.points = {Eigen::Vector3d(-0.0, 0.0, -0.0), Eigen::Vector3d(1, -0.0, 0), Eigen::Vector3d(0, 1, -1e-300 * 1e-300)};
  piece.polygons = {{0, 1, 2}};
  piece.AddCellField("stress", {-0.0 / 0.5});
  piece.AddCellField("vector", {-0.0, -2.5, 0.0}, 3);
  piece.AddPointField("depth", {-0.0, 0.0, -0.0});
  std::ostringstream out;
  WriteVtp({piece}, out);
  WritePvd({{-0.0, 0, "pad", "pad_000000.vtp"}}, out);
  const std::string text = out.str();
  for (size_t at = text.find("-0"); at != std::string::npos; at = text.find("-0", at + 1)) {
    const char next = at + 2 < text.size() ? text[at + 2] : ' ';
    EXPECT_TRUE(next == '.' || std::isdigit(static_cast<unsigned char>(next)) || next == 'e')
        << "a negative zero at " << at << ": " << text.substr(at > 20 ? at - 20 : 0, 40);
  }
  EXPECT_NE(text.find("-2.5"), std::string::npos);  // a negative number keeps its sign
  EXPECT_NE(text.find("timestep=\"0\""), std::string::npos);
  const XmlElement xml = testing_vtk::VtpPieces(XmlReader(text.substr(0, text.find("</VTKFile>") + 10)).Root())[0];
  EXPECT_EQ(DataArray(xml.One("Points"), "Points").Numbers(), (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
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

// A square pad (two triangles, 1 m a side, its bottom at the pad frame's z = 0) pressed into level
// ground: the grid points under it go down to its bottom, the others stay, and a second pose adds its
// imprint without filling the first.
TEST(VtkWriter, CraterKeepsTheDeepestImprintOfEveryPose) {
  const PadSurfaceMesh mesh = MakePadSurfaceMesh(VtkSquareElements());
  const rft::PlaneGround ground;
  CraterSurface crater(ground, Eigen::Vector2d(-0.45, -0.45), Eigen::Vector2d(1.95, 1.45), 100);
  const auto at = [](const VtkPolyData& p, double x, double y) {
    for (size_t k = 0; k < p.points.size(); ++k)
      if (std::abs(p.points[k].x() - x) < 1e-12 && std::abs(p.points[k].y() - y) < 1e-12) return k;
    ADD_FAILURE() << "no grid point at " << x << ", " << y;
    return size_t{0};
  };
  const VtkPolyData flat = crater.Piece();
  EXPECT_EQ(flat.points.size(), 26u * 21u);  // -0.5 .. 2.0 and -0.5 .. 1.5 by 0.1 m: the grid snaps out
  EXPECT_EQ(flat.polygons.size(), 25u * 20u);
  EXPECT_EQ(flat.points.front(), Eigen::Vector3d(-0.5, -0.5, 0.0));
  EXPECT_EQ(flat.points[at(flat, 0.3, 0.7)].x(), 0.3);  // integer / 1000: the double nearest 0.3

  crater.Press(mesh, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.1));
  crater.Press(mesh, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 0.2));  // above: no mark
  VtkPolyData p = crater.Piece();
  const std::vector<double>& depth = p.point_fields.at(0).values;
  EXPECT_EQ(p.point_fields.at(0).name, "crater_depth_m");
  EXPECT_EQ(p.points[at(p, 0.0, 0.0)].z(), -0.1);  // the footprint's corners and edges are in it
  EXPECT_EQ(p.points[at(p, 1.0, 1.0)].z(), -0.1);
  EXPECT_EQ(p.points[at(p, 0.5, 0.3)].z(), -0.1);
  EXPECT_EQ(depth[at(p, 0.5, 0.3)], 0.1);
  EXPECT_EQ(p.points[at(p, 1.1, 0.5)].z(), 0.0);
  EXPECT_EQ(p.points[at(p, -0.1, 0.5)].z(), 0.0);
  EXPECT_EQ(depth[at(p, -0.1, 0.5)], 0.0);

  // Slid by 0.5 m and tilted: a second imprint overlapping the first, which stays as deep.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector3d p_WB(0.5, 0.0, -0.05);
  crater.Press(mesh, R, p_WB);
  p = crater.Piece();
  EXPECT_EQ(p.points[at(p, 0.5, 0.5)].z(), -0.1);
  // (1.2, 0.5) lies under the tilted square: the plane through it, z = p_z - tan(0.1) (x - p_x).
  EXPECT_NEAR(p.points[at(p, 1.2, 0.5)].z(), -0.05 - std::tan(0.1) * 0.7, 1e-12);
  EXPECT_EQ(p.points[at(p, 1.9, 0.5)].z(), 0.0);

  // The grid steps: about 14 a pad radius, whole millimetres.
  EXPECT_EQ(CraterSurface::StepFor(0.0275), 2);
  EXPECT_EQ(CraterSurface::StepFor(0.05), 4);
  EXPECT_EQ(CraterSurface::StepFor(0.001), 1);
}

class VtkSeriesTest : public testing_scratch::ScratchDirTest {};

TEST_F(VtkSeriesTest, AFrameThatDidNotChangeListsThePreviousFile) {
  VtkPolyData tri;
  tri.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  tri.polygons = {{0, 1, 2}};
  VtkSeries series(dir_.string(), "run");
  series.AddFrame(0.0, "crater", {tri});
  series.AddFrame(0.1, "crater", {tri});  // the same: listed, not written
  tri.points[0].z() = -0.01;
  series.AddFrame(0.2, "crater", {tri});
  series.AddFrame(0.2, "crater", {tri});  // a replacement at the same time, the same again
  series.AddFrame(0.3, "crater", {tri});
  const auto sets = testing_vtk::ReadXmlFile(series.Finish()).One("Collection").All("DataSet");
  std::vector<std::string> files;
  for (const XmlElement& d : sets) files.push_back(d.Attribute("file"));
  EXPECT_EQ(files, (std::vector<std::string>{"crater_000000.vtp", "crater_000000.vtp", "crater_000002.vtp",
                                             "crater_000002.vtp"}));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "crater_000001.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "crater_000003.vtp"));
  EXPECT_EQ(DataArray(testing_vtk::VtpPieces(testing_vtk::ReadXmlFile((dir_ / "crater_000002.vtp").string()))[0]
                          .One("Points"), "Points").Numbers()[2], -0.01);
}

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

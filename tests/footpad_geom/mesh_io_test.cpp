// Pad meshes from files: the four formats, units, the writer, and one clear error per defect.
#include "footpad_geom/mesh_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "footpad_geom/mass_properties.h"
#include "footpad_geom/revolve.h"
#include "rft/input_error.h"
#include "tests/footpad_geom/mesh_test_shapes.h"

namespace touchdown::geom {
namespace {

using testing::BoxSoup;
using testing::TriangulatedBox;

std::string Fmt(double v) {
  char s[64];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

std::string AsciiStl(const TriangleMesh& m) {
  std::string t = "solid cube\n";
  for (const auto& tri : m.triangles) {
    t += " facet normal 0 0 0\n  outer loop\n";
    for (int i : tri) {
      const auto& v = m.vertices[i];
      t += "   vertex " + Fmt(v.x()) + " " + Fmt(v.y()) + " " + Fmt(v.z()) + "\n";
    }
    t += "  endloop\n endfacet\n";
  }
  return t + "endsolid cube\n";
}

std::string BinaryStl(const TriangleMesh& m) {
  std::string b(80, 'x');  // header; must not start with "solid"
  auto put = [&](const void* p, std::size_t n) { b.append(static_cast<const char*>(p), n); };
  const std::uint32_t n = static_cast<std::uint32_t>(m.triangles.size());
  put(&n, 4);
  for (const auto& tri : m.triangles) {
    const float normal[3] = {0, 0, 0};
    put(normal, 12);
    for (int i : tri) {
      const float v[3] = {float(m.vertices[i].x()), float(m.vertices[i].y()), float(m.vertices[i].z())};
      put(v, 12);
    }
    const std::uint16_t attribute = 0;
    put(&attribute, 2);
  }
  return b;
}

std::string Obj(const PolygonSoup& s) {
  std::string t = "# cube\n";
  for (const auto& v : s.vertices) t += "v " + Fmt(v.x()) + " " + Fmt(v.y()) + " " + Fmt(v.z()) + "\n";
  for (const auto& f : s.faces) {
    t += 'f';
    for (int i : f) {
      t += ' ';
      t += std::to_string(i + 1);
    }
    t += '\n';
  }
  return t;
}

std::string AsciiPly(const TriangleMesh& m) {
  std::string t = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(m.vertices.size()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                  std::to_string(m.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& v : m.vertices) t += Fmt(v.x()) + " " + Fmt(v.y()) + " " + Fmt(v.z()) + "\n";
  for (const auto& tri : m.triangles)
    t += "3 " + std::to_string(tri[0]) + " " + std::to_string(tri[1]) + " " + std::to_string(tri[2]) + "\n";
  return t;
}

// The message of the InputError that preparing `soup` raises, or "(no error)".
std::string DefectOf(const PolygonSoup& soup) {
  try {
    PrepareTriangleMesh(soup, "pad.stl");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

class MeshFiles : public testing::TempDirTest {
 protected:
  std::string LoadError(const std::string& path, const MeshLoadOptions& options = {}) {
    try {
      LoadTriangleMesh(path, options);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST_F(MeshFiles, AllFourFormatsReadTheSameCube) {
  const PolygonSoup quads = BoxSoup(1, 1, 1);
  const TriangleMesh triangles = testing::ToTriangles(quads);
  struct Case {
    std::string file, bytes;
    int triangulated;
  };
  const Case cases[] = {
      {"ascii.stl", AsciiStl(triangles), 0}, {"binary.stl", BinaryStl(triangles), 0},
      {"quads.off", testing::OffText(quads), 6}, {"quads.obj", Obj(quads), 6},
      {"ascii.ply", AsciiPly(triangles), 0},   {"UPPER.STL", BinaryStl(triangles), 0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const PreparedMesh m = LoadTriangleMesh(Write(c.file, c.bytes), {LengthUnit::kMetre, 0.0});
    EXPECT_EQ(m.mesh.vertices.size(), 8u);  // STL's per-facet copies merged
    EXPECT_EQ(m.mesh.triangles.size(), 12u);
    EXPECT_EQ(m.triangulated_faces, c.triangulated);
    EXPECT_FALSE(m.reoriented);
    const VolumeProperties vp = ComputeVolumeProperties(m.mesh);
    EXPECT_NEAR(vp.volume_m3, 1.0, 1e-12);
    EXPECT_TRUE(vp.centroid_m.isApprox(Eigen::Vector3d(0.5, 0.5, 0.5), 1e-12));
  }
}

TEST_F(MeshFiles, MillimetresBecomeMetres) {
  const std::string path = Write("box.off", testing::OffText(BoxSoup(100, 50, 16)));
  const PreparedMesh mm = LoadTriangleMesh(path, {LengthUnit::kMillimetre, 0.0});
  EXPECT_NEAR(ComputeVolumeProperties(mm.mesh).volume_m3, 0.1 * 0.05 * 0.016, 1e-15);
  // The same numbers in metres would be a 100 m pad, beyond the 10 m a pad may measure.
  const std::string small = Write("small.off", testing::OffText(BoxSoup(1, 0.5, 0.16)));
  const PreparedMesh m = LoadTriangleMesh(small, {LengthUnit::kMetre, 0.0});
  EXPECT_NEAR(ComputeVolumeProperties(m.mesh).volume_m3, 1.0 * 0.5 * 0.16, 1e-12);
  EXPECT_EQ(LoadError(path, {LengthUnit::kMetre, 0.0}),
            path + ": mesh is 100 m across, at most 10 m for a pad (check the mesh's unit)");
  EXPECT_EQ(ParseLengthUnit("mm", "f", "unit"), LengthUnit::kMillimetre);
  EXPECT_EQ(ParseLengthUnit("m", "f", "unit"), LengthUnit::kMetre);
  try {
    ParseLengthUnit("inch", "pad.yaml", "mesh.unit");
    ADD_FAILURE() << "no error for an unknown unit";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "pad.yaml: mesh.unit: unknown length unit 'inch' (mm, m)");
  }
}

TEST_F(MeshFiles, WriterRoundTripsEveryFormat) {
  const TriangleMesh pad = RevolveProfileToMesh(MakeChamferProfile(0.05, 0.016, 0.004), 32);
  const double volume = ComputeVolumeProperties(pad).volume_m3;
  for (const char* name : {"pad.stl", "pad.off", "pad.obj", "pad.ply"}) {
    for (bool ascii : {false, true}) {
      SCOPED_TRACE(std::string(name) + (ascii ? " ascii" : " binary"));
      const std::string path = (dir_ / name).string();
      WriteTriangleMesh(pad, path, 1000.0, ascii);  // in mm
      const PreparedMesh back = LoadTriangleMesh(path, {LengthUnit::kMillimetre, 0.0});
      EXPECT_EQ(back.mesh.triangles.size(), pad.triangles.size());
      EXPECT_FALSE(back.reoriented);
      // Binary STL stores float32 coordinates.
      EXPECT_NEAR(ComputeVolumeProperties(back.mesh).volume_m3, volume, 1e-6 * volume);
    }
  }
}

TEST_F(MeshFiles, FileProblemsNameTheFile) {
  EXPECT_EQ(LoadError((dir_ / "none.stl").string()), (dir_ / "none.stl").string() + ": mesh file not found");
  std::filesystem::create_directories(dir_ / "folder.stl");
  EXPECT_EQ(LoadError((dir_ / "folder.stl").string()), (dir_ / "folder.stl").string() + ": is a directory, not a file");
  const std::string xyz = Write("pad.xyz", "1 2 3\n");
  EXPECT_EQ(LoadError(xyz), xyz + ": unknown mesh format '.xyz' (.stl, .off, .obj, .ply)");
  const std::string garbage = Write("garbage.off", "this is not a mesh\n");
  EXPECT_NE(LoadError(garbage).find("garbage.off: could not be read as off"), std::string::npos) << LoadError(garbage);
  const std::string short_stl = Write("short.stl", std::string(90, 'x'));
  EXPECT_NE(LoadError(short_stl).find("short.stl: could not be read as stl"), std::string::npos);
  PolygonSoup open = BoxSoup(1, 1, 1);
  open.faces.pop_back();
  const std::string open_path = Write("open.off", testing::OffText(open));
  EXPECT_EQ(LoadError(open_path), open_path + ": 4 border edges, mesh is not closed");
}

TEST(MeshDefects, OpenMeshIsRefused) {
  PolygonSoup soup = TriangulatedBox();
  soup.faces.pop_back();
  EXPECT_EQ(DefectOf(soup), "pad.stl: 3 border edges, mesh is not closed");
}

TEST(MeshDefects, InvertedMeshIsReorientedOutward) {
  PolygonSoup soup = TriangulatedBox();
  for (auto& f : soup.faces) std::swap(f[1], f[2]);
  const PreparedMesh m = PrepareTriangleMesh(soup, "pad.stl");
  EXPECT_TRUE(m.reoriented);
  EXPECT_NEAR(ComputeVolumeProperties(m.mesh).volume_m3, 1.0, 1e-12);
  // A few faces flipped (inconsistent orientation) is repaired the same way.
  PolygonSoup mixed = TriangulatedBox();
  for (int i : {0, 3, 7}) std::swap(mixed.faces[i][1], mixed.faces[i][2]);
  const PreparedMesh fixed = PrepareTriangleMesh(mixed, "pad.stl");
  EXPECT_TRUE(fixed.reoriented);
  EXPECT_NEAR(ComputeVolumeProperties(fixed.mesh).volume_m3, 1.0, 1e-12);
  // A correct mesh is left alone.
  EXPECT_FALSE(PrepareTriangleMesh(TriangulatedBox(), "pad.stl").reoriented);
}

TEST(MeshDefects, MoebiusBandIsNotOrientable) {
  PolygonSoup band;
  const int n = 16;
  const double pi = std::numbers::pi;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * pi * i / n;
    const Eigen::Vector3d centre(std::cos(t), std::sin(t), 0.0);
    const Eigen::Vector3d d(std::cos(t / 2) * std::cos(t), std::cos(t / 2) * std::sin(t), std::sin(t / 2));
    band.vertices.push_back(centre + 0.3 * d);  // a_i = 2 i
    band.vertices.push_back(centre - 0.3 * d);  // b_i = 2 i + 1
  }
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    // After a full turn the band has flipped over: a_n = b_0, b_n = a_0.
    const int a1 = i + 1 < n ? 2 * (i + 1) : 1, b1 = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    band.faces.push_back({a, b, b1});
    band.faces.push_back({a, b1, a1});
  }
  EXPECT_NE(DefectOf(band).find("pad.stl: mesh is not orientable"), std::string::npos) << DefectOf(band);
}

TEST(MeshDefects, SelfIntersectionIsRefused) {
  const PolygonSoup two = testing::Union(TriangulatedBox(), TriangulatedBox(1, 1, 1, {0.5, 0.5, 0.5}));
  const std::string message = DefectOf(two);
  EXPECT_NE(message.find("pad.stl: mesh intersects itself ("), std::string::npos) << message;
  // Two separate boxes are two solids, not one pad.
  EXPECT_EQ(DefectOf(testing::Union(TriangulatedBox(), TriangulatedBox(1, 1, 1, {2, 0, 0}))),
            "pad.stl: 2 separate closed shells (a pad must be one connected solid: join the pieces, or make each its "
            "own pad)");
}

// A box inside a box would add the inner shell's surface to the contact (15 % more
// submerged area); a pad must be one solid. Boxes side by side are refused too (above).
TEST(MeshDefects, NestedShellsAreRefused) {
  const PolygonSoup nested = testing::Union(TriangulatedBox(1, 1, 1), TriangulatedBox(0.5, 0.5, 0.5, {0.25, 0.25, 0.25}));
  EXPECT_EQ(DefectOf(nested), "pad.stl: 1 closed shell lies inside another (a pad must be one solid, not nested shells)");
  // Three deep: the middle shell is the cavity of the outer one.
  const PolygonSoup three = testing::Union(nested, TriangulatedBox(0.2, 0.2, 0.2, {0.4, 0.4, 0.4}));
  EXPECT_NE(DefectOf(three).find("inside another"), std::string::npos) << DefectOf(three);
}

TEST(MeshDefects, AMeshKilometresAcrossIsAUnitMistake) {
  EXPECT_EQ(DefectOf(TriangulatedBox(1e27, 1e27, 1e27)),
            "pad.stl: mesh is 1e+27 m across, at most 10 m for a pad (check the mesh's unit)");
  EXPECT_EQ(DefectOf(TriangulatedBox(10, 1, 1)), "(no error)");
}

TEST(MeshDefects, ZeroAreaFaceIsRefused) {
  // A cube whose edge v0-v1 carries its midpoint v8; the front face is split into the
  // collinear triangle (v0, v8, v1) and two proper ones. Closed, oriented, but degenerate.
  PolygonSoup soup = BoxSoup(1, 1, 1);
  soup.vertices.push_back({0.5, 0.0, 0.0});
  soup.faces = {{8, 0, 3}, {8, 3, 2}, {8, 2, 1}, {0, 8, 1}, {0, 1, 5}, {0, 5, 4},
                {4, 5, 6, 7}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  EXPECT_EQ(DefectOf(soup), "pad.stl: 1 degenerate face (zero area)");
}

TEST(MeshDefects, RepeatedVertexFaceIsRefused) {
  PolygonSoup soup = TriangulatedBox();
  soup.vertices.push_back(soup.vertices[1]);  // an STL-style copy of v1, merged on reading
  soup.faces.push_back({0, 1, 8});
  EXPECT_EQ(DefectOf(soup), "pad.stl: 1 degenerate face (fewer than three distinct vertices)");
}

TEST(MeshDefects, NonManifoldEdgesAndVerticesAreRefused) {
  const PolygonSoup edge = testing::Union(TriangulatedBox(), TriangulatedBox(1, 1, 1, {1, 1, 0}));
  EXPECT_EQ(DefectOf(edge), "pad.stl: 1 edge shared by more than two faces, mesh is not manifold");
  const PolygonSoup corner = testing::Union(TriangulatedBox(), TriangulatedBox(1, 1, 1, {1, 1, 1}));
  EXPECT_NE(DefectOf(corner).find("pad.stl: 1 non-manifold vertex"), std::string::npos) << DefectOf(corner);
}

TEST(MeshDefects, PolygonFacesAreTriangulated) {
  const PreparedMesh m = PrepareTriangleMesh(BoxSoup(2, 3, 4), "box.off");
  EXPECT_EQ(m.triangulated_faces, 6);
  EXPECT_EQ(m.mesh.triangles.size(), 12u);
  EXPECT_NEAR(ComputeVolumeProperties(m.mesh).volume_m3, 24.0, 1e-12);
}

TEST(MeshDefects, EmptyAndDanglingIndicesAreRefused) {
  EXPECT_EQ(DefectOf(PolygonSoup{}), "pad.stl: mesh has no faces");
  PolygonSoup soup = TriangulatedBox();
  soup.faces.push_back({0, 1, 42});
  EXPECT_EQ(DefectOf(soup), "pad.stl: a face refers to vertex 42, which does not exist");
}

// ---- Regressions found by fuzzing (tests/fuzz/mesh_*): a count written in a file must never
// size an allocation, and every malformed file is one clear InputError.

std::string BigEndian32(std::int32_t v) {
  std::string b(4, '\0');
  for (int i = 0; i < 4; ++i) b[i] = static_cast<char>((static_cast<std::uint32_t>(v) >> (24 - 8 * i)) & 0xff);
  return b;
}

TEST_F(MeshFiles, DeclaredCountsNeverSizeAnAllocation) {
  const struct {
    std::string file, bytes, expected;
  } cases[] = {
      // CGAL's OFF reader resized to 1e9 points and faces before reading one.
      {"huge.off", "OFF\n1000000000 1000000000 0\n0 0 0\n",
       "could not be read as off (file ends after 1 of 1000000000 vertices)"},
      // ... and each face to its declared corner count.
      {"huge_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000 0 1 2\n",
       "could not be read as off (line 6: a face must start with its number of vertices"},
      {"huge_binary.off", "OFF BINARY\n" + BigEndian32(1000000000) + BigEndian32(1) + BigEndian32(0),
       "could not be read as off (declares 1000000000 vertices but the file is too short for them)"},
      // CGAL's PLY reader resized each list to its declared length (here 2^31 - 1 indices).
      {"huge_list.ply",
       std::string("ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n") +
           std::string("\xff\xff\xff\x7f", 4),
       "could not be read as ply (element 'face' item 0: bad list length)"},
      {"huge_element.ply",
       "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\n"
       "end_header\n0 0 0\n",
       "could not be read as ply (element 'vertex' declares 4000000000 items but the file is too short for them)"},
      {"float_count.ply",
       "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n1e30 0 1 2\n",
       "could not be read as ply (line 4: a list length must have an integer type)"},
      {"no_header.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", "could not be read as ply (no end_header)"},
      {"skel.off", "SKEL\n1 0\n0 0 0\n", "could not be read as off (unsupported OFF variant 'SKEL'"},
      {"homogeneous.off", "4OFF\n1 0 0\n0 0 0 1\n", "could not be read as off (unsupported OFF variant '4OFF'"},
      {"text_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 one 2\n",
       "could not be read as off (line 6: not a vertex index: 'one')"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string path = Write(c.file, c.bytes);
    EXPECT_EQ(LoadError(path).rfind(path + ": " + c.expected, 0), 0u) << LoadError(path);
  }
}

TEST_F(MeshFiles, BinaryStlWithANonFiniteCoordinateIsRefused) {
  // CGAL's STL reader keys points in a std::map, which cannot order NaN: the bad point was
  // silently merged into another one.
  std::string b(80, ' ');
  const std::uint32_t n = 1;
  b.append(reinterpret_cast<const char*>(&n), 4);
  const float values[12] = {0, 0, 0, std::nanf(""), 0, 0, 1, 0, 0, 0, 1, 0};
  b.append(reinterpret_cast<const char*>(values), sizeof values);
  b.append(2, '\0');
  const std::string path = Write("nan.stl", b);
  EXPECT_EQ(LoadError(path), path + ": could not be read as stl (facet 0 has a non-finite vertex coordinate)");
}

TEST_F(MeshFiles, OffAndPlyVariantsStillRead) {
  const PolygonSoup quads = BoxSoup(1, 1, 1);
  std::string coff = "COFF\n# with colours\n8 6 0\n";
  for (const auto& v : quads.vertices) coff += Fmt(v.x()) + " " + Fmt(v.y()) + " " + Fmt(v.z()) + " 255 0 0 255\n";
  for (const auto& f : quads.faces)
    coff += "4 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " " +
            std::to_string(f[3]) + " 0.5 0.5 0.5\n";
  std::string one_line = "OFF 8 6 0\n";  // the counts on the header line
  for (const auto& v : quads.vertices) one_line += Fmt(v.x()) + " " + Fmt(v.y()) + " " + Fmt(v.z()) + "\n";
  for (const auto& f : quads.faces)
    one_line += "4 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " " +
                std::to_string(f[3]) + "\n";
  // Big-endian PLY: doubles, an extra vertex property, uint indices and an extra element.
  std::string ply =
      "ply\nformat binary_big_endian 1.0\ncomment test\nelement vertex 8\nproperty double x\nproperty double y\n"
      "property double z\nproperty uchar red\nelement face 6\nproperty list int uint vertex_index\n"
      "element edge 0\nproperty int vertex1\nend_header\n";
  auto be = [&](const void* p, std::size_t size) {
    const char* c = static_cast<const char*>(p);
    for (std::size_t i = size; i-- > 0;) ply += c[i];
  };
  for (const auto& v : quads.vertices) {
    for (int k = 0; k < 3; ++k) be(&v[k], 8);
    ply += '\x07';
  }
  for (const auto& f : quads.faces) {
    const std::int32_t four = 4;
    be(&four, 4);
    for (int i : f) {
      const std::uint32_t u = static_cast<std::uint32_t>(i);
      be(&u, 4);
    }
  }
  for (const auto& [name, bytes] : {std::pair<std::string, std::string>{"colours.off", coff},
                                    {"one_line.off", one_line}, {"big_endian.ply", ply}}) {
    SCOPED_TRACE(name);
    const PreparedMesh m = LoadTriangleMesh(Write(name, bytes), {LengthUnit::kMetre, 0.0});
    EXPECT_EQ(m.mesh.triangles.size(), 12u);
    EXPECT_NEAR(ComputeVolumeProperties(m.mesh).volume_m3, 1.0, 1e-12);
  }
}

TEST_F(MeshFiles, RemeshingToAnAbsurdEdgeIsRefused) {
  // A hand-written 1e-6 mm edge would mean ~1e16 triangles: refused before remeshing.
  const std::string path = Write("box.off", testing::OffText(BoxSoup(100, 100, 16)));
  const std::string message = LoadError(path, {LengthUnit::kMillimetre, 1e-9});
  EXPECT_NE(message.find(path + ": remesh edge length 1e-06 mm would make about"), std::string::npos) << message;
  EXPECT_NE(message.find("(at most 500000): use a longer edge"), std::string::npos) << message;
  EXPECT_EQ(LoadError(path, {LengthUnit::kMillimetre, 0.01}), "(no error)");
}

}  // namespace
}  // namespace touchdown::geom

#pragma once
// Plain mesh containers shared by the mesh reader, the revolve and the pad-body builder. No
// CGAL here: CGAL stays inside footpad_geom/mesh_io.cpp and footpad_geom/mesh_remesh.cpp.
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace touchdown::geom {

// A closed triangle surface: counter-clockwise triangles seen from outside (outward normals)
// once it has passed PrepareTriangleMesh (mesh_io.h). Coordinates in metres unless stated.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Faces of any size, as read from a file, before validation.
struct PolygonSoup {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
};

// The same triangles as a soup (to validate a mesh made elsewhere: revolve, remeshing).
PolygonSoup ToPolygonSoup(const TriangleMesh& mesh);

// Length unit of the coordinates in a mesh file.
enum class LengthUnit { kMillimetre, kMetre };

// "mm" or "m"; anything else throws InputError naming `file` and `field`.
LengthUnit ParseLengthUnit(const std::string& text, const std::string& file, const std::string& field);
double MetresPerUnit(LengthUnit unit);

}  // namespace touchdown::geom

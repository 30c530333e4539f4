// CGAL translation unit 1 of 2 (the other is mesh_remesh.cpp): file IO, validation and
// orientation of pad meshes. Exact predicates, inexact constructions, Surface_mesh.
#include "footpad_geom/mesh_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>
#include <unordered_map>

#include "footpad_geom/mesh_readers.h"
#include "footpad_geom/mesh_remesh.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::geom {

namespace {

namespace fs = std::filesystem;
namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;

using limits::kMaxRemeshTriangles;  // rft/physical_limits.h

InputError Defect(const std::string& source, const std::string& what) {
  return MakeInputError(source, "", what);
}

std::string Count(std::size_t n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::uint64_t EdgeKey(std::size_t a, std::size_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}
std::uint64_t DirectedKey(std::size_t a, std::size_t b) {
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

// Counts what CGAL's soup orientation did: faces it reversed, and vertices at which it had to
// split otherwise separate sheets. (CGAL copies the visitor, hence the pointers.)
struct OrientationCounter : PMP::Default_orientation_visitor {
  std::size_t* reversed;
  std::size_t* non_manifold_vertices;
  std::vector<std::size_t>* original;  // of every point, duplicates included
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
  void non_manifold_vertex(std::size_t, std::size_t) { ++*non_manifold_vertices; }
  void duplicated_vertex(std::size_t v, std::size_t copy) {
    original->resize(std::max(original->size(), copy + 1));
    (*original)[copy] = (*original)[v];
  }
};

// Soup-level checks: degenerate faces, non-manifold and border edges, orientability.
// On return the polygons are consistently oriented (not yet necessarily outward); returns the
// number of faces reversed to get there.
std::size_t CheckAndOrientSoup(std::vector<Point>& points, std::vector<Polygon>& polygons, const std::string& source) {
  std::size_t repeated = 0;
  for (const Polygon& p : polygons) {
    Polygon sorted = p;
    std::sort(sorted.begin(), sorted.end());
    if (sorted.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) ++repeated;
  }
  if (repeated > 0)
    throw Defect(source, Count(repeated, "degenerate face", "degenerate faces") +
                             " (fewer than three distinct vertices)");

  std::unordered_map<std::uint64_t, int> edge_faces;
  for (const Polygon& p : polygons)
    for (std::size_t i = 0; i < p.size(); ++i) ++edge_faces[EdgeKey(p[i], p[(i + 1) % p.size()])];
  std::size_t non_manifold = 0, border = 0;
  for (const auto& [key, n] : edge_faces) {
    if (n > 2) ++non_manifold;
    if (n == 1) ++border;
  }
  if (non_manifold > 0)
    throw Defect(source, Count(non_manifold, "edge", "edges") + " shared by more than two faces, mesh is not manifold");

  std::size_t split_vertices = 0, reversed = 0;
  const std::size_t points_before = points.size();
  std::vector<std::size_t> original(points.size());
  for (std::size_t i = 0; i < original.size(); ++i) original[i] = i;
  OrientationCounter counter;
  counter.reversed = &reversed;
  counter.non_manifold_vertices = &split_vertices;
  counter.original = &original;
  PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(counter));
  // After CGAL's orientation walk, a directed edge (between the original points) used twice
  // joins two faces it could not orient consistently: the surface is not orientable. (CGAL
  // cuts the surface there and may then split the edge's end points, hence the originals.)
  std::unordered_map<std::uint64_t, int> directed;
  std::size_t conflicts = 0;
  for (const Polygon& p : polygons)
    for (std::size_t i = 0; i < p.size(); ++i)
      if (++directed[DirectedKey(original[p[i]], original[p[(i + 1) % p.size()]])] == 2) ++conflicts;
  if (conflicts > 0)
    throw Defect(source, "mesh is not orientable (" + Count(conflicts, "edge joins", "edges join") +
                             " faces that no choice of normals makes consistent)");
  if (split_vertices > 0 || points.size() != points_before)
    throw Defect(source, Count(std::max<std::size_t>(split_vertices, 1), "non-manifold vertex", "non-manifold vertices") +
                             " (separate sheets of the surface touch at a vertex)");
  if (border > 0) throw Defect(source, Count(border, "border edge", "border edges") + ", mesh is not closed");
  return reversed;
}

double SixTimesSignedVolume(const Mesh& mesh, Mesh::Face_index f) {
  auto h = mesh.halfedge(f);
  const Point& a = mesh.point(mesh.source(h));
  const Point& b = mesh.point(mesh.target(h));
  const Point& c = mesh.point(mesh.target(mesh.next(h)));
  return CGAL::scalar_product(a - CGAL::ORIGIN, CGAL::cross_product(b - CGAL::ORIGIN, c - CGAL::ORIGIN));
}

double SignedVolume(const Mesh& mesh) {
  double six_v = 0.0;
  for (Mesh::Face_index f : mesh.faces()) six_v += SixTimesSignedVolume(mesh, f);
  return six_v / 6.0;
}

// The mesh's closed shells: how many, and how many lie inside another. After
// orient_to_bound_a_volume a shell directly inside another bounds a cavity and is oriented
// inward (negative volume); every nesting has at least one such shell. A pad is one solid: an
// inner shell would add its surface to the contact sums as if the soil reached it, and a second
// solid beside the first is a second pad that the one body (one mass, one inertia, one joint)
// would carry rigidly, which no lander has.
struct Shells {
  std::size_t count = 0, nested = 0;
};
Shells CountShells(Mesh& mesh) {
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  Shells shells;
  shells.count = PMP::connected_components(mesh, component);
  if (shells.count > 1) {
    std::vector<double> six_v(shells.count, 0.0);
    for (Mesh::Face_index f : mesh.faces()) six_v[component[f]] += SixTimesSignedVolume(mesh, f);
    for (double v : six_v)
      if (v < 0.0) ++shells.nested;
  }
  mesh.remove_property_map(component);
  return shells;
}

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

PreparedMesh PrepareTriangleMesh(PolygonSoup soup, const std::string& source) {
  if (soup.faces.empty()) throw Defect(source, "mesh has no faces");
  std::vector<Point> points;
  points.reserve(soup.vertices.size());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Eigen::Vector3d& v : soup.vertices) {
    if (!v.allFinite()) throw Defect(source, "mesh has a vertex with a non-finite coordinate");
    points.emplace_back(v.x(), v.y(), v.z());
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  // A pad of kilometres is a unit mistake (or garbage); its contact sums would lose every digit.
  const double extent = soup.vertices.empty() ? 0.0 : (hi - lo).maxCoeff();
  if (extent > limits::kPadSize_m.high) {
    char text[160];
    std::snprintf(text, sizeof text, "mesh is %.3g m across, at most %g m for a pad (check the mesh's unit)", extent,
                  limits::kPadSize_m.high);
    throw Defect(source, text);
  }
  std::vector<Polygon> polygons;
  polygons.reserve(soup.faces.size());
  for (const std::vector<int>& f : soup.faces) {
    Polygon p;
    for (int i : f) {
      if (i < 0 || static_cast<std::size_t>(i) >= points.size())
        throw Defect(source, "a face refers to vertex " + std::to_string(i) + ", which does not exist");
      p.push_back(static_cast<std::size_t>(i));
    }
    polygons.push_back(std::move(p));
  }
  soup = {};

  PreparedMesh out;
  out.merged_points = static_cast<int>(PMP::merge_duplicate_points_in_polygon_soup(points, polygons));
  PMP::remove_isolated_points_in_polygon_soup(points, polygons);
  const std::size_t reversed = CheckAndOrientSoup(points, polygons, source);
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Defect(source, "mesh is not a manifold surface");

  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  for (Mesh::Face_index f : mesh.faces())
    if (mesh.degree(f) > 3) ++out.triangulated_faces;
  if (out.triangulated_faces > 0 && !PMP::triangulate_faces(mesh))
    throw Defect(source, "some of the " + Count(out.triangulated_faces, "polygon face", "polygon faces") +
                             " could not be triangulated");

  std::vector<Mesh::Face_index> degenerate;
  PMP::degenerate_faces(mesh, std::back_inserter(degenerate));
  if (!degenerate.empty())
    throw Defect(source, Count(degenerate.size(), "degenerate face", "degenerate faces") + " (zero area)");

  if (PMP::does_self_intersect(mesh)) {
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    PMP::self_intersections(mesh, std::back_inserter(pairs));
    throw Defect(source, "mesh intersects itself (" + Count(pairs.size(), "pair", "pairs") + " of faces intersect)");
  }

  const double volume_before = SignedVolume(mesh);
  const bool outward = PMP::is_outward_oriented(mesh);
  PMP::orient_to_bound_a_volume(mesh);
  const double volume_after = SignedVolume(mesh);
  out.reoriented = reversed > 0 || !outward || volume_after != volume_before;
  if (!(volume_after > 0.0)) throw Defect(source, "mesh encloses no volume");
  const Shells shells = CountShells(mesh);
  if (shells.nested > 0)
    throw Defect(source, Count(shells.nested, "closed shell lies", "closed shells lie") +
                             " inside another (a pad must be one solid, not nested shells)");
  if (shells.count > 1)
    throw Defect(source, Count(shells.count, "separate closed shell", "separate closed shells") +
                             " (a pad must be one connected solid: join the pieces, or make each its own pad)");

  // No element was removed, so vertex and face indices are contiguous.
  out.mesh.vertices.reserve(mesh.number_of_vertices());
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    out.mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  out.mesh.triangles.reserve(mesh.number_of_faces());
  for (Mesh::Face_index f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (Mesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f))) t[k++] = static_cast<int>(v.idx());
    out.mesh.triangles.push_back(t);
  }
  return out;
}

PreparedMesh LoadTriangleMesh(const std::string& path, const MeshLoadOptions& options) {
  RequireReadableFile(path, "mesh file");
  const std::string ext = Lower(fs::path(path).extension().string());
  if (ext != ".stl" && ext != ".off" && ext != ".obj" && ext != ".ply")
    throw Defect(path, "unknown mesh format '" + ext + "' (.stl, .off, .obj, .ply)");
  if (!(options.remesh_edge_m >= 0.0) || !std::isfinite(options.remesh_edge_m))
    throw Defect(path, "remesh edge length must be >= 0 and finite");

  // OFF and PLY go through touchdown's bounded readers (mesh_readers.h): CGAL's trust the
  // counts in the file. STL and OBJ are read by CGAL, which grows its arrays as it reads.
  const std::string format = ext.substr(1);
  PolygonSoup soup;
  if (format == "off") {
    soup = ReadOffSoup(path);
  } else if (format == "ply") {
    soup = ReadPlySoup(path);
  } else {
    if (format == "stl") CheckBinaryStlCoordinates(path);
    std::vector<Point> points;
    std::vector<Polygon> polygons;
    bool read = false;
    try {
      const auto np = CGAL::parameters::verbose(false);
      read = format == "stl" ? CGAL::IO::read_STL(path, points, polygons, np)
                             : CGAL::IO::read_OBJ(path, points, polygons, np);
    } catch (const std::exception&) {
      read = false;
    }
    if (!read) throw Defect(path, "could not be read as " + format + " (malformed file)");
    soup.vertices.reserve(points.size());
    for (const Point& p : points) soup.vertices.emplace_back(p.x(), p.y(), p.z());
    for (Polygon& p : polygons) {
      std::vector<int> f;
      for (std::size_t i : p) {
        if (i >= points.size()) throw Defect(path, "a face refers to vertex " + std::to_string(i) + ", which does not exist");
        f.push_back(static_cast<int>(i));
      }
      soup.faces.push_back(std::move(f));
    }
  }
  const double scale = MetresPerUnit(options.unit);
  for (Eigen::Vector3d& v : soup.vertices) v *= scale;
  PreparedMesh prepared = PrepareTriangleMesh(std::move(soup), path);
  if (options.remesh_edge_m > 0.0) {
    // Refuse a target edge that would make an absurd number of triangles (a hand-written
    // 1e-9 would otherwise exhaust memory): an even mesh of edge e has about
    // area / (sqrt(3)/4 e^2) triangles.
    double area = 0.0;
    for (const auto& t : prepared.mesh.triangles) {
      const Eigen::Vector3d& a = prepared.mesh.vertices[t[0]];
      area += 0.5 * (prepared.mesh.vertices[t[1]] - a).cross(prepared.mesh.vertices[t[2]] - a).norm();
    }
    const double estimate = area / (std::sqrt(3.0) / 4.0 * options.remesh_edge_m * options.remesh_edge_m);
    if (!(estimate <= kMaxRemeshTriangles)) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "remesh edge length %.6g mm would make about %.3g triangles (at most %.0f): use a longer edge",
                    options.remesh_edge_m * units::kMmPerM, estimate, kMaxRemeshTriangles);
      throw Defect(path, text);
    }
    const PreparedMesh remeshed =
        PrepareTriangleMesh(ToPolygonSoup(RemeshIsotropic(prepared.mesh, options.remesh_edge_m)), path + " (remeshed)");
    prepared.mesh = remeshed.mesh;
  }
  return prepared;
}

void WriteTriangleMesh(const TriangleMesh& mesh, const std::string& path, double scale, bool ascii) {
  const std::string ext = Lower(fs::path(path).extension().string());
  if (ext != ".stl" && ext != ".off" && ext != ".obj" && ext != ".ply")
    throw Defect(path, "unknown mesh format '" + ext + "' (.stl, .off, .obj, .ply)");
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) points.emplace_back(v.x() * scale, v.y() * scale, v.z() * scale);
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    triangles.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  const bool binary = !ascii;
  const auto np = CGAL::parameters::stream_precision(17).use_binary_mode(binary);
  bool ok = false;
  if (ext == ".stl")
    ok = CGAL::IO::write_STL(path, points, triangles, np);
  else if (ext == ".off")
    ok = CGAL::IO::write_OFF(path, points, triangles, np);
  else if (ext == ".obj")
    ok = CGAL::IO::write_OBJ(path, points, triangles, np);
  else
    ok = CGAL::IO::write_PLY(path, points, triangles, np);
  if (!ok) throw Defect(path, "could not write the mesh file");
}

}  // namespace touchdown::geom

// CGAL translation unit 2 of 2 (the other is mesh_io.cpp): isotropic remeshing.
#include "footpad_geom/mesh_remesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <stdexcept>

namespace touchdown::geom {

namespace {
namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

// Normals more than this far apart across an edge make it a feature line that is kept.
constexpr double kFeatureAngleDeg = 30.0;
}  // namespace

TriangleMesh RemeshIsotropic(const TriangleMesh& input, double target_edge_m, int iterations) {
  if (!(target_edge_m > 0.0) || iterations < 1)
    throw std::invalid_argument("RemeshIsotropic: target edge must be > 0 and iterations >= 1");
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertex;
  vertex.reserve(input.vertices.size());
  for (const Eigen::Vector3d& v : input.vertices) vertex.push_back(mesh.add_vertex(Point(v.x(), v.y(), v.z())));
  for (const auto& t : input.triangles)
    if (mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == Mesh::null_face())
      throw std::invalid_argument("RemeshIsotropic: input is not a manifold triangle mesh (prepare it first)");

  auto feature = mesh.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
  PMP::detect_sharp_edges(mesh, kFeatureAngleDeg, feature);
  // Feature edges may be split and collapsed along themselves (protect_constraints false) and
  // their vertices slide along the feature polylines (relax_constraints); corners stay put.
  PMP::isotropic_remeshing(faces(mesh), target_edge_m, mesh,
                           CGAL::parameters::number_of_iterations(static_cast<unsigned>(iterations))
                               .edge_is_constrained_map(feature)
                               .protect_constraints(false)
                               .relax_constraints(true));
  mesh.collect_garbage();

  TriangleMesh out;
  out.vertices.reserve(mesh.number_of_vertices());
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  out.triangles.reserve(mesh.number_of_faces());
  for (Mesh::Face_index f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (Mesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f))) t[k++] = static_cast<int>(v.idx());
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace touchdown::geom

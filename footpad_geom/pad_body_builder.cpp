#include "footpad_geom/pad_body_builder.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "footpad_geom/convex_hull.h"
#include "footpad_geom/mass_properties.h"
#include "rft/input_error.h"

namespace touchdown::geom {

rft::SurfaceElements MakeSurfaceElements(const TriangleMesh& mesh, const Eigen::Vector3d& origin_m) {
  rft::SurfaceElements e;
  e.Resize(static_cast<int>(mesh.triangles.size()));
  for (int i = 0; i < e.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const Eigen::Vector3d p0 = mesh.vertices[t[0]] - origin_m;
    const Eigen::Vector3d p1 = mesh.vertices[t[1]] - origin_m;
    const Eigen::Vector3d p2 = mesh.vertices[t[2]] - origin_m;
    const Eigen::Vector3d twice_area = (p1 - p0).cross(p2 - p0);
    const double norm = twice_area.norm();
    e.p0_B.col(i) = p0;
    e.p1_B.col(i) = p1;
    e.p2_B.col(i) = p2;
    e.area_m2(i) = 0.5 * norm;
    e.n_B.col(i) = norm > 0.0 ? Eigen::Vector3d(twice_area / norm) : Eigen::Vector3d::Zero();
  }
  e.UpdateBounds();
  return e;
}

void ValidateInertia(const Eigen::Matrix3d& inertia, const std::string& source, const std::string& field) {
  auto fail = [&](const std::string& why) { throw MakeInputError(source, field, why); };
  if (!inertia.allFinite()) fail("must be finite");
  const double scale = inertia.cwiseAbs().maxCoeff();
  if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) fail("must be symmetric");
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues();  // ascending
  std::ostringstream s;
  s << "principal moments " << m(0) << ", " << m(1) << ", " << m(2) << " kg m^2";
  if (!(m(0) > 0.0)) fail("must be positive definite (" + s.str() + ")");
  if (m(0) + m(1) < m(2) * (1.0 - 1e-9)) fail("is not a rigid body's inertia: " + s.str() + " break I1 + I2 >= I3");
}

PadBody MakePadBody(const TriangleMesh& mesh, const PadMassModel& mass, const Eigen::Vector3d& reference_point_m,
                    const std::string& source) {
  if (mass.mass_kg.has_value() == mass.density_kg_m3.has_value())
    throw MakeInputError(source, "mass_kg", "give exactly one of mass_kg and density_kg_m3");
  const double given = mass.mass_kg ? *mass.mass_kg : *mass.density_kg_m3;
  if (!(given > 0.0) || !std::isfinite(given))
    throw MakeInputError(source, mass.mass_kg ? "mass_kg" : "density_kg_m3", "must be positive and finite");
  if (!reference_point_m.allFinite()) throw MakeInputError(source, "reference_point", "must be finite");
  const VolumeProperties vp = ComputeVolumeProperties(mesh);
  if (!(vp.volume_m3 > 0.0)) throw MakeInputError(source, "mesh", "encloses no volume (is it closed and outward?)");

  PadBody body;
  body.surface = MakeSurfaceElements(mesh, reference_point_m);
  const double density = mass.mass_kg ? *mass.mass_kg / vp.volume_m3 : *mass.density_kg_m3;
  body.mass_kg = density * vp.volume_m3;
  const Eigen::Vector3d com_m = mass.center_of_mass_m.value_or(vp.centroid_m);
  body.com_B = com_m - reference_point_m;
  if (mass.inertia_com_kg_m2) {
    ValidateInertia(*mass.inertia_com_kg_m2, source, "inertia_kg_m2");
    body.inertia_com_B = *mass.inertia_com_kg_m2;
  } else {
    // A given centre of mass means a non-uniform body (ballast): its inertia is not the
    // uniform solid's, so it must be given too.
    if (mass.center_of_mass_m)
      throw MakeInputError(source, "center_of_mass", "needs the inertia about it (inertia_kg_m2) as well");
    body.inertia_com_B = density * vp.inertia_per_density_m5;
  }
  // Only vertices of some triangle: a stray vertex of the file is not part of the surface.
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int i : t) used[static_cast<size_t>(i)] = 1;
  body.vertices_B.resize(3, static_cast<int>(std::count(used.begin(), used.end(), 1)));
  for (size_t k = 0, c = 0; k < mesh.vertices.size(); ++k)
    if (used[k]) body.vertices_B.col(static_cast<int>(c++)) = mesh.vertices[k] - reference_point_m;
  body.hull_vertices_B = ConvexHullVertices(body.vertices_B);
  body.lowest_z_B = body.vertices_B.cols() > 0 ? body.vertices_B.row(2).minCoeff() : 0.0;
  return body;
}

}  // namespace touchdown::geom

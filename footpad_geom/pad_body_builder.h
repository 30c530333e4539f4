#pragma once
// A pad mesh (closed, outward normals, metres, in its own coordinates) turned into the rigid
// body the contact and the dynamics use: surface elements in the pad frame B (origin at the
// reference point, axes those of the mesh), mass, centre of mass and inertia.
#include <Eigen/Core>

#include <optional>
#include <string>

#include "footpad_geom/pad_body.h"
#include "footpad_geom/triangle_mesh.h"
#include "rft/surface_elements.h"

namespace touchdown::geom {

// How the mass properties are fixed. Exactly one of mass_kg and density_kg_m3. Without an
// explicit inertia, the centre of mass and inertia are those of the solid at uniform density;
// an explicit centre of mass (a ballasted pad) needs an explicit inertia about it.
struct PadMassModel {
  std::optional<double> mass_kg;
  std::optional<double> density_kg_m3;
  std::optional<Eigen::Vector3d> center_of_mass_m;   // mesh coordinates [m]
  std::optional<Eigen::Matrix3d> inertia_com_kg_m2;  // about the centre of mass, mesh axes
};

// The triangles of `mesh` shifted so that `origin_m` (mesh coordinates) becomes the origin.
rft::SurfaceElements MakeSurfaceElements(const TriangleMesh& mesh, const Eigen::Vector3d& origin_m);

// Throws InputError naming `source` if the mass model is inconsistent (both or neither of mass
// and density, a non-physical inertia) or the mesh encloses no volume.
PadBody MakePadBody(const TriangleMesh& mesh, const PadMassModel& mass, const Eigen::Vector3d& reference_point_m,
                    const std::string& source);

// Throws InputError (naming `source` and `field`) unless `inertia` is symmetric positive definite
// and its principal moments satisfy the triangle inequality (I1 + I2 >= I3), as any body's do.
void ValidateInertia(const Eigen::Matrix3d& inertia_kg_m2, const std::string& source, const std::string& field);

}  // namespace touchdown::geom

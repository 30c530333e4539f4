#pragma once
// The 3D model data of a pad as a rigid body, in the pad frame B. The origin of B is the pad's
// reference point (ball-joint centre, or the rod attachment on the rig); z_B points up when the
// pad sits level. Built once at load time (from a mesh, or by revolving an axisymmetric
// profile); never changed during a simulation.
#include <Eigen/Core>

#include "rft/ground.h"
#include "rft/surface_elements.h"

namespace touchdown::geom {

struct PadBody {
  rft::SurfaceElements surface;                            // closed, outward normals
  Eigen::Matrix3Xd vertices_B;                             // the mesh's vertices, each once [m]
  Eigen::Matrix3Xd hull_vertices_B;                        // those on the convex hull [m]
  double mass_kg = 0.0;
  Eigen::Vector3d com_B = Eigen::Vector3d::Zero();         // centre of mass [m]
  Eigen::Matrix3d inertia_com_B = Eigen::Matrix3d::Zero();  // about the centre of mass, B axes [kg m^2]
  double lowest_z_B = 0.0;                                 // lowest surface point in B [m] (<= 0)
};

// The vertices to search for the body's deepest point below `ground`: over a plane the hull's
// (a support point is a hull vertex; a revolved 64-segment pad has 10x fewer), otherwise all.
inline const Eigen::Matrix3Xd& DeepestPointCandidates(const PadBody& body, const rft::GroundSurface& ground) {
  const bool plane = dynamic_cast<const rft::PlaneGround*>(&ground) != nullptr;
  return plane && body.hull_vertices_B.cols() > 0 ? body.hull_vertices_B : body.vertices_B;
}

}  // namespace touchdown::geom

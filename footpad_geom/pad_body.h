#pragma once
// The 3D model data of a pad as a rigid body, in the pad frame B. The origin of B is the pad's
// reference point (ball-joint centre, or the rod attachment on the rig); z_B points up when the
// pad sits level. Built once at load time (from a mesh, or by revolving an axisymmetric
// profile); never changed during a simulation.
#include <Eigen/Core>

#include "rft/surface_elements.h"

namespace touchdown::geom {

struct PadBody {
  rft::SurfaceElements surface;                            // closed, outward normals
  Eigen::Matrix3Xd vertices_B;                             // the mesh's vertices, each once [m]
  double mass_kg = 0.0;
  Eigen::Vector3d com_B = Eigen::Vector3d::Zero();         // centre of mass [m]
  Eigen::Matrix3d inertia_com_B = Eigen::Matrix3d::Zero();  // about the centre of mass, B axes [kg m^2]
  double lowest_z_B = 0.0;                                 // lowest surface point in B [m] (<= 0)
};

}  // namespace touchdown::geom

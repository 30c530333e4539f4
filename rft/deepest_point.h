#pragma once
// How deep the lowest point of a rigid body lies below the ground surface: the largest vertex
// depth (vertical, as RFT measures it). Touchdown events and reported penetrations use it.
// Over a plane the depth is affine in position, so each vertex costs one dot product in the body
// frame (no per-vertex rotation); any other ground evaluates its Depth per vertex.
#include <Eigen/Core>

#include "rft/ground.h"

namespace touchdown::rft {

// vertices_B: the body's vertices in its frame B (each once is enough; a closed triangle mesh's
// lowest point is one of them). Returns -infinity for no vertices.
double DeepestVertexDepth(const Eigen::Matrix3Xd& vertices_B, const Eigen::Matrix3d& R_WB,
                          const Eigen::Vector3d& p_WB, const GroundSurface& ground);

}  // namespace touchdown::rft

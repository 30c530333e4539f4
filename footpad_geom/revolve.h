#pragma once
// Every axisymmetric pad also as a closed triangle mesh: the profile (axisymmetric_profile.h)
// revolved about the pad axis, closed by the top disc at u = h.
//
// Mesh coordinates: z along the axis, origin at the lowest point on the axis (the profile's
// (0, 0)). Rings of vertices sit on the profile's points (the mesh is inscribed: the exact
// surface of revolution is approached as angular_segments grows). Resolution:
//   - `angular_segments` vertices on the rim ring; the edge length there, e = 2 pi r / N, is the
//     target for the whole mesh;
//   - profile pieces longer than e are split, so triangles stay near-isotropic (the flat
//     bottom and the top disc become rings, not one fan of slivers);
//   - rings nearer the axis have fewer vertices (halved while their edges stay <= e, never
//     fewer than 6), so there is no fan of needle triangles at the axis: the axis vertex has
//     a handful of neighbours;
//   - points of a finely sampled curved profile (e.g. 400 pieces) are skipped while the
//     skipped points lie within a tenth of the angular chord error, r (1 - cos(pi / N)) / 10,
//     of the kept chord, so thinning the profile adds less than the angular discretisation
//     already costs. Corners (chamfer, rim) are always kept.
// A profile whose bottom reaches the top height u = h before the rim ends there: the part at
// u = h beyond it would be a sheet of zero thickness.
#include <Eigen/Core>

#include "footpad_geom/axisymmetric_profile.h"
#include "footpad_geom/pad_body.h"
#include "footpad_geom/triangle_mesh.h"

namespace touchdown::geom {

inline constexpr int kDefaultAngularSegments = 128;

// How a ring's n-gon stands for its circle of radius r:
//   kInscribed      vertices on the circle (the mesh above); its area is below pi r^2 by the
//                   factor sin(2 pi / n) / (2 pi / n): 1.1 % at 24 segments, 2.6 % at 16, 4.5 % at 12.
//   kAreaPreserving vertices at r sqrt((2 pi / n) / sin(2 pi / n)), so every horizontal section has
//                   its circle's area: a flat pad's bearing area, which the depth it sinks to
//                   follows, is then exact at any n (the perimeter is that much longer instead:
//                   +1.2 % at 12 segments).
enum class RimPolygon { kInscribed, kAreaPreserving };

// The radial scale kAreaPreserving puts on a ring of n vertices (n >= 3).
double AreaPreservingRadiusScale(int n);

// angular_segments >= 6 (InputError otherwise). The profile must be valid (ValidateProfile).
TriangleMesh RevolveProfileToMesh(const AxisymmetricProfile& profile, int angular_segments,
                                  RimPolygon rim = RimPolygon::kInscribed);

// The revolved pad at uniform density with total mass `mass_kg`; the pad frame B has its origin
// at `reference_point_from_lowest_point` (mesh coordinates above, e.g. (0, 0, h) for the top
// centre, the rod attachment of the paper's rig) and the mesh's axes.
PadBody RevolveProfileToBody(const AxisymmetricProfile& profile, int angular_segments, double mass_kg,
                             const Eigen::Vector3d& reference_point_from_lowest_point);

}  // namespace touchdown::geom

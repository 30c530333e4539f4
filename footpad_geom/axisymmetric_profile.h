#pragma once
// Axisymmetric footpads described by their generator curve (profile).
//
// A profile is a polyline in the (x, u) half-plane: x is the radius from the pad axis, u the
// height above the pad's lowest point. It starts on the axis at the lowest point (0, 0),
// runs outward along the bottom with x and u never decreasing, and ends at the top of the
// side wall (r, h): the factories append a vertical wall from the rim up to the thickness h.
// The top face looks up and never leads a downward motion, so it is not part of the profile.
// Curved profiles are discretised into `segments` straight pieces (rings); the force
// integral is exact on each piece, so refinement converges to the smooth pad.
#include <string>
#include <vector>

namespace touchdown::geom {

struct ProfilePoint {
  double x_m = 0.0;  // radius [m]
  double u_m = 0.0;  // height above the lowest point [m]
  // The generator curve has no corner here: the point samples a smooth curve (the exponential
  // and spherical-cap bottoms between axis and rim), so the pieces on either side are chords of
  // one curve, not two faces meeting at an edge. Corners (rim, chamfer, tabulated points) keep false.
  bool smooth = false;
};

struct AxisymmetricProfile {
  std::vector<ProfilePoint> points;  // from (0, 0) to (radius, thickness)
  double radius_m() const { return points.back().x_m; }
  double thickness_m() const { return points.back().u_m; }
};

// Throws InputError (naming `source`) unless the polyline starts at (0, 0), never
// decreases in x or u, has no zero-length piece and encloses a non-zero bottom area.
void ValidateProfile(const AxisymmetricProfile& profile, const std::string& source);

AxisymmetricProfile MakeFlatProfile(double radius_m, double thickness_m);
// 45-degree chamfer of leg c at the rim (C4: c = 4 mm).
AxisymmetricProfile MakeChamferProfile(double radius_m, double thickness_m, double chamfer_m);
// The paper's curved pad: u = a0 (exp(a1 x) - 1) out to the rim, then the side wall.
AxisymmetricProfile MakeExponentialProfile(double radius_m, double thickness_m, double a0_m,
                                           double a1_per_m, int segments);
// A spherical cap of sphere radius R at the bottom (u = R - sqrt(R^2 - x^2)), then the wall.
AxisymmetricProfile MakeSphericalCapProfile(double radius_m, double thickness_m,
                                            double sphere_radius_m, int segments);
// A cone with its apex at the lowest point, half-angle measured from the axis.
AxisymmetricProfile MakeConeProfile(double radius_m, double thickness_m, double half_angle_rad);
// A tabulated bottom (x, u) from the axis to the rim; the side wall is appended.
AxisymmetricProfile MakeTabulatedProfile(std::vector<ProfilePoint> bottom, double thickness_m);

}  // namespace touchdown::geom

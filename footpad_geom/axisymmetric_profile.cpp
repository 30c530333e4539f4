#include "footpad_geom/axisymmetric_profile.h"

#include <cmath>
#include <sstream>

#include "rft/input_error.h"

namespace touchdown::geom {

namespace {
std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void RequirePositive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw MakeInputError("", what, "must be a positive finite number, got " + Num(value));
}

void RequireSegments(int segments) {
  if (segments < 1) throw MakeInputError("", "segments", "must be >= 1, got " + Num(segments));
}

// Appends the vertical side wall from the rim up to the pad thickness.
AxisymmetricProfile WithSideWall(std::vector<ProfilePoint> bottom, double thickness_m) {
  const ProfilePoint rim = bottom.back();
  if (rim.u_m > thickness_m)
    throw MakeInputError("", "thickness",
                         "bottom profile rises to " + Num(rim.u_m) + " m, above the thickness " +
                             Num(thickness_m) + " m");
  if (rim.u_m < thickness_m) bottom.push_back({rim.x_m, thickness_m});
  return AxisymmetricProfile{std::move(bottom)};
}
}  // namespace

void ValidateProfile(const AxisymmetricProfile& p, const std::string& source) {
  if (p.points.size() < 2) throw MakeInputError(source, "profile", "needs at least two points");
  if (p.points.front().x_m != 0.0 || p.points.front().u_m != 0.0)
    throw MakeInputError(source, "profile", "must start at the lowest point on the axis (0, 0)");
  for (size_t i = 1; i < p.points.size(); ++i) {
    const ProfilePoint& a = p.points[i - 1];
    const ProfilePoint& b = p.points[i];
    if (!std::isfinite(b.x_m) || !std::isfinite(b.u_m))
      throw MakeInputError(source, "profile", "point " + Num(double(i)) + " is not finite");
    if (b.x_m < a.x_m || b.u_m < a.u_m)
      throw MakeInputError(source, "profile",
                           "x and u must never decrease outward (point " + Num(double(i)) + ")");
    if (b.x_m == a.x_m && b.u_m == a.u_m)
      throw MakeInputError(source, "profile", "point " + Num(double(i)) + " repeats the previous one");
  }
  if (!(p.radius_m() > 0.0))
    throw MakeInputError(source, "profile", "pad has zero area (radius 0)");
}

AxisymmetricProfile MakeFlatProfile(double radius_m, double thickness_m) {
  RequirePositive(radius_m, "radius");
  RequirePositive(thickness_m, "thickness");
  return WithSideWall({{0.0, 0.0}, {radius_m, 0.0}}, thickness_m);
}

AxisymmetricProfile MakeChamferProfile(double radius_m, double thickness_m, double chamfer_m) {
  RequirePositive(radius_m, "radius");
  RequirePositive(thickness_m, "thickness");
  RequirePositive(chamfer_m, "chamfer");
  if (chamfer_m >= radius_m || chamfer_m > thickness_m)
    throw MakeInputError("", "chamfer", "must be smaller than the radius and the thickness, got " +
                                            Num(chamfer_m) + " m");
  return WithSideWall({{0.0, 0.0}, {radius_m - chamfer_m, 0.0}, {radius_m, chamfer_m}},
                      thickness_m);
}

AxisymmetricProfile MakeExponentialProfile(double radius_m, double thickness_m, double a0_m,
                                           double a1_per_m, int segments) {
  RequirePositive(radius_m, "radius");
  RequirePositive(thickness_m, "thickness");
  RequirePositive(a0_m, "a0");
  RequirePositive(a1_per_m, "a1");
  RequireSegments(segments);
  std::vector<ProfilePoint> bottom;
  for (int i = 0; i <= segments; ++i) {
    const double x = radius_m * i / segments;
    bottom.push_back({x, a0_m * std::expm1(a1_per_m * x), i > 0 && i < segments});
  }
  return WithSideWall(std::move(bottom), thickness_m);
}

AxisymmetricProfile MakeSphericalCapProfile(double radius_m, double thickness_m,
                                            double sphere_radius_m, int segments) {
  RequirePositive(radius_m, "radius");
  RequirePositive(thickness_m, "thickness");
  RequirePositive(sphere_radius_m, "sphere_radius");
  RequireSegments(segments);
  if (sphere_radius_m < radius_m)
    throw MakeInputError("", "sphere_radius", "must be at least the pad radius, got " +
                                                  Num(sphere_radius_m) + " m");
  std::vector<ProfilePoint> bottom;
  for (int i = 0; i <= segments; ++i) {
    // Even steps in the polar angle give even arc lengths on the cap.
    const double theta = std::asin(radius_m / sphere_radius_m) * i / segments;
    bottom.push_back({sphere_radius_m * std::sin(theta), sphere_radius_m * (1 - std::cos(theta)), i > 0 && i < segments});
  }
  bottom.back().x_m = radius_m;
  return WithSideWall(std::move(bottom), thickness_m);
}

AxisymmetricProfile MakeConeProfile(double radius_m, double thickness_m, double half_angle_rad) {
  RequirePositive(radius_m, "radius");
  RequirePositive(thickness_m, "thickness");
  if (!(half_angle_rad > 0.0 && half_angle_rad < std::acos(-1.0) / 2))
    throw MakeInputError("", "half_angle", "must be in (0, 90) degrees");
  return WithSideWall({{0.0, 0.0}, {radius_m, radius_m / std::tan(half_angle_rad)}}, thickness_m);
}

AxisymmetricProfile MakeTabulatedProfile(std::vector<ProfilePoint> bottom, double thickness_m) {
  RequirePositive(thickness_m, "thickness");
  if (bottom.size() < 2) throw MakeInputError("", "profile", "needs at least two points");
  AxisymmetricProfile p = WithSideWall(std::move(bottom), thickness_m);
  ValidateProfile(p, "");
  return p;
}

}  // namespace touchdown::geom

#include "footpad_geom/revolve.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "footpad_geom/pad_body_builder.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"

namespace touchdown::geom {

namespace {

constexpr int kMinRingVertices = limits::kMinAngularSegments;

// Distance of q from the segment a-b in the (x, u) plane.
double DistanceToSegment(const ProfilePoint& q, const ProfilePoint& a, const ProfilePoint& b) {
  const double dx = b.x_m - a.x_m, du = b.u_m - a.u_m;
  const double len2 = dx * dx + du * du;
  double t = len2 > 0.0 ? ((q.x_m - a.x_m) * dx + (q.u_m - a.u_m) * du) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(q.x_m - a.x_m - t * dx, q.u_m - a.u_m - t * du);
}

// The generator curve of the closed surface: from the axis along the profile to the rim,
// then along the top (u = h) back to the axis, with long pieces split to <= max_piece.
std::vector<ProfilePoint> ClosedGenerator(const AxisymmetricProfile& profile, double tolerance, double max_piece) {
  const double h = profile.thickness_m();
  // Start at the last point on the axis; stop at the first point at the top height.
  std::vector<ProfilePoint> pts;
  for (const ProfilePoint& p : profile.points) {
    if (p.x_m == 0.0) pts.clear();
    pts.push_back(p);
    if (p.u_m >= h) break;
  }
  if (pts.back().x_m == 0.0)
    throw MakeInputError("", "profile", "reaches the top height on the axis: the pad encloses no volume");
  // Greedy simplification: extend each chord while every skipped point stays within tolerance.
  std::vector<ProfilePoint> kept{pts.front()};
  std::size_t anchor = 0;
  for (std::size_t j = 2; j < pts.size(); ++j) {
    bool fits = true;
    for (std::size_t k = anchor + 1; k < j && fits; ++k)
      fits = DistanceToSegment(pts[k], pts[anchor], pts[j]) <= tolerance;
    if (!fits) {
      anchor = j - 1;
      kept.push_back(pts[anchor]);
    }
  }
  if (pts.size() > 1) kept.push_back(pts.back());
  kept.push_back({0.0, h});  // the top disc closes at the axis

  std::vector<ProfilePoint> out{kept.front()};
  for (std::size_t i = 1; i < kept.size(); ++i) {
    const ProfilePoint a = kept[i - 1], b = kept[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::hypot(b.x_m - a.x_m, b.u_m - a.u_m) / max_piece)));
    for (int k = 1; k <= pieces; ++k) {
      const double t = static_cast<double>(k) / pieces;
      out.push_back({a.x_m + t * (b.x_m - a.x_m), a.u_m + t * (b.u_m - a.u_m)});
    }
    out.back() = b;
  }
  return out;
}

}  // namespace

double AreaPreservingRadiusScale(int n) {
  const double step = 2.0 * std::numbers::pi / n;
  return std::sqrt(step / std::sin(step));
}

TriangleMesh RevolveProfileToMesh(const AxisymmetricProfile& profile, int angular_segments, RimPolygon rim) {
  if (angular_segments < kMinRingVertices)
    throw MakeInputError("", "angular_segments", "must be >= " + std::to_string(kMinRingVertices) + ", got " +
                                                     std::to_string(angular_segments));
  ValidateProfile(profile, "");
  const int n_rim = angular_segments;
  double r_max = 0.0;
  for (const ProfilePoint& p : profile.points) r_max = std::max(r_max, p.x_m);
  const double pi = std::numbers::pi;
  const double edge = 2.0 * pi * r_max / n_rim;
  // A tenth of the rim's angular chord error: a chord error on a curved profile is one-signed,
  // so it is kept well below the angular error it would otherwise add to.
  const double tolerance = 0.1 * r_max * (1.0 - std::cos(pi / n_rim));
  const std::vector<ProfilePoint> generator = ClosedGenerator(profile, tolerance, edge);

  // One ring of vertices per generator point; a point on the axis is a single vertex.
  struct Ring {
    int first, count;
  };
  TriangleMesh mesh;
  std::vector<Ring> rings;
  for (const ProfilePoint& p : generator) {
    int n = 1;
    if (p.x_m > 0.0) {
      n = n_rim;
      while (n % 2 == 0 && n / 2 >= kMinRingVertices && n / 2 >= n_rim * p.x_m / r_max) n /= 2;
    }
    rings.push_back({static_cast<int>(mesh.vertices.size()), n});
    // Each ring scaled by its own count: the rings nearer the axis have fewer vertices.
    const double r = n > 1 && rim == RimPolygon::kAreaPreserving ? p.x_m * AreaPreservingRadiusScale(n) : p.x_m;
    for (int i = 0; i < n; ++i) {
      const double theta = 2.0 * pi * i / n;
      mesh.vertices.emplace_back(r * std::cos(theta), r * std::sin(theta), p.u_m);
    }
  }
  // Bands between consecutive rings. Walking along the generator (outward on the bottom, up
  // the wall, inward on the top) with theta increasing, triangles (a_i, a_i+1, b_j) and
  // (a_i, b_j+1, b_j) are counter-clockwise seen from outside. Both rings start at theta = 0;
  // the one whose next vertex comes first in theta advances.
  for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
    const Ring a = rings[k], b = rings[k + 1];
    auto va = [&](int i) { return a.first + (a.count == 1 ? 0 : i % a.count); };
    auto vb = [&](int j) { return b.first + (b.count == 1 ? 0 : j % b.count); };
    const int na = a.count == 1 ? 0 : a.count, nb = b.count == 1 ? 0 : b.count;
    int i = 0, j = 0;
    while (i < na || j < nb) {
      // Compare the angles (i + 1) / na and (j + 1) / nb without division.
      const bool advance_a = j == nb || (i < na && static_cast<long>(i + 1) * nb <= static_cast<long>(j + 1) * na);
      if (advance_a) {
        mesh.triangles.push_back({va(i), va(i + 1), vb(j)});
        ++i;
      } else {
        mesh.triangles.push_back({va(i), vb(j + 1), vb(j)});
        ++j;
      }
    }
  }
  return mesh;
}

PadBody RevolveProfileToBody(const AxisymmetricProfile& profile, int angular_segments, double mass_kg,
                             const Eigen::Vector3d& reference_point_from_lowest_point) {
  PadMassModel mass;
  mass.mass_kg = mass_kg;
  return MakePadBody(RevolveProfileToMesh(profile, angular_segments), mass, reference_point_from_lowest_point,
                     "revolved profile");
}

}  // namespace touchdown::geom

#include "rft/soil_map.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace touchdown::rft {

bool PolygonContains(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p) {
  bool inside = false;
  const size_t n = poly.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

namespace {
double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

bool OnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

// Whether segments ab and cd share a point (crossing, touching or overlapping).
bool SegmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  const Eigen::Vector2d& d) {
  const double d1 = Cross(c, d, a), d2 = Cross(c, d, b), d3 = Cross(a, b, c), d4 = Cross(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && OnSegment(c, d, a)) || (d2 == 0 && OnSegment(c, d, b)) || (d3 == 0 && OnSegment(a, b, c)) ||
         (d4 == 0 && OnSegment(a, b, d));
}
}  // namespace

std::string PolygonProblem(const std::vector<Eigen::Vector2d>& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return "needs at least three corners";
  double twice_area = 0.0, extent = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % n];
    if (a == b) return "corners " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " coincide";
    twice_area += a.x() * b.y() - b.x() * a.y();
    extent = std::max(extent, (b - polygon[0]).cwiseAbs().maxCoeff());
  }
  // Edges that are not neighbours must be apart (a figure eight, a bow tie: whose signed area may
  // even cancel to zero).
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the closing corner
      if (SegmentsMeet(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n]))
        return "edges " + std::to_string(i) + " (corners " + std::to_string(i) + "-" + std::to_string((i + 1) % n) +
               ") and " + std::to_string(j) + " (corners " + std::to_string(j) + "-" + std::to_string((j + 1) % n) +
               ") cross or touch: the polygon must not intersect itself";
    }
  // A polygon whose edges do not cross and that has no area has every corner on one line.
  if (!(std::abs(twice_area) > 1e-12 * extent * extent)) return "encloses no area (its corners lie on one line)";
  // Neighbouring edges share only their corner: not one folding back along the other.
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d &p = polygon[(i + n - 1) % n], &corner = polygon[i], &q = polygon[(i + 1) % n];
    if (Cross(corner, p, q) == 0.0 && (p - corner).dot(q - corner) > 0.0)
      return "at corner " + std::to_string(i) + " the polygon folds back along its previous edge";
  }
  return "";
}

std::vector<Eigen::Vector2d> RectanglePolygon(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Terrain UniformTerrain(std::string soil_name, SoilContactModel contact, std::shared_ptr<const GroundSurface> surface) {
  Terrain t;
  t.surface = std::move(surface);
  t.soils.push_back({std::move(soil_name), std::move(contact)});
  return t;
}

int SoilGrid::SoilAt(double x_m, double y_m) const {
  const double u = std::floor((x_m - x0_m) / cell_m), v = std::floor((y_m - y0_m) / cell_m);
  if (!(u >= 0.0 && u < nx && v >= 0.0 && v < ny)) return -1;
  return soil[static_cast<size_t>(v) * static_cast<size_t>(nx) + static_cast<size_t>(u)];
}

int Terrain::SoilAt(double x_m, double y_m) const {
  const Eigen::Vector2d p(x_m, y_m);
  for (const SoilPatch& patch : patches)
    if (PolygonContains(patch.polygon_W, p)) return patch.soil;
  const int cell = grid.nx > 0 ? grid.SoilAt(x_m, y_m) : -1;
  return cell >= 0 ? cell : 0;
}

}  // namespace touchdown::rft

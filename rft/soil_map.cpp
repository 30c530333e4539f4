#include "rft/soil_map.h"

#include <cmath>

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

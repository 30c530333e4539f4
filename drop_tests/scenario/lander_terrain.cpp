#include "drop_tests/scenario/lander_terrain.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "rft/crater_population.h"
#include "rft/input_error.h"

namespace touchdown::scenario {

rft::HeightGrid LoadTerrainGrid(const TerrainFileSpec& terrain, double height_m) {
  rft::HeightGrid grid = io::ReadEsriAsciiGrid(terrain.file, terrain.window);
  const Eigen::Vector2d origin = terrain.origin_m.value_or(
      Eigen::Vector2d(0.5 * (grid.x0_m + grid.x_max_m()), 0.5 * (grid.y0_m + grid.y_max_m())));
  if (!(origin.x() >= grid.x0_m && origin.x() <= grid.x_max_m() && origin.y() >= grid.y0_m &&
        origin.y() <= grid.y_max_m()))
    throw MakeInputError(terrain.file, "origin_m", "lies outside the terrain's nodes");
  // The raster's own height at the origin, interpolated as the ground will be.
  const double reference = rft::HeightFieldGround(grid).Height(origin.x(), origin.y());
  grid.x0_m -= origin.x();
  grid.y0_m -= origin.y();
  for (double& h : grid.heights_m) h = h - reference + height_m;
  return grid;
}

std::shared_ptr<const rft::HeightFieldGround> BuildHeightField(const LanderHeightField& spec, double height_m,
                                                               double slope_x, double slope_y,
                                                               const std::string& where) {
  if (!spec.terrain && !spec.craters) return nullptr;
  rft::HeightGrid grid;
  if (spec.terrain) {
    grid = LoadTerrainGrid(*spec.terrain, height_m);
  } else {
    const CraterFieldSpec& c = *spec.craters;
    const int n = 2 * static_cast<int>(std::ceil(c.half_extent_m / c.cell_size_m - 1e-9)) + 1;  // odd: a node at 0
    const double h = 0.5 * (n - 1) * c.cell_size_m;
    grid = {.x0_m = -h, .y0_m = -h, .cell_m = c.cell_size_m, .nx = n, .ny = n, .heights_m = {}};
    grid.heights_m.reserve(static_cast<size_t>(n) * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        grid.heights_m.push_back(height_m + slope_x * (-h + i * c.cell_size_m) + slope_y * (-h + j * c.cell_size_m));
  }
  if (spec.craters) {
    const CraterFieldSpec& c = *spec.craters;
    const rft::CraterPopulationSpec population{.cumulative_per_m2 = c.cumulative_per_m2,
                                               .exponent = c.exponent,
                                               .min_diameter_m = c.min_diameter_m,
                                               .max_diameter_m = c.max_diameter_m,
                                               .degradation_min = c.degradation_min,
                                               .degradation_max = c.degradation_max,
                                               .seed = static_cast<uint64_t>(c.seed)};
    const double wx = grid.x_max_m() - grid.x0_m + 2 * c.max_diameter_m;
    const double wy = grid.y_max_m() - grid.y0_m + 2 * c.max_diameter_m;
    if (const std::string problem = rft::CraterPopulationProblem(population, wx * wy); !problem.empty())
      throw MakeInputError(where, "ground.craters", problem);
    rft::AddCraters(rft::DrawCraters(population, grid.x0_m, grid.y0_m, grid.x_max_m(), grid.y_max_m()), &grid);
  }
  if (const std::string problem = rft::HeightGridProblem(grid); !problem.empty())
    throw MakeInputError(where, spec.terrain ? "ground.terrain" : "ground.craters", problem);
  return std::make_shared<const rft::HeightFieldGround>(std::move(grid));
}

std::shared_ptr<const rft::GroundSurface> GroundSurfaceOf(const LanderHeightField& spec, double height_m,
                                                          double slope_x, double slope_y, const std::string& where) {
  if (!spec.has_height_field()) return std::make_shared<const rft::PlaneGround>(height_m, slope_x, slope_y);
  // The loader refuses a slope beside a raster; a sweep or study setting slope_deg reaches here.
  if (spec.terrain && (slope_x != 0.0 || slope_y != 0.0))
    throw MakeInputError(where, "ground.slope_deg", "only without a terrain file (the terrain gives the slopes)");
  if (spec.surface && spec.built_for == std::array<double, 3>{height_m, slope_x, slope_y}) return spec.surface;
  return BuildHeightField(spec, height_m, slope_x, slope_y, where);
}

void RequireOnHeightField(const LanderHeightField& spec, const rft::GroundSurface& surface,
                          const std::vector<Eigen::Vector2d>& points_W, double margin_m, const std::string& where) {
  const auto* field = dynamic_cast<const rft::HeightFieldGround*>(&surface);
  if (field == nullptr) return;
  const rft::HeightGrid& g = field->grid();
  for (size_t k = 0; k < points_W.size(); ++k) {
    const Eigen::Vector2d& p = points_W[k];
    if (field->Contains(p.x() - margin_m, p.y() - margin_m) && field->Contains(p.x() + margin_m, p.y() + margin_m))
      continue;
    char text[256];
    std::snprintf(text, sizeof text,
                  "pad %zu starts at (%.3f, %.3f) m, not %.3f m inside the height field's nodes, x %.3f to %.3f, "
                  "y %.3f to %.3f (world frame): widen the window or the extent",
                  k + 1, p.x(), p.y(), margin_m, g.x0_m, g.x_max_m(), g.y0_m, g.y_max_m());
    throw MakeInputError(where, spec.terrain ? "ground.terrain" : "ground.craters", text);
  }
}

}  // namespace touchdown::scenario

#pragma once
// A lander scenario's ground as a height field instead of a plane (docs/terrain.md): a terrain
// raster (`ground.terrain`, an ESRI ASCII grid, drop_tests/formats/esri_ascii_grid.h) and/or
// generated craters (`ground.craters`, rft/crater_population.h), built once when the scenario is
// read into the one rft::HeightFieldGround every landing of it shares.
//
// World frame: the raster's point `origin_m` (default: the window's centre) is the world's origin,
// and heights are shifted so the surface there is at `height_m` (a site's elevation of -2 km
// would otherwise cost the integrator its millimetres: rft/physical_limits.h kHeight_m). Craters
// without a raster are drawn on the scenario's plane (height_m, slope_deg, downhill_azimuth_deg)
// sampled over [-half_extent_m, half_extent_m]^2 around the origin.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/formats/esri_ascii_grid.h"
#include "rft/ground.h"
#include "rft/height_field_ground.h"

namespace touchdown::scenario {

struct TerrainFileSpec {
  std::string file;                         // the raster, as a path (resolved against the scenario's folder)
  std::optional<io::RasterWindow> window;   // raster coordinates [m]; none: the whole raster
  std::optional<Eigen::Vector2d> origin_m;  // raster coordinates of the world origin; none: the window's centre
};

// ground.craters, flat so its numbers are one io::FieldTable (lander_scenario_yaml.cpp).
struct CraterFieldSpec {
  double cumulative_per_m2 = 0.0;  // c in N(>D) = c D^-b [craters / m^2, D in m]
  double exponent = 2.0;           // b
  double min_diameter_m = 0.0, max_diameter_m = 0.0;
  double degradation_min = 0.0, degradation_max = 0.0;  // each crater's drawn uniformly between
  double cell_size_m = 0.0, half_extent_m = 0.0;        // the grid, without a terrain file
  double seed = 0.0;                                    // a whole number (a YAML number field)
};

struct LanderHeightField {
  std::optional<TerrainFileSpec> terrain;
  std::optional<CraterFieldSpec> craters;
  // Built from them when the scenario is read (null for a plane): world frame, craters added; and
  // the plane it was built on (height_m, slope_x, slope_y), so a sweep that changes the plane
  // builds it again rather than land on a stale one.
  std::shared_ptr<const rft::HeightFieldGround> surface;
  std::array<double, 3> built_for{0.0, 0.0, 0.0};
  bool has_height_field() const { return terrain.has_value() || craters.has_value(); }
};

// The grid of `terrain` in the world frame (origin and heights shifted as above); InputError
// naming the raster file otherwise.
rft::HeightGrid LoadTerrainGrid(const TerrainFileSpec& terrain, double height_m);

// The ground's one height field: the raster's (if any), or the plane sampled over the craters'
// extent, with the craters added. `where` names the scenario file for errors.
std::shared_ptr<const rft::HeightFieldGround> BuildHeightField(const LanderHeightField& spec, double height_m,
                                                               double slope_x, double slope_y,
                                                               const std::string& where);

// The one place a lander's ground surface is made: the height field if the scenario has one (the
// one built at load when it was built on this plane), else the plane
// z = height_m + slope_x x + slope_y y. A slope beside a terrain file is refused (InputError).
std::shared_ptr<const rft::GroundSurface> GroundSurfaceOf(const LanderHeightField& spec, double height_m,
                                                          double slope_x, double slope_y, const std::string& where);

// Throws InputError (file `where`, field ground.terrain or ground.craters) unless every point of
// `points_W` (x, y) lies `margin_m` inside the height field's grid: a landing must start on
// measured or generated ground, not on the clamped edge heights beyond it.
void RequireOnHeightField(const LanderHeightField& spec, const rft::GroundSurface& surface,
                          const std::vector<Eigen::Vector2d>& points_W, double margin_m, const std::string& where);

}  // namespace touchdown::scenario

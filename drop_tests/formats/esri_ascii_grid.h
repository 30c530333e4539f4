#pragma once
// ESRI ASCII grids (.asc, "Arc/Info ASCII Grid"): a terrain raster readable without GDAL.
//
//   ncols 4                  (any order; keys case-insensitive)
//   nrows 3
//   xllcorner 1000.0         (or xllcenter: the lower-left cell's centre)
//   yllcorner 2000.0         (or yllcenter)
//   cellsize 1.0             (square cells; > 0)
//   NODATA_value -9999       (optional)
//   z z z z                  (nrows lines of ncols numbers, the northernmost row first)
//
// Each value is the height [m] at its cell's centre; those centres become the nodes of an
// rft::HeightGrid (rft/height_field_ground.h) in the raster's own coordinates (x east, y north,
// the map units taken as metres). Everything is checked at load time, and a refusal is one
// InputError naming the file, the line (and for data the row and column, 1-based, row 1 the
// northernmost) and the reason: a missing, repeated or unknown header key, a count or size that
// is not a positive number, a row of the wrong length, a value that is not a finite number,
// missing or extra rows, and a NODATA value among the nodes the window keeps (elsewhere it is
// allowed: real rasters have NODATA margins).
#include <optional>
#include <string>

#include "rft/height_field_ground.h"

namespace touchdown::io {

// A rectangle in the raster's coordinates [m]: the nodes (cell centres) inside it, edges
// included, are kept. It must lie within the raster's node extent and keep at least 3 x 3 nodes.
struct RasterWindow {
  double x_min_m = 0.0, y_min_m = 0.0, x_max_m = 0.0, y_max_m = 0.0;
};

// The largest window kept, in nodes (5000 x 5000 at 8 bytes each: 200 MB of heights).
inline constexpr long kMaxRasterWindowNodes = 25'000'000;

// The heights of `path` inside `window` (the whole raster without one), south row first.
rft::HeightGrid ReadEsriAsciiGrid(const std::string& path, const std::optional<RasterWindow>& window = {});

}  // namespace touchdown::io

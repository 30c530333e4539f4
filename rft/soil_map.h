#pragma once
// The ground a lander lands on: a free surface (level plane, uniform slope or any height field
// behind rft::GroundSurface) and a map of soils over it. Soil patches are polygons in the
// horizontal plane (rectangles are four-corner polygons); a point takes the soil of the first
// patch that contains it, else the default soil. Each soil is a contact model (a 3D stress law
// carrying its own scaling, zeta at the run's gravity, and its pad-level terms), so each pad can
// land on loosely or closely packed bed.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "rft/ground.h"
#include "rft/soil_contact_model.h"

namespace touchdown::rft {

struct SoilPatch {
  std::string name;
  std::vector<Eigen::Vector2d> polygon_W;  // (x, y) corners [m], either orientation, no self-crossing
  int soil = 0;                            // index into Terrain::soils
};

// A square grid of soil cells (a random patch field's draw, drop_tests/scenario/soil_field.h):
// cell (i, j) covers [x0 + i c, x0 + (i + 1) c) x [y0 + j c, y0 + (j + 1) c). Looked up in O(1):
// a field of thousands of cells as polygon patches would cost a polygon test per cell in every
// right-hand side.
struct SoilGrid {
  double x0_m = 0.0, y0_m = 0.0, cell_m = 1.0;
  int nx = 0, ny = 0;
  std::vector<int> soil;  // row by row (j * nx + i): indices into Terrain::soils

  // The soil of the cell holding (x, y), or -1 outside the grid.
  int SoilAt(double x_m, double y_m) const;
};

struct TerrainSoil {
  std::string name;
  SoilContactModel contact;
};

struct Terrain {
  std::shared_ptr<const rft::GroundSurface> surface;
  std::vector<TerrainSoil> soils;  // soils[0] is the default soil
  std::vector<SoilPatch> patches;
  SoilGrid grid;  // after the patches; empty (nx = 0) without a patch field

  // Index into soils of the soil at (x, y): the first patch holding it, else the grid's cell,
  // else the default soil.
  int SoilAt(double x_m, double y_m) const;
};

// One soil everywhere on `surface`, no patches: a free drop's or a rig's uniform bed.
Terrain UniformTerrain(std::string soil_name, SoilContactModel contact,
                       std::shared_ptr<const GroundSurface> surface = std::make_shared<const PlaneGround>());

// Even-odd point-in-polygon test (boundary points may fall either side).
bool PolygonContains(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

// "" when `polygon` (corners in order, closed implicitly) is a simple polygon with an area;
// otherwise why not: two consecutive corners coincide, the corners enclose no area (all on one
// line), or two edges cross or touch (a figure eight, a bow tie). The even-odd test of
// PolygonContains gives such shapes an inside the user did not draw.
std::string PolygonProblem(const std::vector<Eigen::Vector2d>& polygon);

// Rectangle [x0, x1] x [y0, y1] as a polygon.
std::vector<Eigen::Vector2d> RectanglePolygon(double x0, double y0, double x1, double y1);

}  // namespace touchdown::rft

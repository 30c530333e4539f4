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

struct TerrainSoil {
  std::string name;
  SoilContactModel contact;
};

struct Terrain {
  std::shared_ptr<const rft::GroundSurface> surface;
  std::vector<TerrainSoil> soils;  // soils[0] is the default soil
  std::vector<SoilPatch> patches;

  // Index into soils of the soil at (x, y).
  int SoilAt(double x_m, double y_m) const;
};

// One soil everywhere on `surface`, no patches: a free drop's or a rig's uniform bed.
Terrain UniformTerrain(std::string soil_name, SoilContactModel contact,
                       std::shared_ptr<const GroundSurface> surface = std::make_shared<const PlaneGround>());

// Even-odd point-in-polygon test (boundary points may fall either side).
bool PolygonContains(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

// Rectangle [x0, x1] x [y0, y1] as a polygon.
std::vector<Eigen::Vector2d> RectanglePolygon(double x0, double y0, double x1, double y1);

}  // namespace touchdown::rft

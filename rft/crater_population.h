#pragma once
// A seeded, reproducible population of craters over a rectangle, from a cumulative
// size-frequency distribution, and its heights added into a height grid.
//
// Sizes: N(>D) = c D^-b craters per square metre with D in metres, between D_min and D_max. For
// reference (not a default of any file): the lunar maria's small craters are in equilibrium near
// b = 2, with N(>D) = 10^10.9 D^-2 per 10^6 km^2 (Trask 1966, Ranger VIII and IX, JPL TR 32-800,
// as quoted by Melosh 1989, ch. 10), i.e. c = 10^-1.1 = 0.079 per m^2 with D in m.
// Draws: the expected count over the rectangle widened by D_max on every side (craters centred
// just outside still throw ejecta in), c (D_min^-b - D_max^-b) area, rounded up or down at random
// with the probability of its fraction (mean-preserving; a Poisson count is not needed for a
// terrain); each crater's centre uniform, its diameter by inverting the truncated power law, its
// degradation uniform in [degradation_min, degradation_max]. Every number comes from the seed and
// the crater's index through the SplitMix64 finaliser, so a seed gives the same craters, bit for
// bit, on every run and machine.
// Heights: each crater's profile (rft/crater_profile.h) is added to the grid's nodes out to
// kCraterReach radii (the ejecta there is 0.2 % of the rim height; beyond it nothing is added).
// Adding is an assumption: a later crater does not erase the earlier ones under it.
#include <cstdint>
#include <string>
#include <vector>

#include "rft/height_field_ground.h"

namespace touchdown::rft {

inline constexpr double kCraterReach = 8.0;         // radii from the centre a crater's heights reach
inline constexpr double kMaxExpectedCraters = 1e6;  // a population larger than this is refused

struct CraterPopulationSpec {
  double cumulative_per_m2 = 0.0;  // c in N(>D) = c D^-b [craters / m^2, D in m]
  double exponent = 2.0;           // b [-]
  double min_diameter_m = 1.0, max_diameter_m = 10.0;
  double degradation_min = 0.0, degradation_max = 0.0;  // in [0, 1), rft::DegradedCraterShape
  uint64_t seed = 0;
};

struct Crater {
  double x_m = 0.0, y_m = 0.0, diameter_m = 0.0, degradation = 0.0;
};

// "" when `spec` can be drawn over a rectangle of `area_m2`; otherwise why not (c >= 0, b > 0,
// 0 < D_min < D_max, 0 <= degradation_min <= degradation_max < 1, at most kMaxExpectedCraters).
std::string CraterPopulationProblem(const CraterPopulationSpec& spec, double area_m2);

// The craters over [x_min, x_max] x [y_min, y_max] widened by D_max (see above).
std::vector<Crater> DrawCraters(const CraterPopulationSpec& spec, double x_min_m, double y_min_m, double x_max_m,
                                double y_max_m);

// Adds each crater's heights to the nodes of `grid`.
void AddCraters(const std::vector<Crater>& craters, HeightGrid* grid);

}  // namespace touchdown::rft

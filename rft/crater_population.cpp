#include "rft/crater_population.h"

#include <algorithm>
#include <cmath>

#include "rft/crater_profile.h"

namespace touchdown::rft {

namespace {

// The SplitMix64 finaliser (Steele, Lea & Flood 2014), as io::SplitMix64 in
// drop_tests/util/splitmix.h, which rft sits below and cannot include.
constexpr uint64_t Mix(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Draw number k of the stream `seed`, uniform in [0, 1): counter-based, so crater i's numbers do
// not depend on how many came before.
double Uniform(uint64_t seed, uint64_t k) { return double(Mix(Mix(seed) + k) >> 11) * 0x1.0p-53; }

double ExpectedCount(const CraterPopulationSpec& s, double area_m2) {
  return s.cumulative_per_m2 * (std::pow(s.min_diameter_m, -s.exponent) - std::pow(s.max_diameter_m, -s.exponent)) *
         area_m2;
}

}  // namespace

std::string CraterPopulationProblem(const CraterPopulationSpec& s, double area_m2) {
  if (!(std::isfinite(s.cumulative_per_m2) && s.cumulative_per_m2 >= 0.0)) return "c must be a number >= 0";
  if (!(std::isfinite(s.exponent) && s.exponent > 0.0)) return "the exponent b must be positive";
  if (!(s.min_diameter_m > 0.0 && s.min_diameter_m < s.max_diameter_m && std::isfinite(s.max_diameter_m)))
    return "diameters must satisfy 0 < min < max";
  if (!(s.degradation_min >= 0.0 && s.degradation_min <= s.degradation_max && s.degradation_max < 1.0))
    return "degradations must satisfy 0 <= min <= max < 1";
  const double n = ExpectedCount(s, area_m2);
  if (!(n <= kMaxExpectedCraters))
    return "expects " + std::to_string(n) + " craters, more than " + std::to_string(long(kMaxExpectedCraters));
  return "";
}

std::vector<Crater> DrawCraters(const CraterPopulationSpec& s, double x_min_m, double y_min_m, double x_max_m,
                                double y_max_m) {
  const double m = s.max_diameter_m;
  const double x0 = x_min_m - m, y0 = y_min_m - m, wx = x_max_m - x_min_m + 2.0 * m, wy = y_max_m - y_min_m + 2.0 * m;
  const double expected = ExpectedCount(s, wx * wy);
  const long count = static_cast<long>(std::floor(expected + Uniform(s.seed, 0)));
  const double a = std::pow(s.min_diameter_m, -s.exponent), b = std::pow(s.max_diameter_m, -s.exponent);
  std::vector<Crater> craters(static_cast<size_t>(count));
  for (long i = 0; i < count; ++i) {
    const uint64_t k = 1 + 4 * static_cast<uint64_t>(i);
    Crater& c = craters[i];
    c.x_m = x0 + wx * Uniform(s.seed, k);
    c.y_m = y0 + wy * Uniform(s.seed, k + 1);
    // N(>D) / N(>D_min) = u over the truncated law: D^-b = a - u (a - b).
    c.diameter_m = std::clamp(std::pow(a - Uniform(s.seed, k + 2) * (a - b), -1.0 / s.exponent), s.min_diameter_m,
                              s.max_diameter_m);
    c.degradation = s.degradation_min + (s.degradation_max - s.degradation_min) * Uniform(s.seed, k + 3);
  }
  return craters;
}

void AddCraters(const std::vector<Crater>& craters, HeightGrid* grid) {
  HeightGrid& g = *grid;
  for (const Crater& c : craters) {
    const CraterShape shape = DegradedCraterShape(c.degradation);
    const double reach = kCraterReach * 0.5 * c.diameter_m;
    const int i0 = std::max(0, static_cast<int>(std::ceil((c.x_m - reach - g.x0_m) / g.cell_m)));
    const int i1 = std::min(g.nx - 1, static_cast<int>(std::floor((c.x_m + reach - g.x0_m) / g.cell_m)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((c.y_m - reach - g.y0_m) / g.cell_m)));
    const int j1 = std::min(g.ny - 1, static_cast<int>(std::floor((c.y_m + reach - g.y0_m) / g.cell_m)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double r = std::hypot(g.x0_m + i * g.cell_m - c.x_m, g.y0_m + j * g.cell_m - c.y_m);
        if (r <= reach) g.heights_m[static_cast<size_t>(j) * g.nx + i] += CraterHeight(shape, c.diameter_m, r);
      }
  }
}

}  // namespace touchdown::rft

#include "drop_tests/scenario/soil_field.h"

#include <cmath>
#include <random>

#include "drop_tests/util/splitmix.h"

namespace touchdown::scenario {

namespace {
double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

int Pick(const std::vector<double>& probabilities, double u) {
  double cumulative = 0.0;
  int last = 0;
  for (size_t k = 0; k < probabilities.size(); ++k) {
    if (probabilities[k] <= 0.0) continue;
    cumulative += probabilities[k];
    last = static_cast<int>(k);
    if (u < cumulative) return last;
  }
  return last;  // u above a sum rounded below 1
}
}  // namespace

std::vector<SoilFieldCell> DrawSoilField(const SoilFieldSpec& f, double centre_x_m, double centre_y_m) {
  std::mt19937_64 rng(f.seed);
  const double shift_x = Uniform(rng) * f.cell_size_m, shift_y = Uniform(rng) * f.cell_size_m;
  const int n = static_cast<int>(std::ceil(2.0 * f.half_extent_m / f.cell_size_m)) + 1;
  const double x_start = centre_x_m - f.half_extent_m - shift_x, y_start = centre_y_m - f.half_extent_m - shift_y;
  std::vector<SoilFieldCell> cells;
  cells.reserve(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x0 = x_start + i * f.cell_size_m, y0 = y_start + j * f.cell_size_m;
      cells.push_back({x0, y0, x0 + f.cell_size_m, y0 + f.cell_size_m, Pick(f.probabilities, Uniform(rng))});
    }
  return cells;
}

uint64_t PerLandingFieldSeed(uint64_t study_seed, int64_t index) {
  return io::SplitMix64(io::SplitMix64(study_seed ^ 0x5011f1e1dull) ^ static_cast<uint64_t>(index));
}

}  // namespace touchdown::scenario

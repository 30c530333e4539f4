#pragma once
// A random soil-patch field: the ground around the release point cut into square cells, each
// holding one of a few soils drawn with given probabilities (e.g. loosely or closely packed bed,
// patchy at the scale of the pads). A lander scenario's `ground.soil_field`; a stability study
// gives every landing its own draw (`seed: per_landing`).
//
//   ground:
//     soil: fjs1_lp
//     soil_field: {soils: [fjs1_lp, fjs1_cp], probabilities: [0.6, 0.4], cell_size_m: 0.1,
//                  half_extent_m: 1.0, seed: 7}      # or seed: per_landing (in a study)
//
// The cells tile the square of half width half_extent_m centred below the body at release,
// shifted by a random fraction of a cell (so the pads do not sit at cell centres by design);
// outside it, the ground's default soil. A cell's soil and the shift come from the seed alone:
// the same seed gives the same field on every machine (std::mt19937_64, whose output the C++
// standard fixes, turned into uniform numbers here rather than by a library distribution).
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace touchdown::scenario {

struct SoilFieldSpec {
  std::vector<std::string> soils;    // names or files, as a soil is given anywhere
  std::vector<double> probabilities;  // of `soils`, summing to 1
  double cell_size_m = 0.1;
  double half_extent_m = 1.0;
  uint64_t seed = 0;
  bool seed_per_landing = false;  // a study draws each landing's seed (then `seed` is set per landing)
};

struct SoilFieldCell {
  double x0, y0, x1, y1;  // [m], world
  int soil = 0;           // index into SoilFieldSpec::soils
};

// The cells of one draw of the field around (centre_x, centre_y), row by row.
std::vector<SoilFieldCell> DrawSoilField(const SoilFieldSpec& field, double centre_x_m, double centre_y_m);

// The seed of landing `index` of a study seeded with `study_seed`: the same landing gets the same
// field whatever the threads, ranks or shards.
uint64_t PerLandingFieldSeed(uint64_t study_seed, int64_t index);

}  // namespace touchdown::scenario

// Loading a terrain raster (issue 63's target: a 1 km x 1 km terrain at 1 m resolution in under
// 2 s): a 1000 x 1000 ESRI ASCII grid (about 8 MB of text, written here once into the temporary
// directory, removed at exit) read and validated by io::ReadEsriAsciiGrid, and the same read plus
// the rft::HeightFieldGround built on it (the padded node array), as a scenario's ground is.
// Reports the time per load; a few Height() evaluations close each iteration so nothing is elided.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "drop_tests/formats/esri_ascii_grid.h"
#include "rft/height_field_ground.h"

namespace {

namespace fs = std::filesystem;
constexpr int kNodes = 1000;

// A rolling 1 km site (metres of relief, millimetre digits): the text a real DEM export has.
class Raster {
 public:
  Raster() : path_(fs::temp_directory_path() / ("touchdown_terrain_bench_" + std::to_string(::getpid()) + ".asc")) {
    std::ofstream out(path_);
    out << "ncols " << kNodes << "\nnrows " << kNodes << "\nxllcorner 500000\nyllcorner 4200000\ncellsize 1\n"
        << "NODATA_value -9999\n";
    char value[32];
    for (int r = 0; r < kNodes; ++r) {
      for (int c = 0; c < kNodes; ++c) {
        std::snprintf(value, sizeof value, c ? " %.3f" : "%.3f",
                      -1750.0 + 3.0 * std::sin(0.01 * c) * std::cos(0.013 * r));
        out << value;
      }
      out << '\n';
    }
  }
  ~Raster() { fs::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  fs::path path_;
};

const Raster& SharedRaster() {
  static const Raster raster;
  return raster;
}

void BM_ReadAsc1000x1000(benchmark::State& state) {
  const std::string path = SharedRaster().path();
  state.counters["file_MB"] = double(fs::file_size(path)) / 1e6;
  for (auto _ : state) {
    const touchdown::rft::HeightGrid grid = touchdown::io::ReadEsriAsciiGrid(path);
    benchmark::DoNotOptimize(grid.heights_m.data());
  }
}
BENCHMARK(BM_ReadAsc1000x1000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_ReadAscAndBuildGround1000x1000(benchmark::State& state) {
  const std::string path = SharedRaster().path();
  for (auto _ : state) {
    const touchdown::rft::HeightFieldGround ground(touchdown::io::ReadEsriAsciiGrid(path));
    benchmark::DoNotOptimize(ground.Height(500123.4, 4200567.8));
  }
}
BENCHMARK(BM_ReadAscAndBuildGround1000x1000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

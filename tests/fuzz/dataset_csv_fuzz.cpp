// Fuzz target: a dataset's drops.csv, in a directory that holds two valid trace files
// (t0.csv, traces/t1.csv) so that rows naming them get as far as reading their traces.
#include "drop_tests/dataset/dataset.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string dir = [] {
    const std::string d = touchdown::fuzz::FuzzDirectory("dataset");
    std::filesystem::create_directories(d + "/traces");
    const std::string trace = "t_s,penetration_m,force_N\n0,0,0\n0.001,0.0005,12.5\n0.002,0.0009,20\n";
    touchdown::fuzz::WriteText(d + "/t0.csv", trace);
    touchdown::fuzz::WriteText(d + "/traces/t1.csv", trace);
    return d;
  }();
  touchdown::fuzz::WriteBytes(dir + "/drops.csv", data, size);
  try {
    touchdown::dataset::ReadDataset(dir);
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

// Fuzz target: a dataset trace CSV, named by a fixed valid drops.csv; the generic CSV reader
// sees the same bytes.
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/formats/dataset_csv.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string dir = [] {
    const std::string d = touchdown::fuzz::FuzzDirectory("trace");
    touchdown::fuzz::WriteText(d + "/drops.csv",
                               "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace,tilt_deg\n"
                               "d0,flat,fjs1_lp,vacuum,1.0,1.6,9.81,trace.csv,0\n");
    return d;
  }();
  touchdown::fuzz::WriteBytes(dir + "/trace.csv", data, size);
  try {
    touchdown::io::ReadCsv(dir + "/trace.csv");
  } catch (const touchdown::InputError&) {
  }
  try {
    const touchdown::dataset::Dataset ds = touchdown::dataset::ReadDataset(dir);
    ds.drops.front().FinalPenetration();
    ds.drops.front().PeakForce();
    ds.ExtraNumber(ds.drops.front(), "tilt_deg");
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

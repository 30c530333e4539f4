// Fuzz target: sweep YAML (pads, soils and models resolved from data/ or relative paths).
#include "drop_tests/sweep/sweep_plan.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = touchdown::fuzz::WriteFuzzInput(data, size, "_sweep.yaml");
  try {
    const touchdown::sweep::SweepPlan plan = touchdown::sweep::LoadSweepPlan(path);
    // Every drop must follow from its index: look at the first and the last.
    plan.DropAt(0);
    plan.DropAt(plan.size() - 1);
    plan.DigestText();
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

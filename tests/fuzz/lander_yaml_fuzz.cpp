// Fuzz target: lander scenario YAML, loaded and turned into the model the simulation would run
// (lander specs, pads and soils resolved from data/). Nothing is integrated.
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = touchdown::fuzz::WriteFuzzInput(data, size, "_lander.yaml");
  try {
    const touchdown::scenario::LanderScenario scenario = touchdown::scenario::LoadLanderScenario(path);
    touchdown::scenario::ResolveLander(scenario);
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

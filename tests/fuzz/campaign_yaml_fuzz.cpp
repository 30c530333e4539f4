// Fuzz target: campaign scenario YAML (pads and soils resolved from data/ by name).
#include "drop_tests/scenario/campaign.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = touchdown::fuzz::WriteFuzzInput(data, size, "_campaign.yaml");
  try {
    touchdown::scenario::LoadCampaignScenario(path);
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

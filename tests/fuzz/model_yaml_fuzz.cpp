// Fuzz target: model file YAML (per-soil zeta overrides and effect terms).
#include "drop_tests/catalog.h"
#include "drop_tests/model_file.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const touchdown::rft::SoilParameters soil = touchdown::drop::LoadSoil("fjs1_lp");
  const std::string path = touchdown::fuzz::WriteFuzzInput(data, size, "_model.yaml");
  try {
    const touchdown::drop::ModelFile model = touchdown::drop::LoadModelFile(path);
    touchdown::drop::ApplyModel(model, soil);
    touchdown::drop::ModelDigestText(model);
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

// Fuzz target: model file YAML (per-soil zeta overrides and effect terms).
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/model_file.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const touchdown::rft::SoilParameters soil = touchdown::io::LoadSoil("fjs1_lp");
  const std::string path = touchdown::fuzz::WriteFuzzInput(data, size, "_model.yaml");
  try {
    const touchdown::model::ModelFile model = touchdown::model::LoadModelFile(path);
    touchdown::model::ApplyModel(model, soil);
    touchdown::model::ModelDigestText(model);
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

// Fuzz target: soil YAML. Any input must load or raise InputError; nothing else may escape.
#include "drop_tests/catalog/catalog.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = touchdown::fuzz::WriteFuzzInput(data, size, "_soil.yaml");
  try {
    touchdown::io::LoadSoil(path);
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

// Fuzz target: pad YAML. Any input must load or raise InputError; nothing else may escape.
#include "drop_tests/catalog/catalog.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = touchdown::fuzz::WriteFuzzInput(data, size, "_pad.yaml");
  try {
    touchdown::io::LoadPad(path);
  } catch (const touchdown::InputError&) {
  }
  return 0;
}

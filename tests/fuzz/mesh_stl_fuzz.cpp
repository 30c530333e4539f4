// Fuzz target: .stl pad meshes (see mesh_fuzz.h).
#include "tests/fuzz/mesh_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return touchdown::fuzz::FuzzMesh(data, size, ".stl");
}

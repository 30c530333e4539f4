#pragma once
// Shared body of the four mesh fuzz targets: the input becomes a file with the format's
// extension, is read, validated and, if accepted, turned into a pad body (mass properties,
// surface elements) as a mesh pad YAML would.
#include "footpad_geom/mesh_io.h"
#include "footpad_geom/pad_body_builder.h"
#include "rft/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

namespace touchdown::fuzz {

inline int FuzzMesh(const uint8_t* data, size_t size, const std::string& extension) {
  const std::string path = WriteFuzzInput(data, size, "_mesh" + extension);
  try {
    const geom::PreparedMesh m = geom::LoadTriangleMesh(path, {geom::LengthUnit::kMillimetre, 0.0});
    geom::PadMassModel mass;
    mass.density_kg_m3 = 1000.0;
    geom::MakePadBody(m.mesh, mass, m.mesh.vertices.front(), path);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace touchdown::fuzz

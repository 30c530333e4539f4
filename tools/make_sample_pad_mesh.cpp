// Writes the sample mesh pad data/pads/meshes/hex_pad.stl (binary STL, millimetres): a regular
// hexagonal prism, 100 mm across the corners (circumradius 50 mm, the paper's pad radius) and
// 16 mm thick (the paper's pad thickness), with its lowest face at z = 0 and its axis on z.
// It is synthetic geometry for examples, written coarse on purpose (24 triangles, as a CAD
// export would be); data/pads/hex.yaml remeshes it at load time.
//
//   build/tools/make_sample_pad_mesh [output.stl]   (default: data/pads/meshes/hex_pad.stl)
#include <cmath>
#include <exception>
#include <iostream>
#include <numbers>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "footpad_geom/mesh_io.h"

int main(int argc, char** argv) {
  using namespace touchdown;
  try {
    const std::string out = argc > 1 ? argv[1] : touchdown::io::DataDirectory() + "/pads/meshes/hex_pad.stl";
    const double circumradius_mm = 50.0, thickness_mm = 16.0;
    geom::PolygonSoup soup;
    for (double z : {0.0, thickness_mm}) {
      soup.vertices.emplace_back(0.0, 0.0, z);  // centre of the face, so the faces are fans
      for (int k = 0; k < 6; ++k) {
        const double a = k * std::numbers::pi / 3;
        soup.vertices.emplace_back(circumradius_mm * std::cos(a), circumradius_mm * std::sin(a), z);
      }
    }
    for (int k = 0; k < 6; ++k) {
      const int b0 = 1 + k, b1 = 1 + (k + 1) % 6, t0 = b0 + 7, t1 = b1 + 7;
      soup.faces.push_back({0, b1, b0});   // bottom, seen from below counter-clockwise
      soup.faces.push_back({7, t0, t1});   // top
      soup.faces.push_back({b0, b1, t1});  // side
      soup.faces.push_back({b0, t1, t0});
    }
    const geom::PreparedMesh mesh = geom::PrepareTriangleMesh(soup, "hexagonal prism");
    if (mesh.reoriented) throw std::logic_error("hexagonal prism came out inside out");
    geom::WriteTriangleMesh(mesh.mesh, out);  // coordinates are already in mm
    std::cout << "wrote " << out << " (" << mesh.mesh.triangles.size() << " triangles, mm)\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

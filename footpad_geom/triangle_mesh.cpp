#include "footpad_geom/triangle_mesh.h"

#include "rft/input_error.h"

namespace touchdown::geom {

PolygonSoup ToPolygonSoup(const TriangleMesh& mesh) {
  PolygonSoup soup;
  soup.vertices = mesh.vertices;
  soup.faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) soup.faces.push_back({t[0], t[1], t[2]});
  return soup;
}

LengthUnit ParseLengthUnit(const std::string& text, const std::string& file, const std::string& field) {
  if (text == "mm") return LengthUnit::kMillimetre;
  if (text == "m") return LengthUnit::kMetre;
  throw MakeInputError(file, field, "unknown length unit '" + text + "' (mm, m)");
}

double MetresPerUnit(LengthUnit unit) { return unit == LengthUnit::kMillimetre ? 1e-3 : 1.0; }

}  // namespace touchdown::geom

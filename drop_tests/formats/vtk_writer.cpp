#include "drop_tests/formats/vtk_writer.h"

#include <charconv>
#include <stdexcept>

namespace touchdown::io {

namespace {
// The shortest decimal that reads back as the same double (std::to_chars): exact, and shorter and
// faster than 17 digits. Negative zero (-0 / A of an element without force, a product with a zero
// scale) is written as 0: the same value, and ParaView's readers and users see no "-0".
struct Exact {
  double v;
};
std::ostream& operator<<(std::ostream& out, Exact x) {
  char text[32];
  const double v = x.v == 0.0 ? 0.0 : x.v;
  const std::to_chars_result r = std::to_chars(text, text + sizeof text, v);
  return out.write(text, r.ptr - text);
}

void CheckPiece(const VtkPolyData& p) {
  const auto check_cells = [&](const std::vector<std::vector<int>>& cells) {
    for (const std::vector<int>& cell : cells)
      for (int i : cell)
        if (i < 0 || i >= static_cast<int>(p.points.size()))
          throw std::logic_error("WriteVtp: point index " + std::to_string(i) + " out of range");
  };
  check_cells(p.lines);
  check_cells(p.polygons);
  const auto check_fields = [](const std::vector<VtkField>& fields, size_t count) {
    for (const VtkField& f : fields)
      if (f.components < 1 || f.values.size() != count * static_cast<size_t>(f.components))
        throw std::logic_error("WriteVtp: field " + f.name + " has " + std::to_string(f.values.size()) +
                               " values for " + std::to_string(count) + " entries");
  };
  check_fields(p.cell_fields, static_cast<size_t>(p.cell_count()));
  check_fields(p.point_fields, p.points.size());
}

void WriteField(const VtkField& f, std::ostream& out) {
  out << "        <DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfComponents=\"" << f.components
      << "\" format=\"ascii\">\n";
  for (size_t i = 0; i < f.values.size(); ++i)
    out << Exact{f.values[i]} << ((i + 1) % f.components == 0 ? '\n' : ' ');
  out << "        </DataArray>\n";
}

void WriteFields(const char* tag, const std::vector<VtkField>& fields, std::ostream& out) {
  out << "      <" << tag;
  if (!fields.empty()) out << " Scalars=\"" << fields.front().name << "\"";
  out << ">\n";
  for (const VtkField& f : fields) WriteField(f, out);
  out << "      </" << tag << ">\n";
}

// VTK's cell arrays: the point indices of all cells, and the end of each cell in them.
void WriteCells(const char* tag, const std::vector<std::vector<int>>& cells, std::ostream& out) {
  out << "      <" << tag << ">\n        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const std::vector<int>& cell : cells)
    for (size_t i = 0; i < cell.size(); ++i) out << cell[i] << (i + 1 == cell.size() ? '\n' : ' ');
  out << "        </DataArray>\n        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  int end = 0;
  for (const std::vector<int>& cell : cells) {
    end += static_cast<int>(cell.size());
    out << end << '\n';
  }
  out << "        </DataArray>\n      </" << tag << ">\n";
}

void WritePiece(const VtkPolyData& p, std::ostream& out) {
  out << "    <Piece NumberOfPoints=\"" << p.points.size() << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << p.lines.size()
      << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << p.polygons.size() << "\">\n";
  WriteFields("PointData", p.point_fields, out);
  WriteFields("CellData", p.cell_fields, out);
  out << "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (const Eigen::Vector3d& x : p.points) out << Exact{x.x()} << ' ' << Exact{x.y()} << ' ' << Exact{x.z()} << '\n';
  out << "        </DataArray>\n      </Points>\n";
  WriteCells("Lines", p.lines, out);
  WriteCells("Polys", p.polygons, out);
  out << "    </Piece>\n";
}
}  // namespace

void VtkPolyData::AddCellField(std::string name, std::vector<double> values, int components) {
  cell_fields.push_back({std::move(name), components, std::move(values)});
}

void VtkPolyData::AddPointField(std::string name, std::vector<double> values, int components) {
  point_fields.push_back({std::move(name), components, std::move(values)});
}

void WriteVtp(const std::vector<VtkPolyData>& pieces, std::ostream& out) {
  for (const VtkPolyData& p : pieces) CheckPiece(p);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <PolyData>\n";
  for (const VtkPolyData& p : pieces) WritePiece(p, out);
  out << "  </PolyData>\n</VTKFile>\n";
}

void WritePvd(const std::vector<VtkCollectionEntry>& entries, std::ostream& out) {
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
  for (const VtkCollectionEntry& e : entries)
    out << "    <DataSet timestep=\"" << Exact{e.time_s} << "\" group=\"\" part=\"" << e.part << "\" name=\"" << e.name
        << "\" file=\"" << e.file << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
}

}  // namespace touchdown::io

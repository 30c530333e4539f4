#pragma once
// VTK XML output for ParaView, written directly rather than through libvtk (docs/paraview.md says
// why): surfaces and lines as PolyData (.vtp: points, polygons, lines, cell and point fields) and a
// time series as a collection (.pvd) that lists each time step's files.
//
// Data are written as ASCII, each double as the shortest decimal that reads back as the same double
// (std::to_chars), so every number is exact and the files are the same byte for byte on every run
// (golden outputs compare them). Only formatting happens here: where the files go, and that they
// never overwrite a user's, is output_path.h's.
#include <Eigen/Core>
#include <ostream>
#include <string>
#include <vector>

namespace touchdown::io {

// A named field with `components` values per cell (or point), cell after cell.
struct VtkField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

// One piece of PolyData in world coordinates [m]. Its cells are VTK's, lines first, then polygons
// (the order in which VTK numbers a PolyData's cells): cell fields hold one entry per cell in that
// order.
struct VtkPolyData {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> lines;     // polylines: point indices
  std::vector<std::vector<int>> polygons;  // point indices, counter-clockwise seen from outside
  std::vector<VtkField> cell_fields;
  std::vector<VtkField> point_fields;

  int cell_count() const { return static_cast<int>(lines.size() + polygons.size()); }
  // Appends a cell field (values: one per cell, or `components` per cell).
  void AddCellField(std::string name, std::vector<double> values, int components = 1);
  // Appends a point field (values: one per point, or `components` per point).
  void AddPointField(std::string name, std::vector<double> values, int components = 1);
};

// Writes `pieces` as one PolyData file, a <Piece> each. Every piece must carry the same fields
// (ParaView merges pieces). A field of the wrong size or a point index out of range is a bug:
// std::logic_error.
void WriteVtp(const std::vector<VtkPolyData>& pieces, std::ostream& out);

// One data set of a collection: the file (relative to the .pvd), its time [s] and its part (the
// block it becomes in ParaView, named `name`). A file may appear at several times (a static part).
struct VtkCollectionEntry {
  double time_s = 0.0;
  int part = 0;
  std::string name;
  std::string file;
};
void WritePvd(const std::vector<VtkCollectionEntry>& entries, std::ostream& out);

}  // namespace touchdown::io

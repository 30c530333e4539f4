#pragma once
// Bounded readers for the mesh formats whose CGAL readers trust the file's counts: OFF
// (CGAL resizes to the header's vertex and face counts and to each face's declared size before
// reading a single value) and PLY (CGAL resizes to each list's declared length). A 20-byte file
// declaring a billion vertices would exhaust memory there. These readers only keep what they
// have actually read, so memory grows with the file, never with a number written in it, and
// every count is checked against what follows.
//
// Supported: OFF, COFF, NOFF, CNOFF, STOFF, ... in ASCII (the first three numbers of a vertex
// record are its coordinates; normals, colours and texture coordinates after them are
// skipped) and plain `OFF BINARY` (big-endian, as CGAL writes it); PLY in ascii,
// binary_little_endian and binary_big_endian with any element and property layout (vertex x, y,
// z and a face list `vertex_indices` or `vertex_index` are used). 4OFF, nOFF and SKEL are
// refused as unsupported.
//
// Also: binary STL files are scanned for non-finite coordinates, which CGAL's STL reader
// would merge into other points (its point map cannot order NaN).
//
// Every problem throws InputError "<path>: could not be read as <format> (<reason>)".
#include <string>

#include "footpad_geom/triangle_mesh.h"

namespace touchdown::geom {

// Coordinates in the file's unit; indices as written (checked later by PrepareTriangleMesh).
PolygonSoup ReadOffSoup(const std::string& path);
PolygonSoup ReadPlySoup(const std::string& path);
// Throws InputError if `path` is a binary STL with a non-finite vertex coordinate.
void CheckBinaryStlCoordinates(const std::string& path);

}  // namespace touchdown::geom

#include "footpad_geom/mesh_readers.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>
#include <utility>
#include <vector>

#include "rft/input_error.h"
#include "rft/input_file.h"

namespace touchdown::geom {

namespace {

[[noreturn]] void Fail(const std::string& path, const char* format, const std::string& why) {
  throw MakeInputError(path, "", std::string("could not be read as ") + format + " (" + why + ")");
}

std::string Slurp(const std::string& path, const char*) { return ReadInputFile(path, "mesh file"); }

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && IsSpace(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !IsSpace(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// A whole token as a double (a leading '+' allowed); false on anything else.
bool ParseDouble(std::string_view t, double* value) {
  if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), *value);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

// A whole token as an integer in [lo, hi] ("3" or "3.0").
bool ParseInteger(std::string_view t, long long lo, long long hi, long long* value) {
  if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), *value);
  if (r.ec == std::errc() && r.ptr == t.data() + t.size()) return *value >= lo && *value <= hi;
  double d = 0.0;
  if (!ParseDouble(t, &d) || d != std::floor(d) || !(d >= static_cast<double>(lo) && d <= static_cast<double>(hi)))
    return false;
  *value = static_cast<long long>(d);
  return true;
}

std::string Quoted(std::string_view t) {
  constexpr size_t kMax = 24;
  std::string s(t.substr(0, kMax));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return "'" + s + (t.size() > kMax ? "...'" : "'");
}

// Lines of a text with '#' comments removed; blank lines skipped.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool Next(std::string_view* line) {
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view l = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++number_;
      if (const size_t hash = l.find('#'); hash != std::string_view::npos) l = l.substr(0, hash);
      bool blank = true;
      for (char c : l) blank = blank && IsSpace(c);
      if (!blank) {
        *line = l;
        return true;
      }
    }
    return false;
  }
  int number() const { return number_; }
  // Offset just after the current line.
  size_t offset() const { return pos_ > text_.size() ? text_.size() : pos_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int number_ = 0;
};

std::string At(int line) { return "line " + std::to_string(line) + ": "; }

// Big-endian / little-endian raw reads with bounds.
class ByteReader {
 public:
  ByteReader(std::string_view bytes, bool big_endian) : bytes_(bytes), big_(big_endian) {}
  size_t remaining() const { return bytes_.size() - pos_; }
  bool Raw(void* out, size_t n) {
    if (remaining() < n) return false;
    unsigned char buffer[8];
    std::memcpy(buffer, bytes_.data() + pos_, n);
    pos_ += n;
    constexpr bool host_big = std::endian::native == std::endian::big;
    if (big_ != host_big)
      for (size_t i = 0; i < n / 2; ++i) std::swap(buffer[i], buffer[n - 1 - i]);
    std::memcpy(out, buffer, n);
    return true;
  }

 private:
  std::string_view bytes_;
  size_t pos_ = 0;
  bool big_;
};

// ---- OFF ----------------------------------------------------------------------------------

PolygonSoup ReadBinaryOff(const std::string& path, std::string_view bytes) {
  ByteReader in(bytes, /*big_endian=*/true);
  auto integer = [&](const char* what) {
    std::int32_t v = 0;
    if (!in.Raw(&v, 4)) Fail(path, "off", std::string("binary file ends in ") + what);
    return v;
  };
  const std::int32_t nv = integer("the header"), nf = integer("the header");
  integer("the header");  // edges, unused
  if (nv < 0 || nf < 0) Fail(path, "off", "negative vertex or face count");
  if (static_cast<std::uint64_t>(nv) * 12 > in.remaining())
    Fail(path, "off", "declares " + std::to_string(nv) + " vertices but the file is too short for them");
  PolygonSoup soup;
  for (std::int32_t i = 0; i < nv; ++i) {
    float xyz[3] = {0.0f, 0.0f, 0.0f};  // the size check above guarantees the bytes
    for (float& c : xyz) in.Raw(&c, 4);
    soup.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  for (std::int32_t f = 0; f < nf; ++f) {
    const std::int32_t n = integer("a face");
    if (n < 0 || static_cast<std::uint64_t>(n) * 4 > in.remaining())
      Fail(path, "off", "face " + std::to_string(f) + " declares " + std::to_string(n) + " vertices");
    std::vector<int> face;
    for (std::int32_t k = 0; k < n; ++k) face.push_back(integer("a face"));
    soup.faces.push_back(std::move(face));
    std::int32_t colours = 0;
    if (in.remaining() == 0 && f == nf - 1) break;  // the last colour count may be left out
    if (!in.Raw(&colours, 4) || colours < 0 || colours > 4 || static_cast<size_t>(colours) * 4 > in.remaining())
      Fail(path, "off", "face " + std::to_string(f) + " has a bad colour count");
    for (std::int32_t k = 0; k < colours; ++k) {
      float c;
      in.Raw(&c, 4);
    }
  }
  return soup;
}

}  // namespace

PolygonSoup ReadOffSoup(const std::string& path) {
  const std::string text = Slurp(path, "off");
  LineReader lines(text);
  std::string_view line;
  if (!lines.Next(&line)) Fail(path, "off", "empty file");
  std::vector<std::string_view> header = Tokens(line);
  std::string_view keyword = header.front();
  // [ST][C][N]OFF; the homogeneous (4), n-dimensional (n) and SKEL variants are not pads.
  std::string_view k = keyword;
  if (k.starts_with("ST")) k.remove_prefix(2);
  if (k.starts_with("C")) k.remove_prefix(1);
  if (k.starts_with("N")) k.remove_prefix(1);
  if (k != "OFF") {
    if (keyword.find("OFF") != std::string_view::npos || keyword.find("SKEL") != std::string_view::npos)
      Fail(path, "off", "unsupported OFF variant " + Quoted(keyword) + " (OFF, COFF, NOFF, STOFF)");
    Fail(path, "off", At(lines.number()) + "no OFF header, got " + Quoted(keyword));
  }
  header.erase(header.begin());
  if (!header.empty() && header.front() == "BINARY") {
    if (keyword != "OFF") Fail(path, "off", "binary " + Quoted(keyword) + " is not supported (plain OFF only)");
    // The binary part starts after the header line.
    return ReadBinaryOff(path, std::string_view(text).substr(lines.offset()));
  }
  if (header.empty()) {  // the counts on their own line
    if (!lines.Next(&line)) Fail(path, "off", "file ends before the vertex and face counts");
    header = Tokens(line);
  }
  long long nv = 0, nf = 0;
  if (header.size() < 2 || !ParseInteger(header[0], 0, INT_MAX, &nv) || !ParseInteger(header[1], 0, INT_MAX, &nf))
    Fail(path, "off", At(lines.number()) + "expected the vertex and face counts");

  PolygonSoup soup;
  for (long long i = 0; i < nv; ++i) {
    if (!lines.Next(&line))
      Fail(path, "off", "file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    const std::vector<std::string_view> t = Tokens(line);
    double xyz[3];
    if (t.size() < 3) Fail(path, "off", At(lines.number()) + "a vertex needs three coordinates");
    for (int c = 0; c < 3; ++c)
      if (!ParseDouble(t[c], &xyz[c])) Fail(path, "off", At(lines.number()) + "not a number: " + Quoted(t[c]));
    soup.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  for (long long f = 0; f < nf; ++f) {
    if (!lines.Next(&line))
      Fail(path, "off", "file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const std::vector<std::string_view> t = Tokens(line);
    long long n = 0;
    if (!ParseInteger(t[0], 0, static_cast<long long>(t.size()) - 1, &n))
      Fail(path, "off", At(lines.number()) + "a face must start with its number of vertices, followed by them");
    std::vector<int> face;
    for (long long j = 1; j <= n; ++j) {
      long long index = 0;
      if (!ParseInteger(t[j], INT_MIN, INT_MAX, &index))
        Fail(path, "off", At(lines.number()) + "not a vertex index: " + Quoted(t[j]));
      face.push_back(static_cast<int>(index));
    }
    soup.faces.push_back(std::move(face));
  }
  return soup;
}

// ---- PLY ----------------------------------------------------------------------------------

namespace {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

bool ParsePlyType(std::string_view name, PlyType* type) {
  static const struct {
    const char* a;
    const char* b;
    PlyType t;
  } kTypes[] = {{"char", "int8", PlyType::kInt8},       {"uchar", "uint8", PlyType::kUint8},
                {"short", "int16", PlyType::kInt16},    {"ushort", "uint16", PlyType::kUint16},
                {"int", "int32", PlyType::kInt32},      {"uint", "uint32", PlyType::kUint32},
                {"float", "float32", PlyType::kFloat32}, {"double", "float64", PlyType::kFloat64}};
  for (const auto& e : kTypes)
    if (name == e.a || name == e.b) {
      *type = e.t;
      return true;
    }
  return false;
}

size_t PlySize(PlyType t) {
  switch (t) {
    case PlyType::kInt8: case PlyType::kUint8: return 1;
    case PlyType::kInt16: case PlyType::kUint16: return 2;
    case PlyType::kInt32: case PlyType::kUint32: case PlyType::kFloat32: return 4;
    case PlyType::kFloat64: return 8;
  }
  return 1;
}

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType count_type = PlyType::kUint8;
  PlyType type = PlyType::kFloat32;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

// One value source for the body: ASCII tokens or binary numbers.
class PlyValues {
 public:
  PlyValues(const std::string& path, std::string_view body, int format)
      : path_(path), body_(body), format_(format), bytes_(body, format == 2) {}
  size_t remaining() const { return format_ == 0 ? body_.size() - pos_ : bytes_.remaining(); }
  bool ascii() const { return format_ == 0; }

  double Next(PlyType type) {
    if (format_ == 0) {
      while (pos_ < body_.size() && IsSpace(body_[pos_])) ++pos_;
      const size_t start = pos_;
      while (pos_ < body_.size() && !IsSpace(body_[pos_])) ++pos_;
      if (pos_ == start) Fail(path_, "ply", "file ends inside an element");
      double v = 0.0;
      const std::string_view token = body_.substr(start, pos_ - start);
      if (!ParseDouble(token, &v)) Fail(path_, "ply", "not a number: " + Quoted(token));
      return v;
    }
    auto read = [&](auto value) {
      if (!bytes_.Raw(&value, sizeof value)) Fail(path_, "ply", "binary file ends inside an element");
      return static_cast<double>(value);
    };
    switch (type) {
      case PlyType::kInt8: return read(std::int8_t{});
      case PlyType::kUint8: return read(std::uint8_t{});
      case PlyType::kInt16: return read(std::int16_t{});
      case PlyType::kUint16: return read(std::uint16_t{});
      case PlyType::kInt32: return read(std::int32_t{});
      case PlyType::kUint32: return read(std::uint32_t{});
      case PlyType::kFloat32: return read(float{});
      case PlyType::kFloat64: return read(double{});
    }
    return 0.0;
  }

 private:
  const std::string& path_;
  std::string_view body_;
  int format_;  // 0 ascii, 1 little endian, 2 big endian
  size_t pos_ = 0;
  ByteReader bytes_;
};


// The ASCII header of a PLY file, up to end_header: its elements with their properties, the
// format of the body, and where the body starts.
struct PlyHeader {
  std::vector<PlyElement> elements;
  int format = -1;  // 0 ascii, 1 binary little endian, 2 binary big endian
  size_t body_offset = 0;
};

PlyHeader ReadPlyHeader(const std::string& path, const std::string& text) {
  std::vector<PlyElement> elements;
  int format = -1;
  size_t pos = 0, line_number = 0;
  bool ended = false;
  while (!ended) {
    if (pos >= text.size()) Fail(path, "ply", "no end_header");
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view line = std::string_view(text).substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    const std::vector<std::string_view> t = Tokens(line);
    const std::string where = At(static_cast<int>(line_number));
    if (line_number == 1) {
      if (t.size() != 1 || t[0] != "ply") Fail(path, "ply", "the first line must be 'ply'");
      continue;
    }
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format") {
      if (t.size() < 2) Fail(path, "ply", where + "format needs a name");
      if (t[1] == "ascii") format = 0;
      else if (t[1] == "binary_little_endian") format = 1;
      else if (t[1] == "binary_big_endian") format = 2;
      else Fail(path, "ply", where + "unknown format " + Quoted(t[1]));
    } else if (t[0] == "element") {
      long long count = 0;
      if (t.size() != 3 || !ParseInteger(t[2], 0, LLONG_MAX, &count))
        Fail(path, "ply", where + "expected 'element <name> <count>'");
      elements.push_back({std::string(t[1]), static_cast<std::uint64_t>(count), {}});
    } else if (t[0] == "property") {
      if (elements.empty()) Fail(path, "ply", where + "a property before any element");
      PlyProperty p;
      if (t.size() == 5 && t[1] == "list") {
        p.list = true;
        if (!ParsePlyType(t[2], &p.count_type) || !ParsePlyType(t[3], &p.type))
          Fail(path, "ply", where + "unknown property type");
        if (p.count_type == PlyType::kFloat32 || p.count_type == PlyType::kFloat64)
          Fail(path, "ply", where + "a list length must have an integer type");
        p.name = std::string(t[4]);
      } else if (t.size() == 3 && ParsePlyType(t[1], &p.type)) {
        p.name = std::string(t[2]);
      } else {
        Fail(path, "ply", where + "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      }
      elements.back().properties.push_back(std::move(p));
    } else if (t[0] == "end_header") {
      ended = true;
    } else {
      Fail(path, "ply", where + "unknown header line " + Quoted(t[0]));
    }
  }
  if (format < 0) Fail(path, "ply", "no format line");
  if (pos > text.size()) pos = text.size();
  return {std::move(elements), format, pos};

}

// Reads the items of one element: vertices (x, y, z) and faces (vertex_indices) go into `soup`,
// every other element and property is read past.
void ReadPlyElement(const std::string& path, const PlyElement& e, PlyValues& values, PolygonSoup& soup) {
  // Every item takes at least one byte (binary) or one character (ASCII): a count larger
  // than what is left cannot be right, and looping over it could take forever.
  if (e.count > values.remaining())
    Fail(path, "ply", "element '" + e.name + "' declares " + std::to_string(e.count) +
                          " items but the file is too short for them");
  const bool vertex = e.name == "vertex", face = e.name == "face";
  int x = -1, y = -1, z = -1, indices = -1;
  for (size_t i = 0; i < e.properties.size(); ++i) {
    const PlyProperty& p = e.properties[i];
    if (vertex && !p.list && p.name == "x") x = static_cast<int>(i);
    if (vertex && !p.list && p.name == "y") y = static_cast<int>(i);
    if (vertex && !p.list && p.name == "z") z = static_cast<int>(i);
    if (face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) indices = static_cast<int>(i);
  }
  if (vertex && (x < 0 || y < 0 || z < 0)) Fail(path, "ply", "the vertex element needs properties x, y and z");
  if (face && indices < 0) Fail(path, "ply", "the face element needs a list property vertex_indices");
  for (std::uint64_t item = 0; item < e.count; ++item) {
    double xyz[3] = {0, 0, 0};
    std::vector<int> polygon;
    for (size_t i = 0; i < e.properties.size(); ++i) {
      const PlyProperty& p = e.properties[i];
      if (!p.list) {
        const double v = values.Next(p.type);
        if (static_cast<int>(i) == x) xyz[0] = v;
        if (static_cast<int>(i) == y) xyz[1] = v;
        if (static_cast<int>(i) == z) xyz[2] = v;
        continue;
      }
      const double n = values.Next(p.count_type);
      const size_t least = values.ascii() ? 1 : PlySize(p.type);
      if (!(n >= 0.0 && n == std::floor(n) && n <= static_cast<double>(values.remaining() / least)))
        Fail(path, "ply", "element '" + e.name + "' item " + std::to_string(item) + ": bad list length");
      for (size_t k = 0; k < static_cast<size_t>(n); ++k) {
        const double v = values.Next(p.type);
        if (static_cast<int>(i) != indices) continue;
        if (!(v == std::floor(v) && v >= static_cast<double>(INT_MIN) && v <= static_cast<double>(INT_MAX)))
          Fail(path, "ply", "face " + std::to_string(item) + ": not a vertex index");
        polygon.push_back(static_cast<int>(v));
      }
    }
    if (vertex) soup.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    if (face) soup.faces.push_back(std::move(polygon));
  }
}

}  // namespace

PolygonSoup ReadPlySoup(const std::string& path) {
  const std::string text = Slurp(path, "ply");
  const PlyHeader header = ReadPlyHeader(path, text);
  PlyValues values(path, std::string_view(text).substr(header.body_offset), header.format);
  PolygonSoup soup;
  bool have_vertices = false, have_faces = false;
  for (const PlyElement& e : header.elements) {
    if (e.properties.empty()) continue;  // nothing to read
    ReadPlyElement(path, e, values, soup);
    have_vertices = have_vertices || e.name == "vertex";
    have_faces = have_faces || e.name == "face";
  }
  if (!have_vertices) Fail(path, "ply", "no vertex element");
  if (!have_faces) Fail(path, "ply", "no face element");
  return soup;
}

// ---- STL ----------------------------------------------------------------------------------

void CheckBinaryStlCoordinates(const std::string& path) {
  const std::string bytes = Slurp(path, "stl");
  if (bytes.size() < 84) return;
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);  // little endian (the format's)
  if constexpr (std::endian::native == std::endian::big) n = __builtin_bswap32(n);
  const bool exact = bytes.size() == 84 + 50 * static_cast<std::uint64_t>(n);
  // An ASCII STL starts with "solid" (after blanks); a binary one may too, but then its size
  // matches its facet count.
  size_t first = 0;
  while (first < bytes.size() && IsSpace(bytes[first])) ++first;
  if (!exact && bytes.compare(first, 5, "solid") == 0) return;
  const std::uint64_t facets = std::min<std::uint64_t>(n, (bytes.size() - 84) / 50);
  for (std::uint64_t f = 0; f < facets; ++f)
    for (int c = 0; c < 9; ++c) {  // three vertices after the normal
      float v;
      std::memcpy(&v, bytes.data() + 84 + 50 * f + 12 + 4 * c, 4);
      if (!std::isfinite(v))
        Fail(path, "stl", "facet " + std::to_string(f) + " has a non-finite vertex coordinate");
    }
}

}  // namespace touchdown::geom

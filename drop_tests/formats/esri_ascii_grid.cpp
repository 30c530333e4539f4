#include "drop_tests/formats/esri_ascii_grid.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string_view>

#include "rft/input_file.h"

namespace touchdown::io {

namespace {

std::string Lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Splits the text into lines and each line into whitespace-separated tokens, without copying.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  // The next line that is not blank, with its 1-based number; false at the end.
  bool Next(std::string_view* line, int* number) {
    while (pos_ < text_.size()) {
      const size_t end = std::min(text_.find('\n', pos_), text_.size());
      *line = text_.substr(pos_, end - pos_);
      *number = ++line_;
      pos_ = end + 1;
      if (std::any_of(line->begin(), line->end(), [](char c) { return !IsSpace(c); })) return true;
    }
    return false;
  }
  // Puts back the line just read (the first data line, met while looking for header keys).
  void Unread(std::string_view line) {
    pos_ = static_cast<size_t>(line.data() - text_.data());
    --line_;
  }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int line_ = 0;
};

// The next token of `line` from `*pos`, or an empty view at the end.
std::string_view NextToken(std::string_view line, size_t* pos) {
  size_t b = *pos;
  while (b < line.size() && IsSpace(line[b])) ++b;
  size_t e = b;
  while (e < line.size() && !IsSpace(line[e])) ++e;
  *pos = e;
  return line.substr(b, e - b);
}

bool ParseDouble(std::string_view token, double* value) {
  const char* begin = token.data();
  const char* end = token.data() + token.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars rejects a leading '+'
  const auto r = std::from_chars(begin, end, *value);
  return r.ec == std::errc() && r.ptr == end && begin != end;
}

std::string Quoted(std::string_view s) { return "'" + std::string(s.substr(0, 40)) + (s.size() > 40 ? "...'" : "'"); }

enum Key { kNcols, kNrows, kXll, kYll, kCellsize, kNodata, kKeyCount };

struct Header {
  std::array<bool, kKeyCount> seen{};
  long ncols = 0, nrows = 0;
  double xll = 0.0, yll = 0.0, cell = 0.0, nodata = 0.0;
  bool x_corner = true, y_corner = true;
};

// The header lines (a key and a value each), up to the first line that starts with a number.
Header ReadHeader(const std::string& path, LineReader& lines) {
  Header h;
  std::string_view line;
  int number = 0;
  while (lines.Next(&line, &number)) {
    size_t pos = 0;
    const std::string_view key_token = NextToken(line, &pos);
    if (!std::isalpha(static_cast<unsigned char>(key_token.front()))) {
      lines.Unread(line);
      break;
    }
    const std::string key = Lower(key_token);
    const std::string where = "line " + std::to_string(number);
    Key k;
    if (key == "ncols")
      k = kNcols;
    else if (key == "nrows")
      k = kNrows;
    else if (key == "xllcorner" || key == "xllcenter")
      k = kXll, h.x_corner = key == "xllcorner";
    else if (key == "yllcorner" || key == "yllcenter")
      k = kYll, h.y_corner = key == "yllcorner";
    else if (key == "cellsize")
      k = kCellsize;
    else if (key == "nodata_value")
      k = kNodata;
    else
      throw MakeInputError(path, where,
                           "unknown header key " + Quoted(key_token) +
                               " (expected ncols, nrows, xllcorner or xllcenter, yllcorner or "
                               "yllcenter, cellsize, NODATA_value; non-square cells are not supported)");
    if (h.seen[k]) throw MakeInputError(path, where, "header key " + Quoted(key_token) + " given twice");
    h.seen[k] = true;
    const std::string_view value_token = NextToken(line, &pos);
    if (!NextToken(line, &pos).empty())
      throw MakeInputError(path, where, "header key " + Quoted(key_token) + " takes one value");
    double value = 0.0;
    if (!ParseDouble(value_token, &value) || !std::isfinite(value))
      throw MakeInputError(path, where, Quoted(key_token) + " must be a finite number, got " + Quoted(value_token));
    switch (k) {
      case kNcols:
      case kNrows:
        if (value < 1.0 || value != std::floor(value) || value > 1e6)
          throw MakeInputError(
              path, where, Quoted(key_token) + " must be a whole number from 1 to 1000000, got " + Quoted(value_token));
        (k == kNcols ? h.ncols : h.nrows) = static_cast<long>(value);
        break;
      case kXll:
        h.xll = value;
        break;
      case kYll:
        h.yll = value;
        break;
      case kCellsize:
        if (!(value > 0.0)) throw MakeInputError(path, where, "cellsize must be positive, got " + Quoted(value_token));
        h.cell = value;
        break;
      default:
        h.nodata = value;
        break;
    }
  }
  static constexpr std::array<const char*, kKeyCount> kNames{
      "ncols", "nrows", "xllcorner (or xllcenter)", "yllcorner (or yllcenter)", "cellsize", ""};
  for (int k = 0; k < kNodata; ++k)
    if (!h.seen[k]) throw MakeInputError(path, "header", std::string("missing key ") + kNames[k]);
  return h;
}

// The node indices [lo, hi] of one axis inside [min, max]: nodes at first + i cell, i < n. A node
// on the window's edge counts as inside despite rounding (1e-9 of a cell).
void AxisRange(const std::string& path, const char* axis, double first, double cell, long n, double min, double max,
               long* lo, long* hi) {
  const double last = first + (n - 1) * cell, slack = 1e-9 * cell;
  if (!(min < max))
    throw MakeInputError(path, "window",
                         std::string(axis) + " range is empty: " + std::to_string(min) + " to " + std::to_string(max));
  if (min < first - slack || max > last + slack)
    throw MakeInputError(path, "window",
                         std::string(axis) + " range " + std::to_string(min) + " to " + std::to_string(max) +
                             " reaches outside the raster's cell centres, " + std::to_string(first) + " to " +
                             std::to_string(last));
  *lo = std::max(0L, static_cast<long>(std::ceil((min - first) / cell - 1e-9)));
  *hi = std::min(n - 1, static_cast<long>(std::floor((max - first) / cell + 1e-9)));
}

}  // namespace

rft::HeightGrid ReadEsriAsciiGrid(const std::string& path, const std::optional<RasterWindow>& window) {
  const std::string text = ReadInputFile(path, "terrain file");
  LineReader lines(text);
  const Header h = ReadHeader(path, lines);
  // Node (column c, row r from the north) lies at (x_first + c cell, y_first + (nrows - 1 - r) cell).
  const double x_first = h.x_corner ? h.xll + 0.5 * h.cell : h.xll;
  const double y_first = h.y_corner ? h.yll + 0.5 * h.cell : h.yll;
  long i_lo = 0, i_hi = h.ncols - 1, j_lo = 0, j_hi = h.nrows - 1;  // j counts from the south
  if (window) {
    AxisRange(path, "x", x_first, h.cell, h.ncols, window->x_min_m, window->x_max_m, &i_lo, &i_hi);
    AxisRange(path, "y", y_first, h.cell, h.nrows, window->y_min_m, window->y_max_m, &j_lo, &j_hi);
  }
  const long nx = i_hi - i_lo + 1, ny = j_hi - j_lo + 1;
  const std::string kept = std::to_string(nx) + " x " + std::to_string(ny) + " nodes";
  if (nx < 3 || ny < 3)
    throw MakeInputError(path, window ? "window" : "header",
                         "keeps " + kept + "; the interpolation needs at least 3 x 3");
  if (nx * ny > kMaxRasterWindowNodes)
    throw MakeInputError(
        path, window ? "window" : "header",
        "keeps " + kept + ", more than " + std::to_string(kMaxRasterWindowNodes) + " (select a smaller window)");

  rft::HeightGrid grid{.x0_m = x_first + i_lo * h.cell,
                       .y0_m = y_first + j_lo * h.cell,
                       .cell_m = h.cell,
                       .nx = static_cast<int>(nx),
                       .ny = static_cast<int>(ny),
                       .heights_m = std::vector<double>(static_cast<size_t>(nx * ny))};
  std::string_view line;
  int number = 0;
  for (long r = 0; r < h.nrows; ++r) {
    const std::string row_name = "row " + std::to_string(r + 1);
    if (!lines.Next(&line, &number))
      throw MakeInputError(
          path, row_name,
          "missing: the file ends after " + std::to_string(r) + " of " + std::to_string(h.nrows) + " rows");
    const long j = h.nrows - 1 - r;
    const bool row_kept = j >= j_lo && j <= j_hi;
    double* out = row_kept ? grid.heights_m.data() + (j - j_lo) * nx : nullptr;
    size_t pos = 0;
    long c = 0;
    for (std::string_view token = NextToken(line, &pos); !token.empty(); token = NextToken(line, &pos), ++c) {
      const auto where = [&] {
        return "line " + std::to_string(number) + " (" + row_name + ", column " + std::to_string(c + 1) + ")";
      };
      if (c >= h.ncols)
        throw MakeInputError(path, "line " + std::to_string(number) + " (" + row_name + ")",
                             "has more than ncols = " + std::to_string(h.ncols) + " values");
      double value = 0.0;
      if (!ParseDouble(token, &value) || !std::isfinite(value))
        throw MakeInputError(path, where(), "not a finite number: " + Quoted(token));
      if (!row_kept || c < i_lo || c > i_hi) continue;
      if (h.seen[kNodata] && value == h.nodata)
        throw MakeInputError(path, where(),
                             std::string("NODATA inside the ") + (window ? "window" : "raster") +
                                 " (a terrain needs every height it interpolates)");
      out[c - i_lo] = value;
    }
    if (c != h.ncols)
      throw MakeInputError(path, "line " + std::to_string(number) + " (" + row_name + ")",
                           "has " + std::to_string(c) + " values, expected ncols = " + std::to_string(h.ncols));
  }
  if (lines.Next(&line, &number))
    throw MakeInputError(path, "line " + std::to_string(number),
                         "more data after the " + std::to_string(h.nrows) + " rows nrows gives");
  return grid;
}

}  // namespace touchdown::io

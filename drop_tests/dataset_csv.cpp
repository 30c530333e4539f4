#include "drop_tests/dataset_csv.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_set>
#include <unistd.h>

#include "rft/input_error.h"

namespace touchdown::drop {

namespace {
std::vector<std::string> SplitCells(const std::string& line) {
  std::vector<std::string> cells;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    std::string cell = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    // Surrounding blanks are not part of a value (spreadsheets add them).
    const size_t a = cell.find_first_not_of(" \t"), b = cell.find_last_not_of(" \t");
    cells.push_back(a == std::string::npos ? std::string() : cell.substr(a, b - a + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}
}  // namespace

int CsvTable::Find(const std::string& column) const {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == column) return static_cast<int>(i);
  return -1;
}

int CsvTable::Require(const std::string& column) const {
  const int i = Find(column);
  if (i < 0) throw MakeInputError(file, "line 1", "missing column '" + column + "'");
  return i;
}

void CsvTable::Fail(size_t row, int column, const std::string& message) const {
  FailAt(row_lines[row], column, message);
}

void CsvTable::FailAt(int line, int column, const std::string& message) const {
  throw MakeInputError(file,
                       "line " + std::to_string(line) + ", column " + std::to_string(column + 1) + " (" +
                           header[column] + ")",
                       message);
}

double CsvTable::Number(size_t row, int column) const { return NumberAt(rows[row][column], row_lines[row], column); }

double CsvTable::NumberAt(const std::string& cell, int line, int column) const {
  double v = 0.0;
  if (!ParseNumber(cell, &v)) FailAt(line, column, "not a finite number: '" + cell + "'");
  return v;
}

CsvTable ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;
  CsvTable t = VisitCsv(path, [&](const CsvTable&, std::vector<std::string>& cells, int line) {
    rows.push_back(std::move(cells));
    lines.push_back(line);
  });
  t.rows = std::move(rows);
  t.row_lines = std::move(lines);
  return t;
}

CsvTable VisitCsv(const std::string& path, const CsvRowVisitor& on_row) {
  if (!std::filesystem::is_regular_file(path)) throw MakeInputError(path, "", "file not found");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MakeInputError(path, "", "cannot read the file");
  CsvTable t;
  t.file = path;
  std::string line;
  int number = 0;
  bool blank_seen = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) {
      blank_seen = true;
      continue;
    }
    if (blank_seen)
      throw MakeInputError(path, "line " + std::to_string(number), "data after a blank line");
    std::vector<std::string> cells = SplitCells(line);
    if (t.header.empty()) {
      std::unordered_set<std::string> seen;  // not pairwise: a header may have many columns
      for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].empty())
          throw MakeInputError(path, "line 1, column " + std::to_string(i + 1), "empty column name");
        if (!seen.insert(cells[i]).second)
          throw MakeInputError(path, "line 1, column " + std::to_string(i + 1), "duplicate column '" + cells[i] + "'");
      }
      t.header = std::move(cells);
      continue;
    }
    if (cells.size() != t.header.size())
      throw MakeInputError(path, "line " + std::to_string(number),
                           "expected " + std::to_string(t.header.size()) + " cells as in the header, got " +
                               std::to_string(cells.size()));
    on_row(t, cells, number);
  }
  if (t.header.empty()) throw MakeInputError(path, "line 1", "empty file (no header)");
  return t;
}

std::string FormatNumber(double value) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, r.ptr);
}

bool ParseNumber(const std::string& cell, double* value) {
  if (cell.empty()) return false;
  const char* begin = cell.data();
  if (*begin == '+') ++begin;  // from_chars rejects a leading '+'
  const auto r = std::from_chars(begin, cell.data() + cell.size(), *value);
  return r.ec == std::errc() && r.ptr == cell.data() + cell.size() && std::isfinite(*value);
}


}  // namespace touchdown::drop

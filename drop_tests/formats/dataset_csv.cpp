#include "drop_tests/formats/dataset_csv.h"

#include <charconv>
#include <fstream>
#include <cmath>
#include <string>
#include <unordered_set>

#include "rft/input_error.h"
#include "rft/input_file.h"

namespace touchdown::io {

namespace {
// One RFC 4180 record reader, streaming through the file: fields separated by commas, records
// by LF or CRLF, a field in double quotes may hold commas, line breaks and doubled quotes ("").
// Blanks around an unquoted field are not part of it (spreadsheets add them); a quoted field
// is taken exactly. Spreadsheet exports (Excel's UTF-8 BOM, CRLF, pandas QUOTE_ALL) read as is.
class CsvRecords {
 public:
  explicit CsvRecords(const std::string& path) : path_(path) {
    RequireReadableFile(path);  // says what is wrong with the path, in one place for every reader
    if (!in_.open(path, std::ios::in | std::ios::binary)) throw MakeInputError(path, "", "cannot open the file");
    const char bom[] = "\xEF\xBB\xBF";  // the UTF-8 byte order mark Excel writes
    int matched = 0;
    while (matched < 3 && Peek() == static_cast<unsigned char>(bom[matched])) {
      Get();
      ++matched;
    }
    if (matched != 0 && matched != 3) Fail(1, "a broken UTF-8 byte order mark at the start of the file");
  }

  // The next record into `cells` (its first line in `line`); false at the end of the file.
  // A record of blanks only sets `blank`.
  bool Next(std::vector<std::string>* cells, int* line, bool* blank) {
    if (Peek() == kEnd) return false;
    cells->clear();
    *line = line_;
    *blank = true;
    while (true) {
      std::string cell;
      while (IsBlank(Peek())) Get();
      if (Peek() == '"') {
        *blank = false;
        ReadQuoted(&cell);
        while (IsBlank(Peek())) Get();
        if (Peek() != ',' && !AtLineEnd())
          Fail(line_, "unexpected text after a closing quote (a quote inside a quoted field is written \"\")");
      } else {
        while (Peek() != ',' && !AtLineEnd()) {
          if (Peek() == '"') Fail(line_, "a quote inside an unquoted field (quote the whole field)");
          cell.push_back(static_cast<char>(Get()));
        }
        while (!cell.empty() && IsBlank(cell.back())) cell.pop_back();
        if (!cell.empty()) *blank = false;
      }
      cells->push_back(std::move(cell));
      if (Peek() == ',') {
        *blank = false;
        Get();
        continue;
      }
      SkipLineEnd();
      return true;
    }
  }

 private:
  static constexpr int kEnd = std::char_traits<char>::eof();
  int Peek() { return in_.sgetc(); }
  int Get() { return in_.sbumpc(); }
  static bool IsBlank(int c) { return c == ' ' || c == '\t'; }
  // At '\n', "\r\n", a '\r' ending the file, or the end: a lone '\r' inside a line is data.
  bool AtLineEnd() {
    const int c = Peek();
    if (c == kEnd || c == '\n') return true;
    if (c != '\r') return false;
    Get();
    const int next = Peek();
    in_.sungetc();
    return next == '\n' || next == kEnd;
  }
  void SkipLineEnd() {
    if (Peek() == kEnd) return;
    if (Peek() == '\r') Get();
    if (Peek() == '\n') Get();
    ++line_;
  }
  void ReadQuoted(std::string* cell) {
    const int opened = line_;
    Get();  // the opening quote
    while (true) {
      const int c = Get();
      if (c == kEnd) Fail(opened, "a quoted field is not closed (missing \")");
      if (c == '"') {
        if (Peek() != '"') return;
        Get();
      }
      if (c == '\n') ++line_;
      cell->push_back(static_cast<char>(c));
    }
  }
  [[noreturn]] void Fail(int line, const std::string& message) const {
    throw MakeInputError(path_, "line " + std::to_string(line), message);
  }

  const std::string& path_;
  std::filebuf in_;
  int line_ = 1;
};
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
  CsvRecords records(path);
  CsvTable t;
  t.file = path;
  std::vector<std::string> cells;
  int number = 0;
  bool blank = false, blank_seen = false;
  while (records.Next(&cells, &number, &blank)) {
    if (blank) {
      blank_seen = true;
      continue;
    }
    if (blank_seen)
      throw MakeInputError(path, "line " + std::to_string(number), "data after a blank line");
    for (size_t i = 0; i < cells.size(); ++i)
      if (!IsValidUtf8(cells[i]))
        throw MakeInputError(path, "line " + std::to_string(number) + ", column " + std::to_string(i + 1),
                             "not valid UTF-8 text");
    if (t.header.empty()) {
      std::unordered_set<std::string> seen;  // not pairwise: a header may have many columns
      for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].empty())
          throw MakeInputError(path, "line 1, column " + std::to_string(i + 1), "empty column name");
        if (!seen.insert(cells[i]).second)
          throw MakeInputError(path, "line 1, column " + std::to_string(i + 1), "duplicate column '" + cells[i] + "'");
      }
      t.header = std::move(cells);
      cells = {};
      continue;
    }
    if (cells.size() != t.header.size())
      throw MakeInputError(path, "line " + std::to_string(number),
                           "expected " + std::to_string(t.header.size()) + " cells as in the header, got " +
                               std::to_string(cells.size()));
    on_row(t, cells, number);
    cells.clear();
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


}  // namespace touchdown::io

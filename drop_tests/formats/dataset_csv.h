#pragma once
// Comma-separated tables as the dataset format uses them: a header line, then rows of cells,
// read per RFC 4180 (quoted fields, "" for a quote, LF or CRLF, an optional UTF-8 BOM), so
// files saved by Excel or pandas (QUOTE_ALL) read as written. Numbers are written in
// the shortest form that reads back to the same double (std::to_chars), so a write-read round
// trip is exact. Every error names the file, the 1-based line and the column.
#include <functional>
#include <string>
#include <vector>

#include "drop_tests/formats/output_path.h"

namespace touchdown::io {

struct CsvTable {
  std::string file;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> row_lines;  // the file line of each row (1-based; the header is line 1)

  // Index of `column` in the header, or -1.
  int Find(const std::string& column) const;
  // Index of a required column; throws InputError naming the file and the column if missing.
  int Require(const std::string& column) const;
  // The cell as a finite double; throws InputError naming file, line and column otherwise.
  double Number(size_t row, int column) const;
  [[noreturn]] void Fail(size_t row, int column, const std::string& message) const;
  // The same for a row met by VisitCsv, named by its file line.
  double NumberAt(const std::string& cell, int line, int column) const;
  [[noreturn]] void FailAt(int line, int column, const std::string& message) const;
};

// Reads a CSV file row by row without keeping the rows: `on_row` gets each row's cells (after
// the header, which is checked first) and its file line; the rules are ReadCsv's. Returns the
// table's file and header (no rows). A trace of ten million rows kept as strings needed 2 GB.
using CsvRowVisitor = std::function<void(const CsvTable& header, std::vector<std::string>& cells, int line)>;
CsvTable VisitCsv(const std::string& path, const CsvRowVisitor& on_row);

// Reads the whole file; every row must have as many cells as the header and every cell must be
// UTF-8. Blank lines at the end are allowed.
CsvTable ReadCsv(const std::string& path);
// Shortest decimal that parses back to exactly `value`.
std::string FormatNumber(double value);
// Strict parse of a whole cell into a finite double (false on anything else).
bool ParseNumber(const std::string& cell, double* value);


}  // namespace touchdown::io

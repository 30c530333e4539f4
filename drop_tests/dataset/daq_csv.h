#pragma once
// A DAQ's text export as `touchdown import` reads it (docs/import.md): comment lines (metadata)
// anywhere, skipped; blank lines before the header skipped, blank lines at the end allowed; the
// first other line is the header of column names; then one row per sample, its cells separated by
// one delimiter character (a space means runs of blanks, as fixed-width exports write). A cell
// may be quoted ("..." with "" for a quote) and then holds the delimiter. Numbers are required in
// the requested columns only; the other columns may hold anything. Every error is one line naming
// the file, its 1-based line and the column (io::CsvTable's wording, as the dataset reader's).
#include <string>
#include <vector>

namespace touchdown::dataset {

struct DaqTextFormat {
  char delimiter = ',';
  std::string comment = "#";  // a line whose first non-blank characters are this is skipped
  char decimal = '.';         // ',' for exports with a decimal comma (then the delimiter is not ',')
};

struct DaqColumns {
  std::string file;
  std::vector<std::string> header;
  std::vector<int> lines;                   // the file line of each sample (1-based)
  std::vector<std::vector<double>> values;  // values[k][i]: requested column k at sample i
};

// Reads the `columns` (by header name) of the file at `path`. Throws InputError: a missing column
// (with the header's names), a row whose cell count differs from the header's, a requested cell
// that is not a finite number, no sample rows.
DaqColumns ReadDaqColumns(const std::string& path, const DaqTextFormat& format, const std::vector<std::string>& columns);

}  // namespace touchdown::dataset

#include "drop_tests/dataset/daq_csv.h"

#include <algorithm>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/util/nearest_name.h"
#include "rft/input_error.h"
#include "rft/input_file.h"

namespace touchdown::dataset {

namespace {

bool IsDaqBlank(char c, char delimiter) { return (c == ' ' || c == '\t') && c != delimiter; }

// One line's cells; "" on success, else what is wrong. A space delimiter splits on runs of blanks.
std::string SplitDaqLine(const std::string& line, char delimiter, std::vector<std::string>* cells) {
  cells->clear();
  const bool blank_runs = delimiter == ' ';
  const size_t n = line.size();
  size_t i = 0;
  auto skip_blanks = [&] {
    while (i < n && (blank_runs ? (line[i] == ' ' || line[i] == '\t') : IsDaqBlank(line[i], delimiter))) ++i;
  };
  skip_blanks();
  while (true) {
    std::string cell;
    if (i < n && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= n) return "a quoted cell is not closed (missing \")";
        if (line[i] == '"') {
          if (i + 1 < n && line[i + 1] == '"') {
            cell.push_back('"');
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        cell.push_back(line[i++]);
      }
      skip_blanks();
      if (i < n && !(blank_runs ? (line[i - 1] == ' ' || line[i - 1] == '\t') : line[i] == delimiter))
        return "unexpected text after a closing quote";
    } else {
      while (i < n && (blank_runs ? (line[i] != ' ' && line[i] != '\t') : line[i] != delimiter)) cell.push_back(line[i++]);
      while (!cell.empty() && IsDaqBlank(cell.back(), delimiter)) cell.pop_back();
    }
    cells->push_back(std::move(cell));
    if (i >= n) return "";
    if (!blank_runs) ++i;  // the delimiter
    skip_blanks();
    if (blank_runs && i >= n) return "";
  }
}

bool IsCommentLine(const std::string& line, const std::string& comment) {
  const size_t first = line.find_first_not_of(" \t");
  return !comment.empty() && first != std::string::npos && line.compare(first, comment.size(), comment) == 0;
}

bool IsBlankLine(const std::string& line) { return line.find_first_not_of(" \t") == std::string::npos; }

}  // namespace

DaqColumns ReadDaqColumns(const std::string& path, const DaqTextFormat& format, const std::vector<std::string>& columns) {
  std::string text = ReadInputFile(path, "raw file");
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // the byte order mark Excel writes
  DaqColumns out;
  out.file = path;
  out.values.resize(columns.size());
  io::CsvTable table;  // its file and header, for messages in the dataset reader's wording
  table.file = path;
  std::vector<int> index;
  int header_line = 0, blank_after = 0;
  std::vector<std::string> cells;
  size_t start = 0;
  for (int number = 1; start < text.size(); ++number) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (IsCommentLine(line, format.comment)) continue;
    if (IsBlankLine(line)) {
      if (header_line > 0 && blank_after == 0) blank_after = number;
      continue;
    }
    if (!IsValidUtf8(line)) throw MakeInputError(path, "line " + std::to_string(number), "not valid UTF-8 text");
    if (const std::string problem = SplitDaqLine(line, format.delimiter, &cells); !problem.empty())
      throw MakeInputError(path, "line " + std::to_string(number), problem);
    if (header_line == 0) {
      header_line = number;
      table.header = cells;
      out.header = cells;
      for (const std::string& name : columns) {
        const auto found = std::find(cells.begin(), cells.end(), name);
        if (found == cells.end()) {
          std::string listed;
          for (const std::string& c : cells) listed += (listed.empty() ? "'" : ", '") + c + "'";
          throw MakeInputError(path, "line " + std::to_string(number),
                               "missing column '" + name + "'" + io::DidYouMean(name, cells) + "; the header holds " +
                                   listed + " (delimiter '" + std::string(1, format.delimiter) + "')");
        }
        if (std::find(found + 1, cells.end(), name) != cells.end())
          throw MakeInputError(path, "line " + std::to_string(number), "column '" + name + "' appears twice in the header");
        index.push_back(static_cast<int>(found - cells.begin()));
      }
      continue;
    }
    if (blank_after > 0)
      throw MakeInputError(path, "line " + std::to_string(number),
                           "data after a blank line (line " + std::to_string(blank_after) + ")");
    if (cells.size() != table.header.size())
      throw MakeInputError(path, "line " + std::to_string(number),
                           "expected " + std::to_string(table.header.size()) + " cells as in the header (line " +
                               std::to_string(header_line) + "), got " + std::to_string(cells.size()));
    for (size_t k = 0; k < index.size(); ++k) {
      std::string cell = cells[index[k]];
      if (format.decimal != '.') std::replace(cell.begin(), cell.end(), format.decimal, '.');
      double value = 0.0;
      if (!io::ParseNumber(cell, &value)) table.FailAt(number, index[k], "not a finite number: '" + cells[index[k]] + "'");
      out.values[k].push_back(value);
    }
    out.lines.push_back(number);
  }
  if (header_line == 0) throw MakeInputError(path, "", "no header line (every line is blank or a comment)");
  if (out.lines.empty())
    throw MakeInputError(path, "line " + std::to_string(header_line), "no samples after the header");
  return out;
}

}  // namespace touchdown::dataset

#include "drop_tests/formats/plot_decimation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace touchdown::io {

std::vector<size_t> PlotRowsToKeep(size_t rows, size_t columns, const std::function<double(size_t, size_t)>& value,
                                   size_t buckets, size_t kept_whole) {
  std::vector<size_t> keep;
  if (buckets == 0 || rows <= std::max(kept_whole, 2 * buckets)) {
    keep.resize(rows);
    std::iota(keep.begin(), keep.end(), size_t{0});
    return keep;
  }
  std::vector<size_t> lo(columns), hi(columns);
  std::vector<double> lo_value(columns), hi_value(columns);
  std::vector<size_t> bucket_rows;
  for (size_t b = 0; b < buckets; ++b) {
    // Bucket boundaries b * rows / buckets without overflow for any row count.
    const size_t begin = rows / buckets * b + rows % buckets * b / buckets;
    const size_t end = rows / buckets * (b + 1) + rows % buckets * (b + 1) / buckets;
    std::fill(lo.begin(), lo.end(), end);
    std::fill(hi.begin(), hi.end(), end);
    for (size_t i = begin; i < end; ++i)
      for (size_t c = 0; c < columns; ++c) {
        const double v = value(i, c);
        if (std::isnan(v)) continue;
        if (lo[c] == end || v < lo_value[c]) lo[c] = i, lo_value[c] = v;
        if (hi[c] == end || v > hi_value[c]) hi[c] = i, hi_value[c] = v;
      }
    bucket_rows = {begin, end - 1};
    for (size_t c = 0; c < columns; ++c)
      if (lo[c] != end) bucket_rows.insert(bucket_rows.end(), {lo[c], hi[c]});
    std::sort(bucket_rows.begin(), bucket_rows.end());
    bucket_rows.erase(std::unique(bucket_rows.begin(), bucket_rows.end()), bucket_rows.end());
    keep.insert(keep.end(), bucket_rows.begin(), bucket_rows.end());
  }
  return keep;
}

std::vector<size_t> PlotRowsToKeep(size_t rows, const std::vector<std::span<const double>>& columns, size_t buckets,
                                   size_t kept_whole) {
  for (const std::span<const double>& c : columns)
    if (c.size() != rows) throw std::invalid_argument("PlotRowsToKeep: a column's length differs from the rows");
  return PlotRowsToKeep(
      rows, columns.size(), [&](size_t row, size_t column) { return columns[column][row]; }, buckets, kept_whole);
}

}  // namespace touchdown::io

#pragma once
// What goes into a plot data file: a trace of ten million samples is drawn from a few thousand
// rows. Short traces are kept whole. A longer one is cut into kPlotBuckets consecutive index
// ranges and each range keeps its first and last row and, for every column given, the rows
// where that column is smallest and largest (NaN ignored): the M4 reduction (Jugel et al.,
// "M4: a visualization-oriented time series data aggregation", VLDB 2014). A line through the
// kept rows, in their order, passes through every extreme, so with no more ranges than a panel
// has pixel columns the figure is the same to the eye; peaks are never lost. Deterministic.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace touchdown::io {

// Four times the pixel width of the widest plot panel touchdown draws (1000 px): enough that
// a scatter of a long trace (measured samples drawn as points) still looks solid.
inline constexpr size_t kPlotBuckets = 4000;
// Traces up to this many rows are plotted whole.
inline constexpr size_t kPlotRowsKeptWhole = 4 * kPlotBuckets;

// Row indices to plot, increasing, out of `rows` rows whose plotted columns are `columns` (each
// `rows` long). At most buckets * (2 + 2 * columns.size()) indices.
std::vector<size_t> PlotRowsToKeep(size_t rows, const std::vector<std::span<const double>>& columns,
                                   size_t buckets = kPlotBuckets, size_t kept_whole = kPlotRowsKeptWhole);
// The same over `columns` columns read through value(row, column), for traces whose plotted
// columns are computed from samples rather than stored.
std::vector<size_t> PlotRowsToKeep(size_t rows, size_t columns, const std::function<double(size_t, size_t)>& value,
                                   size_t buckets = kPlotBuckets, size_t kept_whole = kPlotRowsKeptWhole);

}  // namespace touchdown::io

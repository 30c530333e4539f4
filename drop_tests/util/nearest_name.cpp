#include "drop_tests/util/nearest_name.h"

#include <algorithm>

namespace touchdown::io {

int EditDistance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  // d[i][j]: distance between a's first i and b's first j characters, rows kept as a flat table.
  std::vector<int> d((n + 1) * (m + 1));
  auto at = [&](size_t i, size_t j) -> int& { return d[i * (m + 1) + j]; };
  for (size_t i = 0; i <= n; ++i) at(i, 0) = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) at(0, j) = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
    }
  return at(n, m);
}

std::optional<std::string> NearestName(const std::string& typed, const std::vector<std::string>& known) {
  const int limit = std::max<int>(1, static_cast<int>(typed.size()) / 3);
  std::optional<std::string> best;
  int best_distance = limit + 1;
  for (const std::string& name : known) {
    const int d = EditDistance(typed, name);
    if (d < best_distance) best = name, best_distance = d;
  }
  return best;
}

std::string DidYouMean(const std::string& typed, const std::vector<std::string>& known) {
  const std::optional<std::string> near = NearestName(typed, known);
  return near ? " (did you mean '" + *near + "'?)" : std::string();
}

}  // namespace touchdown::io

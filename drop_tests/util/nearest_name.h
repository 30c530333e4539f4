#pragma once
// "Did you mean ...?" for a mistyped name (a pad, a soil, a subcommand): the known name with the
// fewest single-character edits (insert, delete, substitute, swap two neighbours) from what was
// typed, if it is close enough to be a typo rather than another word.
#include <optional>
#include <string>
#include <vector>

namespace touchdown::io {

// Optimal string alignment distance (Damerau-Levenshtein without repeated edits of a substring).
int EditDistance(const std::string& a, const std::string& b);

// The nearest of `known` within max(1, typed.size() / 3) edits (ties: the first listed), else none.
std::optional<std::string> NearestName(const std::string& typed, const std::vector<std::string>& known);

// " (did you mean 'x'?)" or "".
std::string DidYouMean(const std::string& typed, const std::vector<std::string>& known);

}  // namespace touchdown::io

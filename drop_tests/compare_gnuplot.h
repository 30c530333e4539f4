#pragma once
// Renders a gnuplot script that sits inside `dir` (paths in it relative to `dir`). Without
// gnuplot on the PATH the script stays for the user and a warning goes to stderr; a gnuplot
// error throws with the log's location.
#include <string>

namespace touchdown::drop {

void RunGnuplot(const std::string& dir, const std::string& script_relative);
// Quotes a path for a gnuplot string literal (single quotes doubled).
std::string GnuplotQuote(const std::string& text);

}  // namespace touchdown::drop

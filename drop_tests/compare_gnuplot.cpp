#include "drop_tests/compare_gnuplot.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace touchdown::drop {

namespace fs = std::filesystem;

std::string GnuplotQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

void RunGnuplot(const std::string& dir, const std::string& script_relative) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    std::cerr << "warning: gnuplot not found; plot script left in " << (fs::path(dir) / script_relative).string()
              << "\n";
    return;
  }
  const fs::path log = fs::path(dir) / (script_relative + ".log");
  const std::string command = "cd '" + dir + "' && gnuplot '" + script_relative + "' 2>'" + log.string() + "'";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("gnuplot failed; see " + log.string());
  fs::remove(log);
}

}  // namespace touchdown::drop

#include "drop_tests/formats/plot_runner.h"

#include <sys/resource.h>
#include <sys/statvfs.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <regex>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/external_program.h"
#include "rft/input_error.h"

namespace touchdown::io {

namespace fs = std::filesystem;

namespace {

constexpr std::array<unsigned char, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// The IEND chunk every PNG ends with: length 0, type "IEND", CRC-32 of the type.
constexpr std::array<unsigned char, 12> kPngEnd = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};

bool NoSpaceLeft(const fs::path& directory) {
  struct statvfs s {};
  return ::statvfs(directory.c_str(), &s) == 0 && s.f_bavail == 0;
}

bool AtFileSizeLimit(const fs::path& file) {
  rlimit limit{};
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  return !ec && ::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && size >= limit.rlim_cur;
}

// Why gnuplot could not finish writing `file` inside `directory`, as the OS would say it.
std::string WriteFailureReason(const fs::path& directory, const fs::path& file) {
  if (NoSpaceLeft(directory)) return std::strerror(ENOSPC);
  if (AtFileSizeLimit(file)) return std::strerror(EFBIG);
  return "gnuplot stopped writing it (is the file system full?)";
}

// gnuplot's first error line in its log: the "<script>", line N: <what> line when there is one
// (gnuplot echoes the offending command and a caret line before it), else the first line with
// text; "" when the log is empty or unreadable. At most 300 characters.
std::string FirstErrorLine(const fs::path& log) {
  std::ifstream in(log, std::ios::binary);
  std::string line, first;
  const std::regex located(R"(line [0-9]+:)");
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (line.find_first_not_of(" \t^") == std::string::npos) continue;  // blank, or the caret under the echo
    if (std::regex_search(line, located)) {
      first = line;
      break;
    }
    if (first.empty()) first = line;
  }
  if (first.size() > 300) first = first.substr(0, 300) + "...";
  return first;
}

// Why gnuplot stopped, for the message: its status, or the signal that killed it.
std::string HowItStopped(const ExternalProgramError& e) {
  if (e.signal() != 0) return "was killed by signal " + std::to_string(e.signal()) + " (" + ::strsignal(e.signal()) + ")";
  return "exited with status " + std::to_string(e.exit_status());
}

}  // namespace

std::string GnuplotQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "''";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

std::string PlaceholderPlot(const std::string& message) {
  return "set label 1 " + GnuplotQuote(message) + " at graph 0.5, graph 0.5 center\nplot [0:1][0:1] NaN notitle\n"
         "unset label 1\n";
}

std::string PngProblem(const fs::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return "missing";
  const std::streamoff size = in.tellg();
  std::array<unsigned char, 8> head{};
  in.seekg(0);
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  if (!in || head != kPngSignature) return "not a PNG";
  std::array<unsigned char, 12> tail{};
  if (size < static_cast<std::streamoff>(head.size() + tail.size())) return "truncated: no IEND chunk at its end";
  in.seekg(size - static_cast<std::streamoff>(tail.size()));
  in.read(reinterpret_cast<char*>(tail.data()), tail.size());
  if (!in || tail != kPngEnd) return "truncated: no IEND chunk at its end";
  return "";
}

void RenderPlots(const fs::path& directory, const PlotScript& script) {
  const fs::path script_file = directory / script.path;
  fs::create_directories(script_file.parent_path());
  WriteFileAtomically(script_file.string(), [&](std::ostream& out) { out << script.text; });
  // A PNG left by an earlier run must not pass for this run's.
  for (const std::string& png : script.outputs) fs::remove(directory / png);
  const fs::path log = script_file.parent_path() / "gnuplot.log";
  try {
    RunProgram({{"gnuplot", script.path}, directory, log, {}});
  } catch (const ExternalProgramError& e) {
    if (e.spawn_errno() == ENOENT)
      throw InputError("gnuplot: not found on the PATH; touchdown draws its plots with gnuplot: install it "
                       "(Debian: apt install gnuplot-nox)");
    if (e.spawn_errno() != 0) throw InputError(std::string(e.what()));
    if (e.signal() == SIGXFSZ || NoSpaceLeft(directory))
      throw InputError(script.path + ": gnuplot could not write its plots: " +
                       std::strerror(e.signal() == SIGXFSZ ? EFBIG : ENOSPC));
    const std::string first = FirstErrorLine(log);
    throw InputError(script.path + ": gnuplot " + HowItStopped(e) + (first.empty() ? "" : ": " + first) +
                     " (check the gnuplot installation: the pngcairo terminal and its fonts; log: " +
                     (fs::path(script.path).parent_path() / "gnuplot.log").string() + " in the output directory)");
  }
  for (const std::string& png : script.outputs) {
    const std::string problem = PngProblem(directory / png);
    if (problem == "missing")
      throw InputError(png + " (in the output directory): gnuplot did not write it" +
                       (NoSpaceLeft(directory) ? std::string(": ") + std::strerror(ENOSPC) : std::string()));
    if (!problem.empty())
      throw InputError(png + " (in the output directory): gnuplot did not write a complete PNG (" + problem +
                       "): " + WriteFailureReason(directory, directory / png));
  }
  fs::remove(log);
}

}  // namespace touchdown::io

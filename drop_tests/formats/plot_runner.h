#pragma once
// The one way touchdown draws its figures (campaign, lander, compare, diagnose, trade): a
// gnuplot script is written into the output directory and gnuplot runs with that directory as
// its working directory, started by RunProgram (external_program.h: argument vector, no shell).
// Every path inside a script is relative to that directory, so the user's --out (quotes,
// spaces, non-ASCII) never reaches gnuplot's parser or a shell; names that do appear in a script
// (drop ids, pads, soils, titles) go through GnuplotQuote.
//
// After gnuplot each expected PNG must exist and be complete (the PNG signature, then an IEND
// chunk at the very end): gnuplot exits 0 after writing a truncated PNG on a full disk, so a
// truncated file is a failure too. Failures:
//   - gnuplot is not on the PATH, or cannot start               -> InputError (exit 2): plots are
//     part of these commands' outputs and gnuplot is a dependency (tools/install_deps.sh);
//   - a PNG missing or truncated, gnuplot killed by SIGXFSZ, or gnuplot failing on a file system
//     with no space left                                          -> InputError (exit 2) naming
//     the file (relative to the output directory) and the OS reason;
//   - any other gnuplot failure (a non-zero exit, killed by a signal)   -> InputError (exit 2)
//     naming the script, how gnuplot stopped and gnuplot's first error line, and pointing at
//     the installation. Every script touchdown writes is rendered by its test suite
//     (tests/apps/plot_outputs_test.cpp and the placeholder cases), so a gnuplot that fails on
//     the user's machine is far more likely that machine's gnuplot (no pngcairo terminal, a
//     missing font, killed by the OOM killer or a time limit) than touchdown's script; the
//     message carries gnuplot's own words either way, so a real script bug is still reportable.
// gnuplot's stderr goes to plots/gnuplot.log, removed when everything is fine.
#include <filesystem>
#include <string>
#include <vector>

namespace touchdown::io {

struct PlotScript {
  std::string path;                  // the script, relative to the directory: "plots/campaign.gp"
  std::string text;                  // gnuplot commands; paths relative to the directory
  std::vector<std::string> outputs;  // the PNGs it must write, relative to the directory
};

// Writes the script and renders it in `directory`; throws as described above.
void RenderPlots(const std::filesystem::path& directory, const PlotScript& script);

// A gnuplot single-quoted string literal holding `text` verbatim (quotes doubled; a line break,
// which no gnuplot string can hold, becomes a space).
std::string GnuplotQuote(const std::string& text);

// Commands drawing an empty frame with `message` in its middle: what a figure shows when there
// is nothing to plot (a gnuplot `plot` of no data is an error).
std::string PlaceholderPlot(const std::string& message);

// "" when `file` is a complete PNG, otherwise why not ("missing", "not a PNG", "truncated: no
// IEND chunk at its end").
std::string PngProblem(const std::filesystem::path& file);

}  // namespace touchdown::io

#pragma once
// One look for every figure touchdown draws (campaign, lander, compare, diagnose, trade,
// stability): the same fonts, grid and key, each figure written as PNG (at slide resolution,
// for the plot runner to check) and as SVG beside it (for papers), and one meaning per colour:
// a pad keeps its colour and a soil its dash pattern in every figure; measured and paper values
// are black points, so they never pass for a simulation.
#include <string>
#include <vector>

namespace touchdown::io {

struct FigureSize {
  int width = 1600, height = 1000;  // pixels of the PNG (SVG: the same in points)
};
inline constexpr FigureSize kFigureWide{1600, 1000};
inline constexpr FigureSize kFigureStrip{1600, 600};
inline constexpr FigureSize kFigureSquare{1100, 1000};

// The script that draws `body` (gnuplot commands: titles, labels, `plot`s) to `base`.png and
// `base`.svg ("plots/fig3_time_histories"): terminal, style, then body, for each file. `svg`
// false: the PNG only (figures written per drop, which are looked at, not printed).
std::string Figure(const std::string& base, const std::string& body, FigureSize size = kFigureWide, bool svg = true);

// The files a Figure writes that RenderPlots must check (the PNG; the SVG is written by the same
// commands).
std::string FigurePng(const std::string& base);

// Colour of a pad (the catalogue's pads have fixed ones; any other name a stable pick from the
// rest of the palette): "#rrggbb".
std::string PadColour(const std::string& pad_name);
// Dash type of a soil: loosely packed solid, closely packed dashed, others by a stable pick.
int SoilDash(const std::string& soil_name);
// `lw 2.5 lc rgb '#..' dt N` for a simulated line of `pad` on `soil`.
std::string PadSoilLine(const std::string& pad_name, const std::string& soil_name);
// The k-th colour of the palette, for series that are not pads (pads of a lander: 1..4).
std::string SeriesColour(int k);
// Measured or published values: black points (filled circles), or a black dashed band edge.
inline constexpr const char* kMeasuredPoints = "pt 7 ps 1.3 lc rgb '#000000'";
inline constexpr const char* kPaperBandLine = "lw 1.5 dt 3 lc rgb '#000000'";

}  // namespace touchdown::io

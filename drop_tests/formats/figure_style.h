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
// `base`.svg ("plots/fig3_time_histories"): terminal, style, then body, for each file. Every
// figure gets both: the PNG for slides and screens, the SVG for papers.
std::string Figure(const std::string& base, const std::string& body, FigureSize size = kFigureWide);

// The files a Figure writes that RenderPlots must check (the PNG; the SVG is written by the same
// commands).
std::string FigurePng(const std::string& base);

// One palette per meaning, the same in every figure:
//  - footpad shapes (PadColour): flat, c4, curved, hex keep one colour each;
//  - soils (SoilDash, SoilPoint, SoilDisplayName): loosely packed solid line and circles, closely
//    packed dashed and squares, named as in the paper ("FJS-1 LP");
//  - a lander's pads 1..4 (LanderPadLine, LanderPadPoint): colour, dash, width and point type all
//    differ, so two pads that move together stay visible as two traces;
//  - force laws (LawColour): quasi-static RFT, dynamic RFT, Bekker;
//  - measured against simulated: measured and published values are black points (kMeasuredPoints)
//    or black dotted lines (kPaperBandLine); simulations are coloured lines.
//
// Colour of a pad (the catalogue's pads have fixed ones; any other name a stable pick from the
// colours none of them holds): "#rrggbb".
std::string PadColour(const std::string& pad_name);
// The colours of the pads one figure draws, `pad_names` distinct, in their order: a catalogue pad
// its own; the others the colours none of them holds, one each while they last (seven: a trade of
// a pad family tells its members apart), then PadColour's pick.
std::vector<std::string> PadColours(const std::vector<std::string>& pad_names);
// Dash type of a soil: loosely packed solid, closely packed dashed, others by a stable pick.
int SoilDash(const std::string& soil_name);
// `lw 2.5 lc rgb '#..' dt N` for a simulated line of `pad` on `soil` (ColourSoilLine: of a pad whose
// colour PadColours gave).
std::string PadSoilLine(const std::string& pad_name, const std::string& soil_name);
std::string ColourSoilLine(const std::string& colour, const std::string& soil_name);
// The k-th colour of the palette, for series that have no meaning of their own.
std::string SeriesColour(int k);
// Point type of a soil's marks: circles on loosely packed, squares on closely packed, others by a
// stable pick; `filled` false gives the open variant of the same shape.
int SoilPoint(const std::string& soil_name, bool filled = true);
// The soil's name as a reader knows it: "fjs1_lp" -> "FJS-1 LP", "fjs1_cp_bekker" -> "FJS-1 CP
// (Bekker)", "lunar_nominal_bekker" -> "lunar nominal (Bekker)"; a name it does not know keeps its
// words, underscores as spaces.
std::string SoilDisplayName(const std::string& soil_name);
// An identifier written for a reader: underscores as spaces ("final_penetration_ratio" ->
// "final penetration ratio").
std::string Words(const std::string& identifier);

// Ranges fitted to the data (docs/figures.md), in round numbers:
// 10^exponent, formed so that a negative power divides (1e-3 is written "0.001").
double PowerOfTen(int exponent);
// A scale's top that reads as a round number: the smallest of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times
// a power of ten at or above v > 0, so at most a third of the scale is left empty (a map's colour
// scale: 0.18 -> 0.2).
double RoundScaleTop(double v);
// The top of an axis from 0 a little past `largest` > 0: the first multiple of a 1-2-5 step (10 to
// 20 of them over the range) at least 3 % above it, so the last value stands clear of the frame and
// at most about a tenth of the axis lies past the data (349.4 -> 360, 43.4 -> 45).
double AxisTopPast(double largest);
// A tic step of 1, 2 or 5 times a power of ten giving at most `max_tics` intervals over `span` > 0
// (a narrow panel's axis, where gnuplot's own choice runs its labels together).
double TicStep(double span, int max_tics);

// Lander pad `i` (0..3, drawn as "pad i+1"): `lw .. lc rgb '..' dt ..`, widest for pad 1 and
// narrowest for pad 4, so when the pads are drawn in order a later pad lies inside an earlier one.
std::string LanderPadLine(int i);
int LanderPadPoint(int i);
std::string LanderPadColour(int i);

// Colour of a force law or model variant: "quasi_static", "dynamic", "bekker" (a name holding one
// of these words takes its colour); others by a stable pick.
std::string LawColour(const std::string& law);
// Simulated values with no other meaning to show (one model against measurements).
inline constexpr const char* kSimulatedColour = "#0072B2";
// A model with an added effect, beside its base (kBaseLine): an accent no pad uses.
inline constexpr const char* kBaseLine = "lw 2.5 dt 2 lc rgb '#6e6e6e'";
inline constexpr const char* kAugmentedColour = "#AA3377";
// Empty cells of a map: a grey no colour scale uses.
inline constexpr const char* kEmptyCellColour = "#bdbdbd";
// Cells of a map at zero on a logarithmic colour scale, which has no zero: a pale blue below the
// scale's darkest blue, apart from the empty cells' grey hatching.
inline constexpr const char* kZeroCellColour = "#deebf7";
// The key in one row (or a few) below the frame, under the x label: the data keep the whole
// width and nothing covers a label or tic.
inline constexpr const char* kKeyBelow = "set key bmargin center horizontal Left reverse samplen 2 width -1\nset bmargin 7\n";
// Measured or published values: black points (filled circles), or a black dashed band edge.
inline constexpr const char* kMeasuredPoints = "pt 7 ps 1.3 lc rgb '#000000'";
inline constexpr const char* kPaperBandLine = "lw 1.5 dt 3 lc rgb '#000000'";

}  // namespace touchdown::io

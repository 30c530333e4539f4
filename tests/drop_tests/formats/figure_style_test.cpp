// The one figure style: every figure written as PNG and SVG, and one meaning per colour, dash and
// mark (pads, soils, a lander's pads, laws), with soils named as a reader knows them; ranges and
// tics fitted to the data in round numbers.
#include "drop_tests/formats/figure_style.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace touchdown::io {
namespace {

TEST(FigureStyle, EveryFigureIsWrittenAsPngAndSvg) {
  const std::string script = Figure("plots/x", "plot x\n", kFigureStrip);
  EXPECT_NE(script.find("set terminal pngcairo"), std::string::npos) << script;
  EXPECT_NE(script.find("set output 'plots/x.png'"), std::string::npos) << script;
  EXPECT_NE(script.find("set terminal svg"), std::string::npos) << script;
  EXPECT_NE(script.find("set output 'plots/x.svg'"), std::string::npos) << script;
  EXPECT_EQ(FigurePng("plots/x"), "plots/x.png");
  // The SVG is drawn from the style afresh, whatever the PNG's body left unset.
  EXPECT_EQ(script.find("reset\n", script.find("set output 'plots/x.png'")) < script.find("set terminal svg"), true)
      << script;
}

TEST(FigureStyle, RangesEndOnRoundNumbersJustPastTheData) {
  // A colour scale's top: the round number at or above the highest value, at most a third above.
  EXPECT_EQ(RoundScaleTop(0.176), 0.2);
  EXPECT_EQ(RoundScaleTop(0.2), 0.2);
  EXPECT_EQ(RoundScaleTop(0.21), 0.25);
  EXPECT_EQ(RoundScaleTop(0.9), 1.0);
  EXPECT_EQ(RoundScaleTop(0.0123), 0.015);
  EXPECT_EQ(RoundScaleTop(7.1), 8.0);
  // An axis from 0 a little past its largest value: 3 % or more past it, on a 1-2-5 step.
  EXPECT_EQ(AxisTopPast(349.4), 360.0);  // the shipped lunar study's deepest pad [mm]
  EXPECT_EQ(AxisTopPast(43.4), 45.0);    // its largest max tilt [deg]
  EXPECT_EQ(AxisTopPast(100.0), 105.0);
  EXPECT_EQ(AxisTopPast(0.0123), 0.013);
  for (double v : {0.37, 1.0, 2.9, 57.0, 811.0, 12345.0}) {
    EXPECT_GE(AxisTopPast(v), 1.03 * v) << v;
    EXPECT_LE(AxisTopPast(v), 1.16 * v) << v;
  }
  EXPECT_EQ(PowerOfTen(-3), 0.001);
  EXPECT_EQ(PowerOfTen(2), 100.0);
  // Tics: 1, 2 or 5 times a power of ten, at most the number asked for.
  EXPECT_EQ(TicStep(2.0, 5), 0.5);   // 0.5 to 2.5 m/s in a narrow panel: 0.5, 1, ... 2.5
  EXPECT_EQ(TicStep(1.5, 5), 0.5);
  EXPECT_EQ(TicStep(100.0, 5), 20.0);
}

TEST(FigureStyle, SoilsAreNamedAsInThePapers) {
  EXPECT_EQ(SoilDisplayName("fjs1_lp"), "FJS-1 LP");
  EXPECT_EQ(SoilDisplayName("fjs1_cp"), "FJS-1 CP");
  EXPECT_EQ(SoilDisplayName("fjs1_cp_bekker"), "FJS-1 CP (Bekker)");
  EXPECT_EQ(SoilDisplayName("fjs1_cp_spot"), "FJS-1 CP spot");
  EXPECT_EQ(SoilDisplayName("lunar_nominal_bekker"), "lunar nominal (Bekker)");
  EXPECT_EQ(SoilDisplayName("my_soil"), "my soil");
  EXPECT_EQ(Words("final_penetration_ratio"), "final penetration ratio");
}

// Two pads of a lander that move together must still show as two traces: no two pads share a
// colour, a width, or a mark.
TEST(FigureStyle, LanderPadsDifferInColourWidthAndMark) {
  std::set<std::string> lines, colours;
  std::set<int> points;
  for (int i = 0; i < 4; ++i) {
    lines.insert(LanderPadLine(i));
    colours.insert(LanderPadColour(i));
    points.insert(LanderPadPoint(i));
    EXPECT_NE(LanderPadLine(i).find(LanderPadColour(i)), std::string::npos);
  }
  EXPECT_EQ(lines.size(), 4u);
  EXPECT_EQ(colours.size(), 4u);
  EXPECT_EQ(points.size(), 4u);
}

TEST(FigureStyle, OneMeaningPerStyle) {
  // Pads: fixed and distinct colours; soils: LP solid circles, CP dashed squares, whatever the law.
  std::set<std::string> pads;
  for (const char* pad : {"flat", "c4", "curved", "hex"}) pads.insert(PadColour(pad));
  EXPECT_EQ(pads.size(), 4u);
  EXPECT_EQ(SoilDash("fjs1_lp"), 1);
  EXPECT_EQ(SoilDash("fjs1_lp_bekker"), 1);
  EXPECT_EQ(SoilDash("fjs1_cp"), 2);
  EXPECT_EQ(SoilPoint("fjs1_lp"), 7);
  EXPECT_EQ(SoilPoint("fjs1_lp", false), 6);
  EXPECT_EQ(SoilPoint("fjs1_cp"), 5);
  // Laws: a variant takes its law's colour.
  EXPECT_EQ(LawColour("quasi_static_zeta_fixed"), LawColour("quasi_static"));
  EXPECT_NE(LawColour("dynamic"), LawColour("quasi_static"));
  EXPECT_NE(LawColour("bekker"), LawColour("dynamic"));
  EXPECT_EQ(PadSoilLine("curved", "fjs1_cp"), "lw 2.5 lc rgb '" + PadColour("curved") + "' dt 2");
  // The pads of one figure: the catalogue's keep theirs, the others one colour each while the
  // seven spare ones last (a trade of a pad family).
  const std::vector<std::string> family = {"flat", "r35", "c4", "r40", "r45", "r55", "r60", "r65", "r70", "curved", "hex"};
  const std::vector<std::string> colours = PadColours(family);
  ASSERT_EQ(colours.size(), family.size());
  EXPECT_EQ(colours[0], PadColour("flat"));
  EXPECT_EQ(colours[9], PadColour("curved"));
  EXPECT_EQ(std::set<std::string>(colours.begin(), colours.end()).size(), family.size());
}

}  // namespace
}  // namespace touchdown::io

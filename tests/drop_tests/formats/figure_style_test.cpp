// The one figure style: every figure written as PNG and SVG, and one meaning per colour, dash and
// mark (pads, soils, a lander's pads, laws), with soils named as a reader knows them.
#include "drop_tests/formats/figure_style.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace touchdown::io {
namespace {

TEST(FigureStyle, EveryFigureIsWrittenAsPngAndSvg) {
  const std::string script = Figure("plots/x", "plot x\n", kFigureStrip);
  EXPECT_NE(script.find("set terminal pngcairo"), std::string::npos) << script;
  EXPECT_NE(script.find("set output 'plots/x.png'"), std::string::npos) << script;
  EXPECT_NE(script.find("set terminal svg"), std::string::npos) << script;
  EXPECT_NE(script.find("set output 'plots/x.svg'"), std::string::npos) << script;
  EXPECT_EQ(FigurePng("plots/x"), "plots/x.png");
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
}

}  // namespace
}  // namespace touchdown::io

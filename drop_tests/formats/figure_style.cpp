#include "drop_tests/formats/figure_style.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "drop_tests/formats/plot_runner.h"

namespace touchdown::io {

namespace {
// Okabe-Ito: distinguishable with the common colour-vision deficiencies and in greyscale print.
constexpr std::array<const char*, 7> kPalette = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                  "#E69F00", "#56B4E9", "#F0E442"};
struct Named {
  const char* name;
  int index;
};
constexpr std::array<Named, 4> kPadColours = {{{"flat", 0}, {"c4", 1}, {"curved", 2}, {"hex", 3}}};

uint32_t StableHash(const std::string& s) {  // FNV-1a: the same pick on every machine and run
  uint32_t h = 2166136261u;
  for (unsigned char c : s) h = (h ^ c) * 16777619u;
  return h;
}

std::string Style() {
  return "set termoption noenhanced\nset datafile separator ','\nset grid lc rgb '#d0d0d0' lw 1\n"
         "set border lw 1.2\nset key box opaque samplen 3 spacing 1.2\nset tics out nomirror\n";
}
}  // namespace

std::string Figure(const std::string& base, const std::string& body, FigureSize size) {
  const std::string dims = " size " + std::to_string(size.width) + "," + std::to_string(size.height);
  // Each file from the style afresh: a body that unsets what it no longer needs (a key strip's
  // border, tics and grid) draws the SVG as it drew the PNG.
  return "reset\n" + Style() + "set terminal pngcairo noenhanced" + dims + " font 'sans,16'\nset output " +
         GnuplotQuote(base + ".png") + "\n" + body + "reset\n" + Style() + "set terminal svg noenhanced" + dims +
         " font 'sans,16'\nset output " + GnuplotQuote(base + ".svg") + "\n" + body + "unset output\n";
}

std::string FigurePng(const std::string& base) { return base + ".png"; }

namespace {
// `multiple` times 10^`exponent`, a negative power dividing: 0.013 is written "0.013", not the
// neighbouring double 13 * 0.001 = 0.013000000000000001.
double Scaled(double multiple, int exponent) {
  return exponent >= 0 ? multiple * std::pow(10.0, exponent) : multiple / std::pow(10.0, -exponent);
}
int Decade(double v) { return static_cast<int>(std::floor(std::log10(v))); }
}  // namespace

double PowerOfTen(int exponent) { return Scaled(1.0, exponent); }

double RoundScaleTop(double v) {
  const int exponent = Decade(v);
  for (const double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0})
    if (Scaled(m, exponent) >= v * (1.0 - 1e-12)) return Scaled(m, exponent);
  return Scaled(1.0, exponent + 1);
}

double AxisTopPast(double largest) {
  for (int exponent = Decade(largest) - 2;; ++exponent)
    for (const double m : {1.0, 2.0, 5.0})
      if (largest / Scaled(m, exponent) <= 20.0)
        return Scaled(std::ceil(1.03 * largest / Scaled(m, exponent) - 1e-9) * m, exponent);
}

double TicStep(double span, int max_tics) {
  for (int exponent = Decade(span / max_tics) - 1;; ++exponent)
    for (const double m : {1.0, 2.0, 5.0})
      if (span / Scaled(m, exponent) <= max_tics) return Scaled(m, exponent);
}

std::string SeriesColour(int k) { return kPalette[static_cast<size_t>(k) % kPalette.size()]; }

namespace {
// The colours no catalogue pad holds: the rest of Okabe-Ito, then four of Paul Tol's "muted" set
// apart from every pad's and law's colour (wine, olive, indigo, teal), so a trade of a dozen pad
// designs still tells them apart.
constexpr std::array<const char*, 7> kSparePadColours = {"#E69F00", "#56B4E9", "#F0E442", "#882255",
                                                          "#999933", "#332288", "#44AA99"};

const char* CatalogueColour(const std::string& pad_name) {
  for (const Named& n : kPadColours)
    if (pad_name == n.name) return kPalette[n.index];
  return nullptr;
}
}  // namespace

std::string PadColour(const std::string& pad_name) {
  if (const char* c = CatalogueColour(pad_name)) return c;
  return kSparePadColours[StableHash(pad_name) % kSparePadColours.size()];
}

std::vector<std::string> PadColours(const std::vector<std::string>& pad_names) {
  std::vector<std::string> colours;
  size_t spare = 0;
  for (const std::string& pad : pad_names) {
    if (const char* c = CatalogueColour(pad))
      colours.push_back(c);
    else
      colours.push_back(spare < kSparePadColours.size() ? kSparePadColours[spare++] : PadColour(pad));
  }
  return colours;
}

int SoilDash(const std::string& soil_name) {
  if (soil_name.find("_lp") != std::string::npos) return 1;
  if (soil_name.find("_cp") != std::string::npos) return 2;
  return 3 + static_cast<int>(StableHash(soil_name) % 3);
}

int SoilPoint(const std::string& soil_name, bool filled) {
  // gnuplot's point types: 6/7 circle, 4/5 square, 8/9 triangle, 12/13 diamond (open/filled).
  int open = 8 + 4 * static_cast<int>(StableHash(soil_name) % 2);
  if (soil_name.find("_lp") != std::string::npos) open = 6;
  if (soil_name.find("_cp") != std::string::npos) open = 4;
  return filled ? open + 1 : open;
}

std::string Words(const std::string& identifier) {
  std::string out = identifier;
  std::replace(out.begin(), out.end(), '_', ' ');
  return out;
}

std::string SoilDisplayName(const std::string& soil_name) {
  std::string rest = soil_name, law;
  if (rest.ends_with("_bekker")) {
    rest.resize(rest.size() - 7);
    law = " (Bekker)";
  }
  std::string variant;
  if (rest.ends_with("_spot")) {
    rest.resize(rest.size() - 5);
    variant = " spot";
  }
  static const std::array<std::pair<const char*, const char*>, 4> kKnown = {
      {{"fjs1_lp", "FJS-1 LP"}, {"fjs1_cp", "FJS-1 CP"}, {"toyoura", "Toyoura sand"}, {"lunar_nominal", "lunar nominal"}}};
  for (const auto& [name, shown] : kKnown)
    if (rest == name) return shown + variant + law;
  return Words(rest) + variant + law;
}

std::string LanderPadColour(int i) {
  // Blue, vermillion, green, black: four hues apart in any colour vision and in greyscale.
  constexpr std::array<const char*, 4> kColours = {"#0072B2", "#D55E00", "#009E73", "#000000"};
  return kColours[static_cast<size_t>(i) % kColours.size()];
}

std::string LanderPadLine(int i) {
  constexpr std::array<const char*, 4> kWidths = {"5", "3.5", "2.2", "1.3"};
  constexpr std::array<int, 4> kDashes = {1, 2, 4, 1};
  const size_t k = static_cast<size_t>(i) % kWidths.size();
  return std::string("lw ") + kWidths[k] + " lc rgb '" + LanderPadColour(i) + "' dt " + std::to_string(kDashes[k]);
}

int LanderPadPoint(int i) {
  constexpr std::array<int, 4> kPoints = {7, 5, 9, 13};  // filled circle, square, triangle, diamond
  return kPoints[static_cast<size_t>(i) % kPoints.size()];
}

std::string LawColour(const std::string& law) {
  // Apart from the pads' colours where a figure shows both; dashes say whether zeta is fixed.
  if (law.find("bekker") != std::string::npos) return "#CC79A7";
  if (law.find("dynamic") != std::string::npos) return "#D55E00";
  if (law.find("quasi_static") != std::string::npos) return "#0072B2";
  return kPalette[4 + StableHash(law) % 3];
}

std::string ColourSoilLine(const std::string& colour, const std::string& soil_name) {
  return "lw 2.5 lc rgb '" + colour + "' dt " + std::to_string(SoilDash(soil_name));
}

std::string PadSoilLine(const std::string& pad_name, const std::string& soil_name) {
  return ColourSoilLine(PadColour(pad_name), soil_name);
}

}  // namespace touchdown::io

#include "drop_tests/io/figure_style.h"

#include <array>
#include <cstdint>

#include "drop_tests/io/plot_runner.h"

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

std::string Figure(const std::string& base, const std::string& body, FigureSize size, bool svg) {
  const std::string dims = " size " + std::to_string(size.width) + "," + std::to_string(size.height);
  std::string script = "reset\n" + Style() + "set terminal pngcairo noenhanced" + dims + " font 'sans,16'\nset output " +
                       GnuplotQuote(base + ".png") + "\n" + body;
  if (svg)
    script += "set terminal svg noenhanced" + dims + " font 'sans,16'\nset output " + GnuplotQuote(base + ".svg") + "\n" + body;
  return script + "unset output\n";
}

std::string FigurePng(const std::string& base) { return base + ".png"; }

std::string SeriesColour(int k) { return kPalette[static_cast<size_t>(k) % kPalette.size()]; }

std::string PadColour(const std::string& pad_name) {
  for (const Named& n : kPadColours)
    if (pad_name == n.name) return kPalette[n.index];
  // Other pads: the colours no catalogue pad holds.
  const size_t free_colours = kPalette.size() - kPadColours.size();
  return kPalette[kPadColours.size() + StableHash(pad_name) % free_colours];
}

int SoilDash(const std::string& soil_name) {
  if (soil_name.ends_with("_lp")) return 1;
  if (soil_name.ends_with("_cp")) return 2;
  return 3 + static_cast<int>(StableHash(soil_name) % 3);
}

std::string PadSoilLine(const std::string& pad_name, const std::string& soil_name) {
  return "lw 2.5 lc rgb '" + PadColour(pad_name) + "' dt " + std::to_string(SoilDash(soil_name));
}

}  // namespace touchdown::io

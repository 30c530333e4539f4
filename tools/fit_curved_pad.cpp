// Chooses the curved pad's exponential profile u = a0 (exp(a1 x) - 1), which the paper does
// not print. Assumption: the curve rises from the lowest point to the top of the pad at the
// rim (u(r) = h, no vertical wall), which fixes a0 = h / (exp(a1 r) - 1). The one free
// parameter a1 is fitted so that the RFT curved/flat penetration ratio equals the paper's
// simulated 2.0 (flat pad, same zeta, 1.6 kg at 1.0 m/s on fjs1_lp in vacuum). The paper's RFT is
// quasi-static, so the soil's own dynamic term is switched off for the fit: the profile is the
// geometry that makes the paper's model give the paper's number, whatever model touchdown runs.
//
//   fit_curved_pad [target_ratio=2.0] [speed_m_s=1.0] [soil=fjs1_lp]
// prints a0_mm and a1_per_mm for data/pads/curved.yaml.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "rft/input_error.h"

using namespace touchdown;

namespace {
// A number argument, whole (no trailing text) and finite; exit 2 naming it otherwise.
double NumberArgument(const char* text, const char* name) {
  size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || text[used] != '\0' || !std::isfinite(v)) {
    std::fprintf(stderr, "fit_curved_pad: %s: not a finite number: '%s'\n", name, text);
    std::exit(2);
  }
  return v;
}
}  // namespace

int main(int argc, char** argv) try {
  const double target = argc > 1 ? NumberArgument(argv[1], "target_ratio") : 2.0;
  const double speed = argc > 2 ? NumberArgument(argv[2], "speed_m_s") : 1.0;
  const std::string soil_name = argc > 3 ? argv[3] : "fjs1_lp";
  if (!(target > 1.0)) {
    std::fprintf(stderr, "fit_curved_pad: target_ratio: must exceed 1 (the curved pad sinks deeper), got %g\n", target);
    return 2;
  }
  const touchdown::io::PadSpec flat = touchdown::io::LoadPad("flat");
  rft::SoilParameters soil = touchdown::io::LoadSoil(soil_name);
  soil.dynamic_term = false;
  touchdown::drop::DropConditions c;
  c.impact_speed_m_s = speed;
  touchdown::drop::ValidateConditions(c, "argument speed_m_s");  // the range every loader checks
  const double flat_depth = touchdown::drop::RunDrop(touchdown::drop::ResolveDrop(flat, soil, c)).result.final_penetration_m;
  const double r = flat.profile.radius_m(), h = flat.profile.thickness_m();

  auto ratio = [&](double a1) {
    touchdown::io::PadSpec curved = flat;
    curved.profile = geom::MakeExponentialProfile(r, h, h / std::expm1(a1 * r), a1, 400);
    return touchdown::drop::RunDrop(touchdown::drop::ResolveDrop(curved, soil, c)).result.final_penetration_m / flat_depth;
  };
  // The ratio falls as a1 grows (the pad flattens towards a rounded-edge flat pad).
  double lo = 1.0, hi = 2000.0;  // [1/m]
  if (!(ratio(lo) > target && ratio(hi) < target)) {
    std::fprintf(stderr, "target ratio %.3f not bracketed: %.3f .. %.3f\n", target, ratio(lo), ratio(hi));
    return 1;
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = std::sqrt(lo * hi);
    (ratio(mid) > target ? lo : hi) = mid;
  }
  const double a1 = std::sqrt(lo * hi);
  std::printf("a1_per_mm: %.6f\na0_mm: %.6f\nratio: %.4f\nflat_depth_mm: %.4f\n", a1 * 1e-3,
              h / std::expm1(a1 * r) * 1e3, ratio(a1), flat_depth * 1e3);
  return 0;
} catch (const touchdown::InputError& e) {
  std::fprintf(stderr, "fit_curved_pad: %s\n", e.what());
  return 2;
}

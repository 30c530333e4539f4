// Drops on Bekker soils (rft/bekker_law.h) through the drop factory: the rig's stop depth against
// the energy balance, the free pad against the rig, and a Bekker soil file through the catalogue.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/catalog/catalog.h"
#include "rft/bekker_law.h"
#include "rft/input_error.h"

namespace touchdown::drop {
namespace {

// The stop depth d of a flat pad (area A, modulus K = k_c / b + k_phi) dropped at v:
// m v^2 / 2 + m g d = A K d^(n+1) / (n+1), solved by bisection (the right side outgrows the left).
double BekkerEnergyBalanceDepth(double m, double g, double v, double area, double modulus, double n) {
  const auto excess = [&](double d) {
    return area * modulus * std::pow(d, n + 1) / (n + 1) - m * g * d - 0.5 * m * v * v;
  };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

DropConditions BekkerDropConditions(double speed, double gravity) {
  DropConditions c;
  c.impact_speed_m_s = speed;
  c.gravity_m_s2 = gravity;
  return c;
}

TEST(BekkerDrop, RigStopDepthFromTheEnergyBalance) {
  const io::PadSpec flat = io::LoadPad("flat");
  const double r = flat.profile.radius_m(), area = std::numbers::pi * r * r;
  // n = 1 (lunar), n = 0.63 with k_c = 0 (Toyoura), n = 0.9649 with both moduli (soft sand, in air).
  for (const char* name : {"lunar_nominal_bekker", "toyoura_bekker", "soft_sand_bekker"}) {
    const rft::SoilParameters soil = io::LoadSoil(name);
    ASSERT_EQ(soil.rft_law_3d, rft::LawKind::kBekker);
    for (const auto& [speed, gravity] : {std::pair{1.0, 1.62}, std::pair{2.5, 9.81}}) {
      DropRunOptions options;
      options.rig.integrator.rtol = 1e-10;
      options.rig.integrator.atol = 1e-13;
      const PadDrop d = RunDrop(ResolveDrop(flat, soil, BekkerDropConditions(speed, gravity), options));
      const double expected = BekkerEnergyBalanceDepth(flat.mass_kg, gravity, speed, area,
                                                       rft::BekkerModulus(soil.bekker, r), soil.bekker.n);
      EXPECT_NEAR(d.result.final_penetration_m, expected, 1e-6 * expected) << name << " v " << speed;
      EXPECT_EQ(d.result.rest_creep_m, 0.0);
      EXPECT_EQ(SummaryJson(d)["law"], "bekker");
    }
  }
}

TEST(BekkerDrop, RigOnLunarGravityIsTheSameSoil) {
  // Bekker's moduli do not scale with gravity: a slow drop's stop depth differs between the Moon
  // and the Earth only through the weight's work m g d (RFT's zeta would change with g too).
  const io::PadSpec flat = io::LoadPad("flat");
  const rft::SoilParameters soil = io::LoadSoil("lunar_nominal_bekker");
  const double moon = RunDrop(ResolveDrop(flat, soil, BekkerDropConditions(1.0, 1.62))).result.final_penetration_m;
  const double earth = RunDrop(ResolveDrop(flat, soil, BekkerDropConditions(1.0, 9.81))).result.final_penetration_m;
  EXPECT_GT(earth, moon);
  const double area = std::numbers::pi * 0.05 * 0.05, k = rft::BekkerModulus(soil.bekker, 0.05);
  EXPECT_NEAR(moon, BekkerEnergyBalanceDepth(1.6, 1.62, 1.0, area, k, 1.0), 1e-5 * moon);
}

TEST(BekkerDrop, FreeFlatPadAgreesWithTheRig) {
  const io::PadSpec flat = io::LoadPad("flat");
  for (const char* name : {"lunar_nominal_bekker", "toyoura_bekker"}) {
    const rft::SoilParameters soil = io::LoadSoil(name);
    const PadDrop rig = RunDrop(ResolveDrop(flat, soil, BekkerDropConditions(1.0, 1.62)));
    DropConditions c = BekkerDropConditions(1.0, 1.62);
    c.free = true;
    const PadDrop free = RunDrop(ResolveDrop(flat, soil, c));
    ASSERT_TRUE(free.free);
    EXPECT_EQ(rig.law_3d, rft::LawKind::kBekker);
    EXPECT_TRUE(rig.contact_model.empty());
    EXPECT_EQ(free.law_3d, rft::LawKind::kBekker);
    EXPECT_EQ(free.contact_model, "bekker");
    // The free pad's revolved polygon has a slightly smaller footprint than the rig's circle (and
    // its b with it): agreement to the polygon's area.
    EXPECT_NEAR(free.result.final_penetration_m, rig.result.final_penetration_m,
                1e-3 * rig.result.final_penetration_m)
        << name;
    // Both peaks are read from the solution (between samples too): the same to the polygon's area.
    EXPECT_NEAR(free.result.peak_force_N, rig.result.peak_force_N, 5e-3 * rig.result.peak_force_N) << name;
    EXPECT_NEAR(free.free->final_tilt_deg, 0.0, 1e-9);
  }
}

TEST(BekkerDrop, FreePadSlidingFeelsTheShear) {
  // A free pad landing with horizontal speed: the Janosi shear slows it; without friction and
  // cohesion it slides further.
  const io::PadSpec flat = io::LoadPad("flat");
  rft::SoilParameters soil = io::LoadSoil("lunar_nominal_bekker");
  DropConditions c = BekkerDropConditions(1.0, 1.62);
  c.horizontal_speed_m_s = 0.5;
  const PadDrop with_shear = RunDrop(ResolveDrop(flat, soil, c));
  soil.bekker.friction_angle_rad = 0.0;
  soil.bekker.cohesion_Pa = 0.0;
  const PadDrop frictionless = RunDrop(ResolveDrop(flat, soil, c));
  ASSERT_TRUE(with_shear.free && frictionless.free);
  EXPECT_GT(frictionless.free->horizontal_travel_m, 1.2 * with_shear.free->horizontal_travel_m);
}

TEST(BekkerDrop, LawAskedForOnAnRftSoilNeedsItsBlock) {
  const io::PadSpec flat = io::LoadPad("flat");
  DropConditions c = BekkerDropConditions(1.0, 1.62);
  c.law_3d = rft::LawKind::kBekker;
  try {
    RunDrop(ResolveDrop(flat, io::LoadSoil("fjs1_lp"), c));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bekker"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(RunsOnBekker(io::LoadSoil("fjs1_lp"), std::nullopt));
  EXPECT_TRUE(RunsOnBekker(io::LoadSoil("lunar_nominal_bekker"), std::nullopt));
}

}  // namespace
}  // namespace touchdown::drop

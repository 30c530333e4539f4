// The drop factory (drop_tests/drop/drop_factory.h): the zeta override and its gravity scaling
// against the closed form, and RunDrop's drops made of the factory's pieces bit for bit.
#include "drop_tests/drop/drop_factory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/model/contact_model.h"
#include "drop_tests/model/effects.h"
#include "footpad_geom/axisymmetric_profile.h"
#include "rft/ground.h"

namespace touchdown::drop {
namespace {

constexpr double kMoonG = 1.62;

TEST(DropFactory, ZetaOverrideScalesWithGravityFromTheSoilsReference) {
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  ASSERT_GT(soil.zeta_N_m3, 0.0);
  // No override: the catalogue zeta, zeta g / g_ref.
  EXPECT_EQ(ZetaAtGravity(DropSoil(soil, std::nullopt, std::nullopt), kMoonG),
            soil.zeta_N_m3 * kMoonG / soil.reference_gravity_m_s2);
  // An override is stated at the soil's reference gravity, as the catalogue's: scaled alike.
  const rft::SoilParameters over = DropSoil(soil, 2.5e6, rft::Atmosphere::kAir);
  EXPECT_EQ(over.zeta_N_m3, 2.5e6);
  EXPECT_EQ(over.atmosphere, rft::Atmosphere::kAir);
  EXPECT_EQ(over.reference_gravity_m_s2, soil.reference_gravity_m_s2);
  EXPECT_EQ(ZetaAtGravity(over, kMoonG), 2.5e6 * kMoonG / soil.reference_gravity_m_s2);
  EXPECT_EQ(ZetaAtGravity(over, soil.reference_gravity_m_s2), 2.5e6);
  // The drop conditions resolve it the same way.
  DropConditions c;
  c.gravity_m_s2 = kMoonG;
  c.zeta_N_m3 = 2.5e6;
  EXPECT_EQ(EffectiveZeta(soil, c), 2.5e6 * kMoonG / soil.reference_gravity_m_s2);
}

TEST(DropFactory, RigResponseIsQuasiStaticRftAtTheDropsZeta) {
  // A flat disc with a negligible wall: F = zeta(g) pi r^2 d (Li 2013, straight down) to 1e-6.
  const double r = 0.05, d = 0.01;
  const auto intrusion = MakeRigIntrusion(geom::MakeFlatProfile(r, 1e-7));
  rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  soil = DropSoil(soil, 3.0e6, std::nullopt);
  const pad::EffectSoilResponse response = MakeRigResponse(*intrusion, soil, kMoonG, {});
  const double zeta_g = 3.0e6 * kMoonG / soil.reference_gravity_m_s2;
  const double closed_form = zeta_g * std::numbers::pi * r * r * d;
  EXPECT_NEAR(response.QuasiStaticForce(d), closed_form, 1e-6 * closed_form);
  EXPECT_EQ(response.QuasiStaticForce(d), intrusion->VerticalForce(d, zeta_g));
}

// A soil's own dynamic term is the effect library's inertial_drag at the same lambda, on the rig
// and on the free pad alike, and a model's inertial_drag replaces it.
TEST(DropFactory, SoilsDynamicTermIsInertialDragOnRigAndFreePad) {
  const io::PadSpec pad = io::LoadPad("flat");
  rft::SoilParameters plain = io::LoadSoil("fjs1_lp");
  plain.dynamic_term = false;  // the shipped soil carries lambda 1.1
  rft::SoilParameters dynamic = plain;
  dynamic.dynamic_term = true;
  dynamic.dynamic_lambda = 0.8;
  for (const bool free : {false, true}) {
    SCOPED_TRACE(free ? "free pad" : "rig");
    DropConditions c;
    c.impact_speed_m_s = 1.5;
    c.free = free;
    DropConditions with_effect = c;
    with_effect.effects.inertial_lambda = 0.8;
    const PadDrop a = RunDrop(ResolveDrop(pad, dynamic, c)), b = RunDrop(ResolveDrop(pad, plain, with_effect));
    EXPECT_EQ(a.result.final_penetration_m, b.result.final_penetration_m);
    EXPECT_EQ(a.result.peak_force_N, b.result.peak_force_N);
    EXPECT_LT(a.result.final_penetration_m, RunDrop(ResolveDrop(pad, plain, c)).result.final_penetration_m);
    DropConditions replaced = c;
    replaced.effects.inertial_replaces_soil = true;  // a model's inertial_drag at lambda 0
    EXPECT_EQ(RunDrop(ResolveDrop(pad, dynamic, replaced)).result.final_penetration_m,
              RunDrop(ResolveDrop(pad, plain, c)).result.final_penetration_m);
  }
}

TEST(DropFactory, RunDropIsTheFactorysRigDropBitForBit) {
  const io::PadSpec pad = io::LoadPad("curved");
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  DropConditions c;
  c.impact_speed_m_s = 1.1;
  c.mass_kg = 2.0;
  c.gravity_m_s2 = kMoonG;
  c.zeta_N_m3 = 2.2e6;
  c.atmosphere = rft::Atmosphere::kAir;
  model::Effect damping{"rate_damping", {}};
  for (const model::EffectParameterInfo& q : model::FindEffect("rate_damping").parameters)
    damping.values.push_back(2 * q.start + q.scale);
  c.effects = model::MakeEffectTerms({damping});
  const PadDrop drop = RunDrop(ResolveDrop(pad, soil, c));

  const rft::SoilParameters drop_soil = DropSoil(soil, c.zeta_N_m3, c.atmosphere);
  const auto intrusion = MakeRigIntrusion(pad.profile);
  const pad::EffectSoilResponse response = MakeRigResponse(*intrusion, drop_soil, kMoonG, c.effects);
  const pad::RigDropResult own = pad::RunRigDrop({{2.0}, &response, {kMoonG, 1.1}, {}});
  ASSERT_EQ(drop.result.trace.size(), own.trace.size());
  ASSERT_GT(own.trace.size(), 10u);
  for (size_t i = 0; i < own.trace.size(); ++i) {
    EXPECT_EQ(drop.result.trace[i].penetration_m, own.trace[i].penetration_m) << i;
    EXPECT_EQ(drop.result.trace[i].force_N, own.trace[i].force_N) << i;
  }
  EXPECT_EQ(drop.result.final_penetration_m, own.final_penetration_m);
  EXPECT_EQ(drop.zeta_effective_N_m3, ZetaAtGravity(drop_soil, kMoonG));
  // The record keeps the catalogue zeta and the drop's atmosphere.
  EXPECT_EQ(drop.soil.zeta_N_m3, soil.zeta_N_m3);
  EXPECT_TRUE(drop.in_air());
}

TEST(DropFactory, FreeDropRunsTheFactorysLaw) {
  const io::PadSpec pad = io::LoadPad("flat");
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  DropConditions c;
  c.impact_speed_m_s = 0.8;
  c.gravity_m_s2 = kMoonG;
  c.zeta_N_m3 = 2.0e6;
  c.tilt_rad = 0.1;
  const PadDrop drop = RunDrop(ResolveDrop(pad, soil, c));
  ASSERT_TRUE(drop.free.has_value());
  const auto law = model::MakeContactModel({.soil = DropSoil(soil, c.zeta_N_m3, std::nullopt), .gravity_m_s2 = kMoonG});
  EXPECT_EQ(drop.contact_model, law.name());
  EXPECT_EQ(drop.law_3d, law.law->kind());
  pad::FreeDropInput in;
  in.impact_speed_m_s = 0.8;
  in.tilt_rad = 0.1;
  in.gravity_m_s2 = kMoonG;
  const pad::FreeDropResult own = pad::RunFreeDrop({&pad.body, rft::UniformTerrain("soil", law), in, {}});
  EXPECT_EQ(drop.free->final_penetration_m, own.final_penetration_m);
  EXPECT_EQ(drop.free->peak_force_N, own.peak_force_N);
  EXPECT_EQ(drop.free->final_tilt_deg, own.final_tilt_deg);
}

}  // namespace
}  // namespace touchdown::drop

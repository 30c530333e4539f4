// Bekker pressure-sinkage and Janosi-Hanamoto shear (rft/bekker_law.h) against their closed forms,
// through the pure functions and through the element contact (rft/contact_wrench.h).
#include "rft/bekker_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rft/contact_wrench.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

constexpr double kBekkerPi = std::numbers::pi;

// The commonly quoted lunar soil (docs/bekker_soil.md), with n given per test.
BekkerParameters LunarBekker(double n) {
  BekkerParameters b;
  b.n = n;
  b.k_c_N_m_n1 = 1.4e3;
  b.k_phi_N_m_n2 = 820e3;
  b.cohesion_Pa = 170.0;
  b.friction_angle_rad = 35.0 * kBekkerPi / 180.0;
  b.shear_modulus_K_m = 0.018;
  return b;
}

SoilParameters BekkerSoil(double n) {
  SoilParameters s;
  s.name = "bekker_test";
  s.rft_law_3d = LawKind::kBekker;
  s.bekker = LunarBekker(n);
  return s;
}

// A flat circular plate: a regular polygon of `sectors` sides, radius r, with its side wall and top.
struct BekkerPlate {
  SurfaceElements surface;
  double area_m2;  // the polygon's area
};
BekkerPlate FlatBekkerPlate(double r, int sectors) {
  return {testing::MakeRevolvedPad(testing::FlatProfile(r, 0.01), sectors),
          0.5 * sectors * r * r * std::sin(2.0 * kBekkerPi / sectors)};
}

ContactWrench BekkerWrench(const SurfaceElements& s, const SoilContactModel& m, double depth_m,
                           const Eigen::Vector3d& v_W) {
  PadKinematics k;
  k.p_WB = Eigen::Vector3d(0, 0, -depth_m);
  k.v_WB_W = v_W;
  return ComputeContactWrench(s, k, PlaneGround(), *m.law, m.pad_terms);
}

// The name outputs print carries no "+depth_exponent" for Bekker's own z^n (the law's kind says so).
TEST(BekkerLaw, ContactModelIsOfKindBekkerAndNamedWithoutDepthExponent) {
  const BekkerPlate plate = FlatBekkerPlate(0.05, 64);
  const SoilContactModel m = MakeSoilContactModel(LawKind::kBekker, BekkerSoil(1.1), 1.62, {}, &plate.surface);
  EXPECT_EQ(m.law->kind(), LawKind::kBekker);
  EXPECT_TRUE(m.pad_terms.has_power_depth());
  EXPECT_EQ(m.name(), "bekker");
}

TEST(BekkerLaw, FootprintDimensionOfMeshes) {
  const BekkerPlate plate = FlatBekkerPlate(0.05, 128);
  // Walls and the top face are not footprint: b is the radius of the polygon's equal-area circle.
  EXPECT_NEAR(FootprintArea(plate.surface), plate.area_m2, 1e-15);
  EXPECT_NEAR(BekkerPlateB(plate.surface), std::sqrt(plate.area_m2 / kBekkerPi), 1e-15);
  EXPECT_NEAR(BekkerPlateB(plate.surface), 0.05, 0.05 * 3e-4);  // the circle's radius, to the 128-gon
  // A 0.1 m square plate (a box): b = s / sqrt(pi), between its half side and its half diagonal.
  const SurfaceElements box = testing::MakeBox({-0.05, -0.05, 0.0}, {0.05, 0.05, 0.02}, 3);
  EXPECT_NEAR(BekkerPlateB(box), 0.1 / std::sqrt(kBekkerPi), 1e-15);
}

TEST(BekkerLaw, FlatCircularPlatePushedStraightDown) {
  const double r = 0.05;
  const BekkerPlate plate = FlatBekkerPlate(r, 256);
  const double b = BekkerPlateB(plate.surface);
  for (const double n : {1.0, 0.8, 1.3}) {
    const SoilContactModel m = MakeSoilContactModel(LawKind::kBekker, BekkerSoil(n), 1.62, {}, &plate.surface);
    for (const double z : {0.001, 0.004, 0.009}) {
      const ContactWrench w = BekkerWrench(plate.surface, m, z, {0, 0, -0.7});
      const BekkerParameters p = LunarBekker(n);
      // F = A (k_c / b + k_phi) z^n for the polygon (exact but for rounding) ...
      const double exact = plate.area_m2 * (p.k_c_N_m_n1 / b + p.k_phi_N_m_n2) * std::pow(z, n);
      EXPECT_NEAR(w.force_W.z(), exact, 1e-11 * exact) << "n " << n << " z " << z;
      EXPECT_NEAR(w.force_W.x(), 0.0, 1e-9 * exact);
      // ... and pi r^2 (k_c / r + k_phi) z^n for the circle, to the polygon's 1e-4.
      const double circle = kBekkerPi * r * r * (p.k_c_N_m_n1 / r + p.k_phi_N_m_n2) * std::pow(z, n);
      EXPECT_NEAR(w.force_W.z(), circle, 2e-4 * circle);
      EXPECT_NEAR(w.force_W.z(), plate.area_m2 * BekkerPressure(p, b, z), 1e-11 * exact);
    }
  }
}

TEST(BekkerLaw, GravityDoesNotEnter) {
  const BekkerPlate plate = FlatBekkerPlate(0.05, 64);
  const SoilContactModel moon = MakeSoilContactModel(LawKind::kBekker, BekkerSoil(1.0), 1.62, {}, &plate.surface);
  const SoilContactModel earth = MakeSoilContactModel(LawKind::kBekker, BekkerSoil(1.0), 9.81, {}, &plate.surface);
  EXPECT_EQ(BekkerWrench(plate.surface, moon, 0.005, {0, 0, -1}).force_W.z(),
            BekkerWrench(plate.surface, earth, 0.005, {0, 0, -1}).force_W.z());
}

TEST(BekkerLaw, StaticSinkageCarriesTheWeight) {
  const BekkerPlate plate = FlatBekkerPlate(0.05, 128);
  const double b = BekkerPlateB(plate.surface);
  for (const double n : {1.0, 0.7}) {
    const BekkerParameters p = LunarBekker(n);
    const SoilContactModel m = MakeSoilContactModel(LawKind::kBekker, BekkerSoil(n), 1.62, {}, &plate.surface);
    const double weight_N = 40.0;
    const double z = BekkerStaticSinkage(p, b, plate.area_m2, weight_N);
    // The closed form z = (W / (A (k_c / b + k_phi)))^(1/n) ...
    EXPECT_NEAR(z, std::pow(weight_N / (plate.area_m2 * (p.k_c_N_m_n1 / b + p.k_phi_N_m_n2)), 1.0 / n), 1e-15);
    // ... is where the contact carries W: bisect the contact's force for W.
    double lo = 0.0, hi = 0.05;
    for (int i = 0; i < 80; ++i) {
      const double mid = 0.5 * (lo + hi);
      (BekkerWrench(plate.surface, m, mid, {0, 0, -1e-3}).force_W.z() < weight_N ? lo : hi) = mid;
    }
    EXPECT_NEAR(0.5 * (lo + hi), z, 1e-12 * z) << "n " << n;
  }
}

TEST(BekkerLaw, JanosiShearClosedForm) {
  const BekkerParameters p = LunarBekker(1.0);
  const double pressure = 5e3;
  const double strength = p.cohesion_Pa + pressure * std::tan(p.friction_angle_rad);
  EXPECT_EQ(JanosiShearStress(p, pressure, 0.0), 0.0);
  EXPECT_NEAR(JanosiShearStress(p, pressure, p.shear_modulus_K_m), strength * (1.0 - std::exp(-1.0)), 1e-12 * strength);
  EXPECT_NEAR(JanosiShearStress(p, pressure, 1.0), strength, 1e-12 * strength);
  // A plate of area A dragged at constant depth (pressure p) at speed v: j = v t, the drag
  // F(t) = A (c + p tan phi)(1 - exp(-v t / K)), and the work over a travel L is
  // A (c + p tan phi)(L - K (1 - exp(-L / K))). Simpson's rule over the law must give it.
  const double area = 0.0079, L = 0.05;
  const int steps = 2000;
  double work = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double w = (i == 0 || i == steps) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    work += w * area * JanosiShearStress(p, pressure, L * i / steps);
  }
  work *= L / steps / 3.0;
  const double closed = area * strength * (L - p.shear_modulus_K_m * (1.0 - std::exp(-L / p.shear_modulus_K_m)));
  EXPECT_NEAR(work, closed, 1e-12 * closed);
}

TEST(BekkerLaw, PlateDraggedAtConstantDepthFeelsTheMobilisedShear) {
  const BekkerPlate plate = FlatBekkerPlate(0.05, 128);
  const double b = BekkerPlateB(plate.surface), z = 0.004;
  const BekkerParameters p = LunarBekker(1.0);
  const SoilContactModel m = MakeSoilContactModel(LawKind::kBekker, BekkerSoil(1.0), 1.62, {}, &plate.surface);
  const double pressure = BekkerPressure(p, b, z);
  // Sliding along +x at constant depth: the footprint carries the pressure and the fully
  // mobilised Janosi shear A (c + p tan phi) against the slip (the j -> infinity limit).
  const ContactWrench w = BekkerWrench(plate.surface, m, z, {0.3, 0, 0});
  const double shear = plate.area_m2 * JanosiShearStress(p, pressure, 1e3);
  EXPECT_NEAR(w.force_W.z(), plate.area_m2 * pressure, 1e-11 * plate.area_m2 * pressure);
  // The leading half of the side wall adds its bulldozing pressure against +x: part of F_x.
  const double wall = 2.0 * 0.05 * (p.k_c_N_m_n1 / b + p.k_phi_N_m_n2) * z * z / 2.0;
  EXPECT_NEAR(w.force_W.x(), -shear - wall, 2e-3 * (shear + wall));
  // Below the regularisation speed the shear on a footprint element grows linearly with the slip.
  const BekkerLaw3D law(p, b);
  const Eigen::Vector3d down(0, 0, -1);
  const double tan_phi = std::tan(p.friction_angle_rad);
  EXPECT_NEAR(law.StressPerDepth(down, {0.3, 0, -0.1}).x(), -law.modulus() * tan_phi, 1e-9);
  EXPECT_NEAR(law.StressPerDepth(down, {0.5e-3, 0, -0.1}).x(), -0.5 * law.modulus() * tan_phi, 1e-9);
  EXPECT_NEAR(law.DynamicStress(down, {0.5e-3, 0, -0.1}).x(), -0.5 * p.cohesion_Pa, 1e-12);
  EXPECT_EQ(law.DynamicStress(down, {0, 0, -0.1}).x(), 0.0);  // straight down: no slip, no shear
  // A wall has no footprint: pressure only.
  EXPECT_EQ(law.StressPerDepth({1, 0, 0}, {0.3, 0, 0}), Eigen::Vector3d(-law.modulus(), 0, 0));
}

TEST(BekkerLaw, FactoryChecksTheBekkerBlock) {
  SoilParameters s = BekkerSoil(1.0);
  const auto message = [&](double b) {
    try {
      MakeStressLaw3D(LawKind::kBekker, s, 9.81, b);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(0.05), "no error");
  EXPECT_NE(message(0.0).find("footprint dimension b"), std::string::npos);
  s.bekker.shear_modulus_K_m = 0.0;
  EXPECT_NE(message(0.05).find("bekker.shear_modulus_K_mm"), std::string::npos);
  s = BekkerSoil(1.0);
  s.bekker.n = -1.0;
  EXPECT_NE(message(0.05).find("bekker.n"), std::string::npos);
  s = BekkerSoil(1.0);
  EffectTerms terms;
  terms.depth_exponent = 1.2;
  const BekkerPlate plate = FlatBekkerPlate(0.05, 64);
  EXPECT_THROW(MakeSoilContactModel(LawKind::kBekker, s, 9.81, terms, &plate.surface), InputError);
  // The contact model takes b from the pad it is given: a bekker law without one is refused.
  EXPECT_NO_THROW(MakeSoilContactModel(LawKind::kBekker, s, 9.81, {}, &plate.surface));
  try {
    MakeSoilContactModel(LawKind::kBekker, s, 9.81, {});
    ADD_FAILURE() << "no error without a pad";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("footprint dimension b"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace touchdown::rft

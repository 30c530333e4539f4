// Janosi's shear displacement j as a state of the free pad (docs/bekker_soil.md): the shear of a
// Bekker soil grows as 1 - exp(-j / K) with the pad's slip, through the real free-pad dynamics;
// energy still balances; j resets at lift-off; RFT soils keep their 14 states.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "footpad_geom/axisymmetric_profile.h"
#include "footpad_geom/revolve.h"
#include "lander/pad/free_drop.h"
#include "lander/pad/free_pad_dynamics.h"
#include "rft/bekker_law.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"
#include "fixtures/paper_soils.h"

namespace touchdown::pad {
namespace {

// data/soils/lunar_nominal_bekker.yaml: n = 1, k_c = 1.4 kN/m^2, k_phi = 820 kN/m^3, c = 0.17 kPa,
// phi = 35 deg, K = 18 mm.
rft::SoilParameters JanosiLunarSoil() {
  rft::SoilParameters s;
  s.name = "lunar_nominal_bekker";
  s.rft_law_3d = rft::LawKind::kBekker;
  s.bekker.n = 1.0;
  s.bekker.k_c_N_m_n1 = 1.4e3;
  s.bekker.k_phi_N_m_n2 = 820e3;
  s.bekker.cohesion_Pa = 170.0;
  s.bekker.friction_angle_rad = 35.0 * units::kDeg;
  s.bekker.shear_modulus_K_m = 0.018;
  return s;
}

geom::PadBody JanosiFlatPlate() {  // data/pads/flat.yaml: 100 mm across, 16 mm thick, 1.6 kg
  const geom::AxisymmetricProfile profile = geom::MakeFlatProfile(0.05, 0.016);
  return geom::RevolveProfileToBody(profile, 32, 1.6, Eigen::Vector3d(0.0, 0.0, 0.008));
}

rft::SoilContactModel JanosiModel(const rft::SoilParameters& soil, const geom::PadBody& body) {
  return rft::MakeSoilContactModel(rft::LawKind::kBekker, soil, 1.62, {}, &body.surface);
}

// A level plate held at depth d, dragged along +x at V, after a shear displacement j: the state.
Eigen::VectorXd DraggedPlate(const FreePadDynamics& pad, double depth, double speed, double j) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(pad.size());
  y[FreePadStateLayout::quat_WB()] = 1.0;
  y[FreePadStateLayout::v_WC_W()] = speed;
  y[FreePadStateLayout::shear()] = j;
  y[FreePadStateLayout::p_WC() + 2] += pad.Depth(pad.PoseOf(y)) - depth;
  return y;
}

TEST(JanosiShearState, PlateDraggedAtConstantDepthRampsAsJanosi) {
  const geom::PadBody body = JanosiFlatPlate();
  const rft::SoilParameters soil = JanosiLunarSoil();
  const rft::SoilContactModel model = JanosiModel(soil, body);
  ASSERT_TRUE(model.has_janosi_shear());
  const rft::Terrain terrain = rft::UniformTerrain("s", model);
  const FreePadDynamics pad(body, terrain, 1.62);  // keeps a reference to the terrain
  FreePadData data;
  ASSERT_EQ(pad.size(), FreePadStateLayout(true).size);
  const double depth = 0.01, speed = 0.3, K = soil.bekker.shear_modulus_K_m;
  // Fully mobilised shear on the bottom (Bekker's pressure at depth d on the footprint A):
  // A (c + p tan phi). The walls carry no shear (no footprint) but bulldoze, whatever j is.
  const double A = rft::FootprintArea(body.surface);
  const double p = rft::BekkerPressure(soil.bekker, rft::BekkerPlateB(body.surface), depth);
  const double full = A * (soil.bekker.cohesion_Pa + p * std::tan(soil.bekker.friction_angle_rad));
  Eigen::VectorXd ydot(pad.size());
  Derivative(pad, data, DraggedPlate(pad, depth, speed, 0.0), ydot);
  const double bulldozing = body.mass_kg * ydot[FreePadStateLayout::v_WC_W()];  // F_x at j = 0: the leading wall alone
  EXPECT_LT(bulldozing, 0.0);
  for (const double j : {0.1 * K, 0.5 * K, K, 2.0 * K, 5.0 * K, 20.0 * K}) {
    Derivative(pad, data, DraggedPlate(pad, depth, speed, j), ydot);
    const double shear = -(body.mass_kg * ydot[FreePadStateLayout::v_WC_W()] - bulldozing);
    EXPECT_NEAR(shear, full * -std::expm1(-j / K), 1e-9 * full) << "j = " << j;
    EXPECT_DOUBLE_EQ(ydot[FreePadStateLayout::shear()], speed);  // j' = |slip| in contact
  }
  // Out of the soil j does not grow.
  Eigen::VectorXd above = DraggedPlate(pad, -0.01, speed, K);
  Derivative(pad, data, above, ydot);
  EXPECT_EQ(ydot[FreePadStateLayout::shear()], 0.0);
}

TEST(JanosiShearState, RftSoilsKeepTheirFourteenStates) {
  const geom::PadBody body = JanosiFlatPlate();
  const rft::Terrain rft_terrain = rft::UniformTerrain("s", test::Fjs1Law(false));
  EXPECT_EQ(FreePadDynamics(body, rft_terrain, 9.81).size(), FreePadStateLayout(false).size);
  rft::SoilParameters frictionless = JanosiLunarSoil();
  frictionless.bekker.cohesion_Pa = 0.0;
  frictionless.bekker.friction_angle_rad = 0.0;
  EXPECT_FALSE(JanosiModel(frictionless, body).has_janosi_shear());
  const rft::Terrain bekker_terrain = rft::UniformTerrain("s", JanosiModel(frictionless, body));
  EXPECT_EQ(FreePadDynamics(body, bekker_terrain, 1.62).size(), FreePadStateLayout(false).size);
}

TEST(JanosiShearState, SlidingDropBalancesItsEnergy) {
  const geom::PadBody body = JanosiFlatPlate();
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.horizontal_speed_m_s = 0.3;
  in.tilt_rad = 3.0 * units::kDeg;
  in.gravity_m_s2 = 1.62;
  const FreeDropResult r =
      RunFreeDrop({&body, rft::UniformTerrain("s", JanosiModel(JanosiLunarSoil(), body)), in, {}});
  const double input = r.impact_energy_J + r.gravity_work_J;
  EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, input, 1e-5 * input);
  EXPECT_GT(r.horizontal_travel_m, 1e-3);
  // j is the slip of the reference point: the travel of the centre of mass, to the little the
  // tilt's righting moves the two apart (measured: 6.422 mm against 6.414 mm).
  EXPECT_NEAR(r.final_shear_displacement_m, r.horizontal_travel_m, 0.01 * r.horizontal_travel_m);
  EXPECT_EQ(r.lift_offs, 0);
}

// Flat ground that falls away by `drop` over a few millimetres at x = edge (smooth, so CVODE steps
// through it): a pad sliding over the edge leaves the soil.
class LedgeGround final : public rft::GroundSurface {
 public:
  LedgeGround(double edge_m, double drop_m) : edge_(edge_m), drop_(drop_m) {}
  double Height(double x_m, double) const override { return -0.5 * drop_ * (1.0 + std::tanh((x_m - edge_) / 0.002)); }

 private:
  double edge_, drop_;
};

TEST(JanosiShearState, ResetsAtLiftOff) {
  const geom::PadBody body = JanosiFlatPlate();
  FreeDropInput in;
  in.impact_speed_m_s = 0.2;
  in.horizontal_speed_m_s = 1.0;
  in.gravity_m_s2 = 1.62;
  const rft::SoilContactModel model = JanosiModel(JanosiLunarSoil(), body);
  const FreeDropResult flat = RunFreeDrop({&body, rft::UniformTerrain("s", model), in, {}});
  const FreeDropResult ledge =
      RunFreeDrop({&body, rft::UniformTerrain("s", model, std::make_shared<const LedgeGround>(0.08, 0.05)), in, {}});
  EXPECT_EQ(flat.lift_offs, 0);
  EXPECT_GE(ledge.lift_offs, 1);
  // On the flat the pad slides from touchdown to rest; past the ledge j counts only the slip after
  // the second touchdown.
  // (measured: flat j = travel = 278.5 mm; past the ledge j = 66 mm of a 249 mm travel).
  EXPECT_NEAR(flat.final_shear_displacement_m, flat.horizontal_travel_m, 1e-6);
  EXPECT_GT(ledge.final_shear_displacement_m, 0.01);
  EXPECT_LT(ledge.final_shear_displacement_m, ledge.horizontal_travel_m - 0.08);  // the 80 mm to the edge
}

}  // namespace
}  // namespace touchdown::pad

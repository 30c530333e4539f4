// The free (6-DOF) pad drop on its own: sideways travel, scaled tolerances, the first sample. The
// paper's pads and soil are built in code (the drop layer's catalogue runs are in
// tests/drop_tests/drop/free_drop_conditions_test.cpp).
#include "lander/pad/free_drop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "footpad_geom/axisymmetric_profile.h"
#include "footpad_geom/revolve.h"
#include "rft/stress_law_3d_factory.h"
#include "fixtures/paper_soils.h"

namespace touchdown::pad {
namespace {

using units::kMm;
constexpr double kPadMass_kg = 1.6;  // data/pads/{flat,curved}.yaml: mass_kg

// data/pads/flat.yaml: 100 mm diameter, 16 mm thick.
geom::AxisymmetricProfile FlatProfile() { return geom::MakeFlatProfile(50 * kMm, 16 * kMm); }

// data/pads/curved.yaml: exponential bottom u = a0 (exp(a1 x) - 1) rising 16 mm to the rim.
geom::AxisymmetricProfile CurvedProfile() {
  const double r = 50 * kMm, h = 16 * kMm, a1 = 0.031901 / kMm;
  return geom::MakeExponentialProfile(r, h, 16 * kMm / std::expm1(a1 * r), a1, 400);
}

TEST(FreeDrop, SidewaysDropTravelsAndStaysLevelEnough) {
  // A coarse revolved curved pad (fast) landing with a horizontal speed: it must come to rest,
  // travel forward (+x), balance its energy, and report its final tilt.
  const geom::AxisymmetricProfile profile = CurvedProfile();
  const geom::PadBody body = geom::RevolveProfileToBody(profile, 24, kPadMass_kg, Eigen::Vector3d(0.0, 0.0, profile.thickness_m()));
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, test::Fjs1(false), 9.81, {});
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.horizontal_speed_m_s = 0.2;
  const FreeDropResult r = RunFreeDrop({&body, rft::UniformTerrain("soil", law), in, {}});
  EXPECT_GT(r.horizontal_travel_m, 1e-3);
  EXPECT_GT(r.trace.back().horizontal_m, 0.0);
  EXPECT_GT(r.final_penetration_m, 0.0);
  EXPECT_LT(r.final_tilt_deg, 10.0);
  const double input = r.impact_energy_J + r.gravity_work_J;
  // To the integration's accuracy: 2e-5 at the default rtol 1e-6 (FreeDropOptions).
  EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, input, 1e-4 * input);
}

// The free drop's absolute tolerances are rtol times each state's scale (free_drop.cpp). A tilted
// drop with them matches a run 100 times tighter, and needs several times fewer steps than the
// scalar atol of 1e-11 (in every unit) it replaced, which resolved the wobble about the symmetric
// axis, driven by the mesh's small asymmetries, to 1e-11 rad/s.
TEST(FreeDrop, ScaledTolerancesMatchATighterRunInFewerSteps) {
  const geom::AxisymmetricProfile profile = FlatProfile();
  const geom::PadBody body = geom::RevolveProfileToBody(profile, 48, kPadMass_kg, Eigen::Vector3d(0.0, 0.0, profile.thickness_m()));
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, test::Fjs1(false), 9.81, {});
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.tilt_rad = 5.0 * std::numbers::pi / 180.0;
  FreeDropOptions defaults;
  defaults.integrator.rtol = 1e-8;  // the scales' effect as measured when they came (the default is 1e-6 now)
  const FreeDropResult r = RunFreeDrop({&body, rft::UniformTerrain("soil", law), in, defaults});
  FreeDropOptions tight = defaults;
  tight.integrator.rtol = 1e-10;
  tight.integrator.max_num_steps = 200000;
  const FreeDropResult ref = RunFreeDrop({&body, rft::UniformTerrain("soil", law), in, tight});
  FreeDropOptions scalar = defaults;
  scalar.integrator.component_atol.assign(14, 1e-11);
  scalar.integrator.max_num_steps = 200000;
  const FreeDropResult old = RunFreeDrop({&body, rft::UniformTerrain("soil", law), in, scalar});
  std::printf("[ tolerances ] steps: scaled %ld, scalar 1e-11 %ld, rtol 1e-10 %ld; depth %.7f / %.7f mm, "
              "tilt %.6f / %.6f deg\n",
              r.solver.steps, old.solver.steps, ref.solver.steps, 1e3 * r.final_penetration_m,
              1e3 * ref.final_penetration_m, r.final_tilt_deg, ref.final_tilt_deg);
  EXPECT_NEAR(r.final_penetration_m, ref.final_penetration_m, 1e-5 * ref.final_penetration_m);
  EXPECT_NEAR(r.final_tilt_deg, ref.final_tilt_deg, 1e-3 * ref.final_tilt_deg + 1e-6);
  EXPECT_NEAR(r.horizontal_travel_m, ref.horizontal_travel_m, 1e-8);
  EXPECT_NEAR(r.time_to_rest_s, ref.time_to_rest_s, 1e-6);
  EXPECT_LT(3 * r.solver.steps, old.solver.steps);
  const double input = r.impact_energy_J + r.gravity_work_J;
  EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, input, 1e-6 * input);
}

// Touchdown is t = 0 with the lowest point exactly on the surface: nothing is submerged in the
// first sample, whatever the root finder's rounding.
TEST(FreeDrop, FirstSampleIsAtTheSurface) {
  const geom::AxisymmetricProfile profile = FlatProfile();
  const geom::PadBody body = geom::RevolveProfileToBody(profile, geom::kDefaultAngularSegments, kPadMass_kg,
                                                        Eigen::Vector3d(0.0, 0.0, profile.thickness_m()));
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, test::Fjs1(false), 9.81, {});
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  const FreeDropResult r = RunFreeDrop({&body, rft::UniformTerrain("soil", law), in, {}});
  ASSERT_FALSE(r.trace.empty());
  EXPECT_EQ(r.trace.front().t_s, 0.0);
  EXPECT_EQ(r.trace.front().penetration_m, 0.0);
  EXPECT_EQ(r.trace.front().force_N, 0.0);
}

// Soil patches (rft/soil_map.h) under a free pad: the pad takes the soil under its reference point,
// so a patch covering the landing spot gives exactly that soil's drop, and one elsewhere changes
// nothing. A pad sliding from loose onto dense soil sinks less than on loose soil alone.
TEST(FreeDrop, TakesTheSoilOfThePatchUnderThePad) {
  const geom::AxisymmetricProfile profile = FlatProfile();
  const geom::PadBody body = geom::RevolveProfileToBody(profile, 24, kPadMass_kg, Eigen::Vector3d(0.0, 0.0, profile.thickness_m()));
  const rft::SoilContactModel lp = test::Fjs1Law(false), cp = test::Fjs1Law(true);
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  const FreeDropResult on_lp = RunFreeDrop({&body, rft::UniformTerrain("lp", lp), in, {}});
  const FreeDropResult on_cp = RunFreeDrop({&body, rft::UniformTerrain("cp", cp), in, {}});
  ASSERT_LT(on_cp.final_penetration_m, 0.8 * on_lp.final_penetration_m);  // the two soils differ

  rft::Terrain patched = rft::UniformTerrain("lp", lp);
  patched.soils.push_back({"cp", cp});
  patched.patches.push_back({"cp_square", rft::RectanglePolygon(-0.5, -0.5, 0.5, 0.5), 1});
  EXPECT_EQ(RunFreeDrop({&body, patched, in, {}}).final_penetration_m, on_cp.final_penetration_m);
  patched.patches[0].polygon_W = rft::RectanglePolygon(2.0, 2.0, 3.0, 3.0);
  EXPECT_EQ(RunFreeDrop({&body, patched, in, {}}).final_penetration_m, on_lp.final_penetration_m);

  // Sliding at 0.5 m/s onto dense soil that starts 2 mm ahead of the pad's centre.
  in.horizontal_speed_m_s = 0.5;
  patched.patches[0].polygon_W = rft::RectanglePolygon(0.002, -0.5, 1.0, 0.5);
  const FreeDropResult onto_cp = RunFreeDrop({&body, patched, in, {}});
  const FreeDropResult sliding_lp = RunFreeDrop({&body, rft::UniformTerrain("lp", lp), in, {}});
  EXPECT_LT(onto_cp.final_penetration_m, sliding_lp.final_penetration_m);
  EXPECT_GT(onto_cp.final_penetration_m, 0.0);
}

}  // namespace
}  // namespace touchdown::pad

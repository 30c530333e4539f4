#pragma once
// The paper's four-legged lander (Sutoh, Wakabayashi & Hoshino, RA-L 2017) and its Table II
// grounds, built in code for the lander tests: the values of the catalogue files named beside
// each, so these tests need no catalogue or scenario loader (drop_tests/). The pad is re-meshed
// at `segments` around the rim (16 keeps the suite fast; the catalogue's 64 is the benchmark's).
#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "footpad_geom/axisymmetric_profile.h"
#include "footpad_geom/pad_body_builder.h"
#include "footpad_geom/revolve.h"
#include "lander/multibody/lander_dynamics.h"
#include "lander/multibody/lander_simulation.h"
#include "rft/ground.h"
#include "rft/soil_map.h"
#include "rft/units.h"
#include "tests/lander/paper_soils.h"

namespace touchdown::test {

inline constexpr int kTestAngularSegments = 16;
inline constexpr double kMm = 1e-3;

// data/landers/sutoh2017_footpad.yaml: flat, 27.5 mm radius, 10 mm thick, 0.08 kg, the ball-joint
// centre (the pad frame's origin) 20 mm above the lowest point.
inline geom::PadBody LanderPad(int segments = kTestAngularSegments) {
  geom::PadMassModel mass;
  mass.mass_kg = 0.08;
  const geom::AxisymmetricProfile profile = geom::MakeFlatProfile(27.5 * kMm, 10 * kMm);
  return geom::MakePadBody(geom::RevolveProfileToMesh(profile, segments), mass, Eigen::Vector3d(0.0, 0.0, 20 * kMm),
                           "sutoh2017_footpad");
}

struct PaperLander {
  lander::LanderModel model;
  rft::Terrain terrain;
  lander::LanderInitialState initial;
  double total_mass_kg = 0.0;
  double drop_height_m = 0.0;
};

// data/landers/sutoh2017_lander.yaml on the ground of data/scenarios/lander_case_<ground_case>.yaml
// ('A': LP under every pad; 'B': CP under pad 1; 'C': CP under pads 1 and 2), released with the
// pad bottoms drop_height_m above the surface (0: placed on it).
// `shipped_soils`: the soils' dynamic term as data/soils ships it (else quasi-static, as the tests pin).
inline PaperLander MakePaperLander(char ground_case, int segments = kTestAngularSegments, double drop_height_m = 0.10,
                                   bool shipped_soils = false) {
  PaperLander out;
  out.total_mass_kg = 4.3;                  // sutoh2017_lander.yaml: total_mass_kg
  const double cog_height = 230 * kMm;      // sutoh2017_lander.yaml: cog_height_mm
  const double joint_radius = 300 * kMm;    // sutoh2017_lander.yaml: legs.joint_radius_mm
  const double hip_radius = 120 * kMm;      // sutoh2017_lander.yaml: legs.hip_radius_mm
  const double hip_height = 200 * kMm;      // sutoh2017_lander.yaml: legs.hip_height_mm
  const auto pad = std::make_shared<const geom::PadBody>(LanderPad(segments));
  lander::LanderModel& m = out.model;
  m.gravity_m_s2 = 9.81;  // lander_case_*.yaml: gravity_m_s2
  m.body_mass_kg = out.total_mass_kg - lander::kNumLegs * pad->mass_kg;
  m.body_inertia_B = Eigen::Vector3d(0.050, 0.050, 0.060).asDiagonal();  // sutoh2017_lander.yaml: body_inertia_kg_m2
  // Standing level on the pad bottoms (as drop_tests/scenario/lander_scenario.cpp places the legs).
  const double joint_height = -pad->lowest_z_B;
  const double pad_com_height = joint_height + pad->com_B.z();
  const double body_com_height =
      (out.total_mass_kg * cog_height - lander::kNumLegs * pad->mass_kg * pad_com_height) / m.body_mass_kg;
  constexpr double kPadAzimuthDeg[lander::kNumLegs] = {45.0, -45.0, -135.0, 135.0};  // clockwise, pad 1 front-left
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const double az = kPadAzimuthDeg[i] * units::kDeg;
    const Eigen::Vector3d dir(std::cos(az), std::sin(az), 0.0);
    m.legs[i].joint_B = joint_radius * dir + Eigen::Vector3d(0, 0, joint_height - body_com_height);
    m.legs[i].hip_B = hip_radius * dir + Eigen::Vector3d(0, 0, hip_height - body_com_height);
    m.legs[i].pad = pad;
  }
  lander::FinishModel(m);

  out.terrain.surface = std::make_shared<rft::PlaneGround>(0.0, 0.0, 0.0);
  out.terrain.soils.push_back({"fjs1_lp", Fjs1Law(false, m.gravity_m_s2, shipped_soils)});  // lander_case_*.yaml: ground.soil
  lander::LanderInitialState& s = out.initial;
  for (int i = 0; i < lander::kNumLegs; ++i) s.R_WP[i] = s.R_WB;
  out.drop_height_m = drop_height_m;  // lander_case_*.yaml: initial.drop_height_m
  s.p_WB.z() = lander::BodyHeightForClearance(m, out.terrain, s, drop_height_m);
  // lander_case_{B,C}.yaml: ground.patches, CP squares of half width 0.08 m under pads 1 (and 2).
  const int cp_pads = ground_case == 'B' ? 1 : ground_case == 'C' ? 2 : 0;
  if (cp_pads > 0) out.terrain.soils.push_back({"fjs1_cp", Fjs1Law(true, m.gravity_m_s2, shipped_soils)});
  for (int leg = 0; leg < cp_pads; ++leg) {
    const double h = 0.08;
    const Eigen::Vector3d c = s.p_WB + s.R_WB * m.legs[leg].joint_B;
    out.terrain.patches.push_back({"compacted_under_pad_" + std::to_string(leg + 1),
                                   rft::RectanglePolygon(c.x() - h, c.y() - h, c.x() + h, c.y() + h), 1});
  }
  return out;
}

// The state `after_s` seconds after the first touchdown of `setup`'s landing (a state in the middle
// of the contact, for Jacobian checks).
inline Eigen::VectorXd StateAfterFirstTouchdown(const PaperLander& setup, double after_s) {
  lander::LanderRunOptions options;
  options.duration_s = 1.0;
  const lander::LanderRunResult touchdown = lander::SimulateLander(setup.model, setup.terrain, setup.initial, options);
  options.duration_s = *touchdown.first_touchdown_s + after_s;
  return lander::SimulateLander(setup.model, setup.terrain, setup.initial, options).final_state;
}

// The right-hand side dy/dt of `setup`'s lander at y, in free modes (no pad held).
inline Eigen::VectorXd FreeModesRhs(const PaperLander& setup, const lander::StateLayout& layout,
                                    const Eigen::VectorXd& y) {
  lander::LanderEvaluation e;
  lander::EvaluateLander(setup.model, layout, setup.terrain, lander::LanderModes{}, y, &e);
  Eigen::VectorXd ydot(layout.size);
  lander::StateDerivative(layout, y, e, ydot);
  return ydot;
}

}  // namespace touchdown::test

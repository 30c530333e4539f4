#pragma once
// The paper's soils built in code for the lander/ tests (no catalogue): FJS-1 in vacuum as in
// data/soils/fjs1_lp.yaml and data/soils/fjs1_cp.yaml, zeta from Agarwal et al. 2023's scaling
// (zeta_N_cm3: agarwal2023), and its li2013 law (quasi-static, or with the shipped dynamic term).
#include <cmath>
#include <memory>

#include "rft/soil.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

namespace touchdown::test {

inline rft::SoilParameters Fjs1(bool closely_packed) {
  rft::SoilParameters s;
  s.name = closely_packed ? "fjs1_cp" : "fjs1_lp";
  s.atmosphere = rft::Atmosphere::kVacuum;                                        // data/soils/fjs1_{lp,cp}.yaml
  s.reference_gravity_m_s2 = 9.81;                                  // data/soils/fjs1_{lp,cp}.yaml
  s.bulk_density_kg_m3 = closely_packed ? 1770.0 : 1540.0;          // data/soils/fjs1_{cp,lp}.yaml
  s.internal_friction_angle_rad = (closely_packed ? 44.0 : 37.0) * units::kDeg;  // data/soils/fjs1_{cp,lp}.yaml
  s.zeta_N_m3 = rft::AgarwalScalingXi(s.bulk_density_kg_m3, s.reference_gravity_m_s2,
                                      std::tan(s.internal_friction_angle_rad));
  return s;
}

// The li2013 contact model of a soil, quasi-static: the lander tests check the multibody model,
// and their pinned numbers predate the shipped soils' dynamic term. With `dynamic_term`, the soil
// as shipped: dynamic RFT's inertial term, lambda 1.1 (data/soils/fjs1_{lp,cp}.yaml), as a
// scenario without a model file runs it (bench/lander_bench.cpp measures that).
inline rft::SoilContactModel Fjs1Law(bool closely_packed, double gravity_m_s2 = 9.81, bool dynamic_term = false) {
  rft::SoilParameters soil = Fjs1(closely_packed);
  soil.dynamic_term = dynamic_term;
  soil.dynamic_lambda = 1.1;  // data/soils/fjs1_{lp,cp}.yaml: dynamic_lambda
  return rft::MakeSoilContactModel(rft::LawKind::kLi2013, soil, gravity_m_s2, rft::WithSoilDynamicTerm({}, soil));
}

}  // namespace touchdown::test

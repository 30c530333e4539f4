#pragma once
// The parameters of a Bekker-Wong-Janosi soil (model data, SI inside; files state them in kN, kPa,
// deg and mm, drop_tests/catalog/catalog.cpp). rft/bekker_law.h uses them.
namespace touchdown::rft {

struct BekkerParameters {
  double n = 1.0;                   // sinkage exponent [-], > 0
  double k_c_N_m_n1 = 0.0;          // cohesive modulus k_c [N/m^(n+1)], >= 0
  double k_phi_N_m_n2 = 0.0;        // frictional modulus k_phi [N/m^(n+2)], >= 0
  double cohesion_Pa = 0.0;         // c [Pa], >= 0
  double friction_angle_rad = 0.0;  // phi [rad], in [0, pi/2)
  double shear_modulus_K_m = 0.0;   // Janosi-Hanamoto shear deformation modulus K [m], > 0
};

}  // namespace touchdown::rft

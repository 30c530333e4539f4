#pragma once
// The terms of the soil response that act on the pad as a whole rather than on one element, as
// constant parameters (never state). The stress law (rft/stress_law_3d.h) says what one element
// feels; these say how the contact (rft/contact_wrench.h) weights depth, what transient the bed
// adds under the whole pad, and what mass of grains the pad carries:
//
//   depth         the stress per depth grows as z_ref (z / z_ref)^p instead of z; the contact
//                 integrates z^p exactly over each clipped triangle (p = 1: the linear law of RFT,
//                 on its own path, z_ref unused)
//   compaction    the bed's compaction transient: a stress -k_c (v.n)^2 n on leading elements
//                 (n . v > 0), integrated over the submerged area and scaled by exp(-z_pad / d_c),
//                 z_pad the pad's penetration (the bed compacts during the first d_c of the stroke)
//   added mass    c_a rho of the entrained cone of grains and c_p rho of the plug (the dead zone
//                 under a flat pad, rft/entrained_mass.h): the free pad and the lander add their
//                 inertia to the pad's vertical motion
//
// For a level axisymmetric pad moving straight down, the compaction stress integrates to
// k_c v^2 exp(-d / d_c) I_3(d), I_k(d) the integral of cos^k(beta) dA over the submerged leading
// surface (beta the attack angle), as the dynamic term gives lambda rho v^2 I_3(d)
// (docs/physics.md, section 4).
#include <Eigen/Core>

namespace touchdown::rft {

// How the stress per unit depth scales with depth z: stress = sigma z_ref (z / z_ref)^p.
struct DepthLaw {
  double exponent = 1.0;      // p [-], > 0
  double reference_m = 0.01;  // z_ref [m], > 0
};

struct PadLevelTerms {
  DepthLaw depth;
  double compaction_k_kg_m3 = 0.0;        // k_c [kg/m^3], >= 0; 0: no compaction transient
  double compaction_depth_m = 1.0;        // d_c [m], > 0
  double added_mass_density_kg_m3 = 0.0;  // c_a rho [kg/m^3], >= 0; 0: no cone
  double plug_density_kg_m3 = 0.0;        // c_p rho [kg/m^3], >= 0; 0: no plug

  bool has_power_depth() const { return depth.exponent != 1.0; }
  bool has_compaction() const { return compaction_k_kg_m3 > 0.0; }
  // Either form of added mass: the contact then reports the footprint and its rate.
  bool has_added_mass() const { return added_mass_density_kg_m3 > 0.0 || plug_density_kg_m3 > 0.0; }
  // The compaction stress [N/m^2] on an element of outward normal n_W moving at v_W:
  // -k_c (v.n)^2 n when it leads (v.n > 0), else 0 (trailing or sliding elements compact nothing).
  Eigen::Vector3d CompactionStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const;
};

}  // namespace touchdown::rft

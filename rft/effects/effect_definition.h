#pragma once
// One effect of the library as a single registration: its id, its parameters (key, unit, range,
// neutral value, fitting scales), its rig form, its 3D element form and its documentation row.
// A new effect is one file here, rft/effects/<name>_effect.cpp, defining
//
//   EffectDefinition <name>_effect();      (namespace touchdown::rft::effects)
//
// The build picks every such file up (rft/effects/CMakeLists.txt generates the list), and from
// there the effect is in the library every command reads (drop_tests/model/effects.h): model
// files, `drop`, `lander`, studies, `synth`, `diagnose` (as a candidate), the Python module. Its
// test is tests/rft/effects/<name>_effect_test.cpp (picked up the same way), its docs row is
// checked against docs/model_gap.md (tests/drop_tests/model/registered_effects_test.cpp), and
// tests/drop_tests/model/registered_effects_test.cpp also holds every registered effect to the
// library's contract: neutral values change nothing, and for a level axisymmetric pad moving
// straight down the 3D form gives the rig's force.
//
// A registered effect acts through the two forms below, so it is an added normal or shear stress
// on the submerged leading surface (a function of the element's normal and velocity, of the
// soil's bulk density and of the effect's parameters). Terms of another kind (a mass carried with
// the pad, a different depth law, a sensor effect) are built into rft/effect_terms.h.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace touchdown::rft {

// The most parameters a registered effect may have (EffectTerms holds them in fixed arrays, so a
// right-hand side never allocates).
inline constexpr int kMaxEffectParameters = 4;
// The most registered effects (the same reason).
inline constexpr int kMaxRegisteredEffects = 8;

// One parameter of an effect as a file and a fit see it.
struct EffectParameter {
  std::string key;          // in files, unit-suffixed: "c_N_s_m3", "d_c_mm"
  std::string symbol;       // in the documentation: "c", "d_c"
  std::string unit;         // SI unit of the value held in memory
  double file_to_si = 1.0;  // value_SI = value_file * file_to_si
  double lower = 0.0, upper = 0.0;  // admissible range (SI)
  double scale = 1.0;       // a typical magnitude (SI), for fitting
  double start = 0.0;       // starting value of a fit (SI)
  std::vector<double> scan;  // if given, a fit first picks the best of these starts (SI)
  double neutral = 0.0;     // the value at which the effect changes nothing (SI)
  std::string file_unit;    // of the value in files, the key's suffix ("mm" for d_c_mm); empty: `unit`

  const std::string& FileUnit() const { return file_unit.empty() ? unit : file_unit; }

  // Why the SI value v is not admissible ("must be in [lower, upper], got v", in file units), or
  // empty when it is.
  std::string RangeProblem(double v) const;
};

// What the rig's 1-DOF drop knows of the pad at one instant: its penetration d, its downward
// speed v (>= 0; 0 for the static capacity) and the integrals I_k(d) of cos^k(beta) dA over the
// submerged leading surface (footpad_geom/axisymmetric_intrusion.h CosinePowerIntegral). A normal
// stress s(v.n) on an element of attack angle beta (v.n = v cos(beta)) pushes up with
// s cos(beta) dA: a stress a (v.n)^k gives a v^k I_{k+1}(d).
struct RigPoint {
  double depth_m = 0.0;
  double speed_down_m_s = 0.0;
  double I1_m2 = 0.0, I2_m2 = 0.0, I3_m2 = 0.0;
  double bulk_density_kg_m3 = 0.0;
};

struct EffectDefinition {
  std::string id;    // its name in files, outputs and on the command line: "cohesion"
  std::string form;  // one line, the documented form
  std::vector<EffectParameter> parameters;
  bool air_only = false;            // acts only on drops in air
  bool needs_bulk_density = false;  // its force scales with the soil's bulk density rho
  // The rig: the upward force [N] it adds at `p` (values in SI, in `parameters` order). Called
  // with p.speed_down_m_s = 0 for the static capacity, so a term that holds at rest (cohesion)
  // gives it there too. Pure: no state, no allocation.
  double (*rig_force_N)(const double* values, const RigPoint& p) = nullptr;
  // The 3D contact: the depth-independent stress [Pa] on a submerged element of outward normal
  // n_W moving at v_W (a DynamicStress, rft/stress_law_3d.h; the contact calls it on leading
  // elements only, n.v >= 0). Pure: no state, no allocation.
  Eigen::Vector3d (*element_stress_Pa)(const double* values, double bulk_density_kg_m3, const Eigen::Vector3d& n_W,
                                       const Eigen::Vector3d& v_W) = nullptr;
  // Its rows of docs/model_gap.md's two effect tables, as they stand there: the rig form
  // ("| `id` | stress ... | `key` [unit] |") and the 3D form ("| id | ... | file |").
  std::string docs_rig_row;
  std::string docs_3d_row;
};

// Every registered effect, in the order of their file names; built once.
const std::vector<EffectDefinition>& RegisteredEffects();

}  // namespace touchdown::rft

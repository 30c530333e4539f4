#pragma once
// The quasi-static soil wrench on a pad held at a depth, tilt and rigid motion, as a user asks for
// it: the options of `touchdown force` and the arguments of the Python module's touchdown.force().
// Both check and compute it here and get the same JSON (ForceJson). The motion gives RFT its
// direction only; the soil's rate-dependent term (dynamic RFT's lambda rho (v.n)^2), which a
// held pad does not feel, is added only when asked for (`dynamic`), at the velocity given.
#include <array>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/drop/drop_request.h"
#include "drop_tests/formats/output_path.h"
#include "rft/contact_wrench.h"
#include "rft/gravity_constants.h"
#include "rft/law_kind.h"
#include "rft/soil.h"
#include "rft/soil_contact_model.h"

namespace touchdown::drop {

struct ForceRequest {
  std::string pad, soil;  // catalogue names or YAML files
  std::optional<std::string> law;  // li2013, agarwal2023 or bekker; none: the soil's own law
  std::string tilt_axis = "x";
  double depth_m = 0.0, tilt_deg = 0.0, gravity_m_s2 = rft::kEarthGravity_m_s2;
  std::array<double, 3> velocity_m_s{0.0, 0.0, -1.0}, omega_rad_s{0.0, 0.0, 0.0};
  std::optional<double> zeta_N_cm3;  // overrides the soil's
  bool dynamic = false;               // add the soil's dynamic term at velocity_m_s (if it has one)
};

// The soil wrench on `pad` held with its lowest point at `depth_m`, turned by k.R_WB and moving as
// k says (k.p_WB is set here), on `soil` under `law` with zeta scaled to `gravity_m_s2` as the soil
// says: the one computation behind `touchdown force` and validate's static bearing pressure. The
// model is returned with the wrench (its law names the result, its depth law draws the VTK).
struct HeldPadWrench {
  rft::SoilContactModel model;
  rft::ContactWrench wrench;
};
HeldPadWrench ComputeHeldPadWrench(const io::PadSpec& pad, const rft::SoilParameters& soil, rft::LawKind law,
                                   double gravity_m_s2, double depth_m, rft::PadKinematics& k);

// Validates the request (InputError naming the field as `naming` spells it), loads the pad and
// the soil and returns the wrench: pad, soil, law, the request, reference_point_m, force_N,
// moment_Nm, submerged_area_m2, leading_elements, surface_elements (SI, world frame, z up), and
// dynamic_term: whether the soil's dynamic term is in the force.
// With `vtk`: also the pad at its pose with the stress on each surface element, as a .vtp file
// (ParaView; docs/paraview.md), written whole or not at all.
nlohmann::json ForceJson(const ForceRequest& request, const RequestNaming& naming,
                         const io::OutputTarget* vtk = nullptr);

}  // namespace touchdown::drop

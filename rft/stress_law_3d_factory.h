#pragma once
// Builds the 3D stress law a soil asks for, scaled to the gravity of the run.
#include <memory>
#include <string_view>

#include "rft/soil.h"
#include "rft/stress_law_3d.h"

namespace touchdown::rft {

// law: "li2013" (Li 2013 via Treers et al. 2021; needs zeta, scaled to gravity_m_s2 from the
// soil's reference gravity) or "agarwal2023" (needs bulk density and internal friction angle;
// xi_n = rho g (894 mu^3 - 386 mu^2 + 89 mu), mu = tan(phi), and mu_surf). When the soil's
// dynamic_term is on, the law is wrapped in DynamicTermLaw (lambda, rho_c). Throws InputError
// on an unknown law name or missing/invalid soil data, naming the soil and the field.
std::unique_ptr<StressLaw3D> MakeStressLaw3D(std::string_view law, const SoilParameters& soil,
                                             double gravity_m_s2);

}  // namespace touchdown::rft

#include "drop_tests/drop/drop_factory.h"

#include "rft/stress_law.h"

namespace touchdown::drop {

rft::SoilParameters DropSoil(const rft::SoilParameters& soil, const std::optional<double>& zeta_N_m3,
                             const std::optional<rft::Atmosphere>& atmosphere) {
  rft::SoilParameters out = soil;
  if (zeta_N_m3) out.zeta_N_m3 = *zeta_N_m3;
  if (atmosphere) out.atmosphere = *atmosphere;
  return out;
}

double ZetaAtGravity(const rft::SoilParameters& drop_soil, double gravity_m_s2) {
  return drop_soil.ZetaAtGravity(gravity_m_s2);
}

std::unique_ptr<geom::AxisymmetricIntrusion> MakeRigIntrusion(const geom::AxisymmetricProfile& profile) {
  return std::make_unique<geom::AxisymmetricIntrusion>(profile, rft::Li2013Law{});
}

model::EffectSoilResponse MakeRigResponse(const geom::AxisymmetricIntrusion& intrusion,
                                          const rft::SoilParameters& drop_soil, double gravity_m_s2,
                                          const model::EffectTerms& terms) {
  const model::SoilResponseInputs in{ZetaAtGravity(drop_soil, gravity_m_s2), drop_soil.bulk_density_kg_m3,
                                     drop_soil.atmosphere == rft::Atmosphere::kAir, terms};
  return model::EffectSoilResponse(intrusion, in);
}

std::unique_ptr<rft::StressLaw3D> MakeFreeLaw(const rft::SoilParameters& drop_soil, const std::string& law_3d,
                                              double gravity_m_s2, const model::EffectTerms& terms,
                                              const std::string& effects_source) {
  const std::string& name = law_3d.empty() ? drop_soil.rft_law_3d : law_3d;
  return model::MakeEffectLaw3D(name, drop_soil, gravity_m_s2, terms, drop_soil.atmosphere == rft::Atmosphere::kAir,
                                effects_source);
}

}  // namespace touchdown::drop

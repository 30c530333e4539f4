#include "drop_tests/drop/drop_request.h"

#include <cmath>
#include <sstream>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/model/model_file.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

namespace touchdown::drop {

std::string RequestNaming::Field(std::string_view option) const {
  std::string name(option);
  if (command_line) return "--" + name;
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

namespace {
// Tilt, horizontal speed and angular rate: finite, the tilt below 90 deg, and only for a free pad.
void CheckFreeMotion(const DropRequest& r, const RequestNaming& n) {
  for (double v : {r.tilt_deg, r.horizontal_speed_m_s, r.omega_rad_s[0], r.omega_rad_s[1], r.omega_rad_s[2]})
    if (!std::isfinite(v))
      throw MakeInputError(n.context, n.Field("free"), "tilt, horizontal speed and omega must be finite");
  if (!(std::abs(r.tilt_deg) < 90.0)) {
    std::ostringstream s;
    s << "must lie strictly between -90 and 90 deg (on its side a pad does not land on its bottom), got " << r.tilt_deg;
    throw MakeInputError(n.context, n.Field("tilt-deg"), s.str());
  }
  if (r.fast && !r.free)
    throw MakeInputError(n.context, n.Field("fast"),
                         "needs " + n.Field("free") + " (the fast model is the free pad's; the rig drop is one DOF)");
  const bool moves = r.tilt_deg != 0.0 || r.horizontal_speed_m_s != 0.0 ||
                     r.omega_rad_s != std::array<double, 3>{0.0, 0.0, 0.0};
  if (!r.free && moves)
    throw MakeInputError(n.context, n.Field("free"),
                         n.Field("tilt-deg") + ", " + n.Field("horizontal-speed") + " and " + n.Field("omega") +
                             " need " + n.Field("free") + " (the rig drop is vertical)");
}

// The soil must take the law the drop runs on, before anything runs: a soil running on the bekker
// law has no zeta to override, and li2013 needs a zeta (a Bekker soil may have none), checked as a
// lander's ground checks its soils (rft::CheckSoilTakesLaw).
void CheckSoilTakesLaw(const rft::SoilParameters& soil, const DropConditions& c, const RequestNaming& n) {
  if (RunsOnBekker(soil, c.law_3d)) {
    if (c.zeta_N_m3)
      throw MakeInputError(n.context, n.Field("zeta"),
                           "soil " + soil.name + " runs on the bekker law, which has no zeta (" + n.Field("law") +
                               " li2013 runs it on RFT with this zeta)");
    return;
  }
  try {
    rft::CheckSoilTakesLaw(c.law_3d.value_or(soil.rft_law_3d), DropSoil(soil, c.zeta_N_m3, c.atmosphere),
                           c.gravity_m_s2);
  } catch (const InputError& e) {
    throw MakeInputError(n.context, c.law_3d ? n.Field("law") : n.Field("soil"), e.what());
  }
}
FreeDropModel ModelOf(const DropRequest& r) { return r.fast ? FreeDropModel::kFast : FreeDropModel::kReference; }
}  // namespace

DropConditions RequestConditions(const DropRequest& r, const RequestNaming& naming) {
  DropConditions c;
  DropRow& row = c;  // the stated conditions, from the request's units
  row.impact_speed_m_s = r.speed_m_s;
  row.mass_kg = r.mass_kg;
  row.gravity_m_s2 = r.gravity_m_s2;
  if (r.zeta_N_cm3) row.zeta_N_m3 = units::ZetaFromN_cm3(*r.zeta_N_cm3);
  CheckFreeMotion(r, naming);
  if (r.free) {
    c.free = true;
    row.tilt_rad = units::DegToRad(r.tilt_deg);
    c.tilt_axis = pad::ParseTiltAxis(r.tilt_axis, naming.context);
    row.horizontal_speed_m_s = r.horizontal_speed_m_s;
    c.omega_W = Eigen::Vector3d(r.omega_rad_s[0], r.omega_rad_s[1], r.omega_rad_s[2]);
  }
  if (r.law) c.law_3d = rft::ParseLawKind(*r.law, naming.context, naming.Field("law"));
  ValidateConditions(c, naming.context);
  return c;
}

io::PadSpec RequestPad(const DropRequest& r, const RequestNaming& naming) {
  return FreeDropPad(io::LoadPad(r.pad), ModelOf(r), naming.context, naming.Field("fast"));
}

DropSetup ResolveDropRequest(const DropRequest& r, const io::PadSpec& pad, DropConditions conditions,
                             const RequestNaming& naming) {
  rft::SoilParameters soil = io::LoadSoil(r.soil);
  if (!r.model.empty()) {
    const model::ModelFile model = model::LoadModelFile(r.model);
    soil = model::ApplyModel(model, soil);
    conditions.effects = model::ModelEffectTerms(model);
    conditions.effects_source = r.model;
  }
  CheckSoilTakesLaw(soil, conditions, naming);
  DropRunOptions options;
  options.free = FreeDropOptionsFor(ModelOf(r));
  return ResolveDrop(pad, soil, conditions, options);
}

nlohmann::json RequestSummaryJson(const DropRequest& r, const PadDrop& drop) {
  nlohmann::json summary = SummaryJson(drop);
  if (r.fast)
    summary["fast_model"] = {
        {"rim_segments", kFastFreeDropRimSegments}, {"rim", "area_preserving"}, {"rtol", kFastFreeDropRtol}};
  return summary;
}

}  // namespace touchdown::drop

#pragma once
// A drop as a user asks for it, by pad and soil name and in the units of the command line (tilt
// in degrees, zeta in N/cm^3): the options of `touchdown drop` and the arguments of the Python
// module's touchdown.drop(). Both check, load and run it here, so both print the same summary
// (SummaryJson) and refuse the same requests with the same one-line InputError.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "rft/gravity_constants.h"

namespace touchdown::drop {

// How an InputError names a request's fields: the command line's options ("command line",
// "--tilt-deg") or the Python module's keyword arguments ("touchdown.drop", "tilt_deg").
struct RequestNaming {
  std::string context = "command line";
  bool command_line = true;

  // `option` as the command line spells it without dashes ("tilt-deg"): "--tilt-deg" or "tilt_deg".
  std::string Field(std::string_view option) const;
};

struct DropRequest {
  std::string pad, soil;  // catalogue names or YAML files (io::LoadPad, io::LoadSoil)
  std::string model;      // a model file (MODEL.yaml), or none
  double speed_m_s = 0.0;
  std::optional<double> mass_kg, zeta_N_cm3;
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
  // The free 6-DOF pad: asked for with `free`; tilt, horizontal speed and omega need it.
  bool free = false;
  double tilt_deg = 0.0, horizontal_speed_m_s = 0.0;
  std::string tilt_axis = "x";
  std::optional<std::string> law;  // li2013, agarwal2023 (free only) or bekker; none: the soil's own law
  std::array<double, 3> omega_rad_s{0.0, 0.0, 0.0};
  // The free drop's fast model (FreeDropModel::kFast) instead of the reference; needs `free`.
  bool fast = false;
};

// The request's conditions (without the model's effects, which ResolveDropRequest adds), validated:
// InputError naming the field as `naming` spells it.
DropConditions RequestConditions(const DropRequest& request, const RequestNaming& naming);
// The pad the request's drop runs on (the fast model's re-meshed pad under `fast`): the drop's, and
// the one its ParaView frames draw. InputError naming the field as `naming` spells it.
io::PadSpec RequestPad(const DropRequest& request, const RequestNaming& naming);
// Loads the soil and the model and resolves the drop of `pad` (RequestPad; the caller keeps it: a free
// drop's setup points to its body) under `conditions` (RequestConditions); RunDrop runs it. A soil
// that does not take the drop's law (li2013 on a Bekker soil without zeta, a zeta for a soil running
// on the bekker law) throws InputError naming the field as `naming` spells it.
DropSetup ResolveDropRequest(const DropRequest& request, const io::PadSpec& pad, DropConditions conditions,
                             const RequestNaming& naming);
// The summary both print: SummaryJson, and under `fast` the fast model's resolution
// (`fast_model`: rim_segments, rim, rtol), so a fast drop's numbers are never taken for the reference's.
nlohmann::json RequestSummaryJson(const DropRequest& request, const PadDrop& drop);

}  // namespace touchdown::drop

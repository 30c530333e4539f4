#pragma once
// The one resolution step of a drop: a catalogued pad, a catalogued soil, the drop's conditions and
// its run options become what the rig or the free pad runs on (pad::RigDropSetup or
// pad::FreeDropSetup, no names left in them) and the record the drop fills in. Every command's
// drops are resolved here, from the drop factory's pieces (drop_factory.h) and, for the free pad,
// the one 3D contact model (model::MakeContactModel).
#include <memory>
#include <optional>
#include <variant>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/drop/pad_drop.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "footpad_geom/pad_body.h"
#include "lander/pad/effect_soil_response.h"
#include "lander/pad/free_drop.h"
#include "lander/pad/rig_drop.h"

namespace touchdown::drop {

struct DropRunOptions {
  pad::RigDropOptions rig{};    // (`{}` on each member: callers name only what they set, `{.rig = r}`)
  pad::FreeDropOptions free{};
  // The pad's profile integral, built once by callers running many drops of one pad (sweeps);
  // null: built here. Must be the pad's own (MakeRigIntrusion, drop_factory.h).
  const geom::AxisymmetricIntrusion* intrusion = nullptr;
};

// A resolved drop. `record` is the drop's record without its result: the pad as described, the
// soil in the drop's atmosphere, the conditions, the mass, zeta at the drop's gravity, the law and
// (free drops) the contact model's name. `run` is what the runner takes. The setup owns what it built
// for the run (a rig's integral and soil response, a free pad's body at another mass); it points to
// the caller's pad body and cached integral, which must outlive it. Moving keeps those pointers valid;
// copying is not allowed.
struct DropSetup {
  PadDrop record;
  std::variant<pad::RigDropSetup, pad::FreeDropSetup> run;

  std::unique_ptr<geom::AxisymmetricIntrusion> intrusion;  // a rig's integral built here (Bekker, or none cached)
  std::unique_ptr<pad::EffectSoilResponse> response;       // a rig's soil response
  std::unique_ptr<geom::PadBody> body;                     // a free pad at another mass than its file's
};

// The rig for level, vertical drops, else the free pad (DropConditions::IsFree). Effects: on the rig in
// their rig form, on the free pad in their 3D form. The conditions are taken as valid: their loaders
// check them (DropConditionsFor, RequestConditions, the campaign and source loaders), where an error
// can name the file and field. Throws InputError for a rig drop of a mesh pad, and a soil the effects or the law
// cannot run on.
DropSetup ResolveDrop(const io::PadSpec& pad, const rft::SoilParameters& soil, const DropConditions& conditions,
                      const DropRunOptions& options = {});

// Runs a resolved drop: its record with the result. A failing integration throws
// integ::IntegrationFailure.
PadDrop RunDrop(const DropSetup& setup);

}  // namespace touchdown::drop

#pragma once
// Simulating one drop of a sweep. Everything that is the same for many drops (pads loaded,
// soils with the model applied, a lander sweep's soil files, the model's effect terms, the pads'
// RFT intrusion tables) is
// built once in SweepModels; SimulateSweepDrop is then a pure function of (models, index) that
// may run on any thread. The kind of drop is chosen per drop:
//
//   rig drop     an axisymmetric pad, tilt = 0 and horizontal speed = 0: the paper's vertical rod (RunRigDrop)
//   free drop    otherwise (a mesh pad always): the 6-DOF free pad (lander/pad/free_drop.h, RunFreeDrop), tilted
//                about the world x axis, sliding along +x; its final tilt and horizontal travel
//                are recorded (final_tilt_deg, horizontal_travel_m). Seconds per drop when tilted
//                (milliseconds under the plan's fast free_drop_model, drop::FreeDropModel).
//   lander drop  a lander sweep (SweepPlan::lander): the scenario with the drop's parameters,
//                one whole lander run (seconds), recorded as its summary (pad penetrations,
//                final roll and pitch, tipped over) and the soil under each pad at release
//                (pad1_soil..pad4_soil, with the paper's ground case when it is one).
// Both pad kinds go through DropConditionsFor + ResolveDrop + RunDrop (drop_tests/drop/drop_setup.h), as
// `compare` does, with the model's effects (all of them, on free pads in their 3D form).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/model/effects.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep_plan.h"

namespace touchdown::geom {
class AxisymmetricIntrusion;
}

namespace touchdown::sweep {

class SweepModels {
 public:
  explicit SweepModels(const SweepPlan& plan);
  ~SweepModels();
  const SweepPlan& plan() const { return plan_; }
  // The pad's profile integral; axisymmetric pads only (has_intrusion).
  bool has_intrusion(int pad) const { return intrusions_[pad] != nullptr; }
  const geom::AxisymmetricIntrusion& intrusion(int pad) const { return *intrusions_[pad]; }
  // The pad the sweep's free drops of pad `pad` run on under the plan's free_drop_model
  // (drop::FreeDropPad): re-meshed once per sweep for the fast model, else the pad itself.
  const io::PadSpec& free_pad(int pad) const { return free_pads_.empty() ? plan_.pads[pad] : free_pads_[pad]; }
  const rft::EffectTerms& effects() const { return effects_; }
  // The run options of the sweep's drops, resolved once (no profile integral: that is per pad).
  const drop::DropRunOptions& drop_options() const { return drop_options_; }
  // A lander sweep: the scenario's default soil with the model applied (for drops that do not
  // set `soil`).
  const rft::SoilParameters& lander_soil() const { return lander_soil_; }
  // A lander sweep: the soil name (as in the soil file) of a soil reference of its ground.
  const std::string& SoilName(const std::string& ref) const;
  // A lander sweep: every soil its landings' grounds may name, read once for all of them.
  const scenario::LanderSoilCatalog& lander_soils() const { return lander_soils_; }

 private:
  const SweepPlan& plan_;
  std::vector<std::unique_ptr<geom::AxisymmetricIntrusion>> intrusions_;
  std::vector<io::PadSpec> free_pads_;  // the fast model's re-meshed pads; empty for the reference
  rft::EffectTerms effects_;  // the model's, parsed once
  drop::DropRunOptions drop_options_;
  rft::SoilParameters lander_soil_;
  std::map<std::string, std::string> soil_names_;  // lander sweeps: soil reference -> name
  scenario::LanderSoilCatalog lander_soils_;
};

// Runs drop `index` and returns its record. A drop that fails (the integrator gives up, the pad
// never stops, ...) comes back with ok = false and the reason; it never throws for that.
// `trace` overrides the plan's trace storage (export asks for full traces).
DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index);
DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index, TraceStorage trace);

// Keeps at most `max_samples` samples, evenly by index, always the first, the last and the
// sample of peak force; used for `traces: decimated`.
std::vector<pad::DropSample> DecimateTrace(const std::vector<pad::DropSample>& trace, int max_samples);

}  // namespace touchdown::sweep

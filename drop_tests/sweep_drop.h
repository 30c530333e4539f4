#pragma once
// Simulating one drop of a sweep. Everything that is the same for many drops (pads loaded,
// soils with the model applied, the pads' RFT intrusion tables) is built once in
// SweepModels; SimulateSweepDrop is then a pure function of (models, index) that may run on
// any thread. The kind of drop is chosen per drop:
//
//   rig drop   tilt = 0 and horizontal speed = 0: the paper's vertical rod (RunRigDrop)
//   free drop  otherwise: the 6-DOF free drop, not in this build yet
//
// Adding the free drop means implementing RunFreeSweepDrop in sweep_drop.cpp and making
// FreeDropAvailable() return true; the sweep file already accepts tilt_deg and
// horizontal_speed_m_s and rejects non-zero values while it is false.
#include <memory>
#include <vector>

#include "drop_tests/results_db.h"
#include "drop_tests/sweep_spec.h"

namespace touchdown::geom {
class AxisymmetricIntrusion;
}

namespace touchdown::drop {

bool FreeDropAvailable();

class SweepModels {
 public:
  explicit SweepModels(const SweepPlan& plan);
  ~SweepModels();
  const SweepPlan& plan() const { return plan_; }
  const geom::AxisymmetricIntrusion& intrusion(int pad) const { return *intrusions_[pad]; }

 private:
  const SweepPlan& plan_;
  std::vector<std::unique_ptr<geom::AxisymmetricIntrusion>> intrusions_;
};

// Runs drop `index` and returns its record. A drop that fails (the integrator gives up, the pad
// never stops, ...) comes back with ok = false and the reason; it never throws for that.
// `trace` overrides the plan's trace storage (export asks for full traces).
DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index);
DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index, TraceStorage trace);

// Keeps at most `max_samples` samples, evenly by index, always the first, the last and the
// sample of peak force; used for `traces: decimated`.
std::vector<DropSample> DecimateTrace(const std::vector<DropSample>& trace, int max_samples);

}  // namespace touchdown::drop

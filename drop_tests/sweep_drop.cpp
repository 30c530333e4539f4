#include "drop_tests/sweep_drop.h"

#include <cmath>
#include <numbers>
#include <algorithm>

#include "footpad_geom/axisymmetric_intrusion.h"
#include "rft/stress_law.h"

namespace touchdown::drop {

namespace {
// zeta at the drop's gravity [N/m^3], computed exactly as RunPadDrop does.
double EffectiveZeta(const SweepPlan& plan, const SweepDropParams& p) {
  rft::SoilParameters effective = plan.soils[p.soil];
  if (p.zeta_N_m3) effective.zeta_N_m3 = *p.zeta_N_m3;
  return effective.ZetaAtGravity(p.gravity_m_s2);
}

DropRecord Describe(const SweepPlan& plan, const SweepDropParams& p) {
  DropRecord r;
  r.index = p.index;
  r.drop_id = plan.DropId(p.index);
  const PadSpec& pad = plan.pads[p.pad];
  const rft::SoilParameters& soil = plan.soils[p.soil];
  r.pad = pad.name;
  r.soil = soil.name;
  r.atmosphere = soil.atmosphere;
  r.impact_speed_m_s = p.impact_speed_m_s;
  r.pad_mass_kg = p.mass_kg.value_or(pad.mass_kg);
  r.gravity_m_s2 = p.gravity_m_s2;
  r.tilt_deg = p.tilt_rad * 180.0 / std::numbers::pi;
  r.horizontal_speed_m_s = p.horizontal_speed_m_s;
  r.zeta_N_cm3 = EffectiveZeta(plan, p) / 1e6;
  return r;
}

void MarkFailed(DropRecord& r, const std::string& reason) {
  r.ok = false;
  r.failure = reason.empty() ? "unknown failure" : reason;
  for (double* v : {&r.final_penetration_m, &r.peak_force_N, &r.time_to_rest_s, &r.max_deceleration_m_s2,
                    &r.impact_energy_J, &r.gravity_work_J, &r.dissipated_energy_J, &r.mean_conversion_rate_W,
                    &r.rest_creep_m})
    *v = std::nan("");
  r.trace.clear();
}

RigDropResult RunRigSweepDrop(const SweepModels& models, const SweepDropParams& p, const DropRecord& r) {
  const geom::AxisymmetricIntrusion& intrusion = models.intrusion(p.pad);
  const double zeta = EffectiveZeta(models.plan(), p);
  const VerticalResistance resistance = [&intrusion, zeta](double depth_m, double) {
    return intrusion.VerticalForce(depth_m, zeta);
  };
  return RunRigDrop({r.pad_mass_kg, r.gravity_m_s2, r.impact_speed_m_s}, resistance, models.plan().rig);
}

// The 6-DOF free drop (tilted or sliding pads) goes here once it exists.
RigDropResult RunFreeSweepDrop(const SweepModels&, const SweepDropParams&, const DropRecord&) {
  throw std::runtime_error("the 6-DOF free drop is not available in this build");
}
}  // namespace

bool FreeDropAvailable() { return false; }

SweepModels::SweepModels(const SweepPlan& plan) : plan_(plan) {
  for (const PadSpec& pad : plan.pads)
    intrusions_.push_back(std::make_unique<geom::AxisymmetricIntrusion>(pad.profile, rft::Li2013Law{}));
}

SweepModels::~SweepModels() = default;

std::vector<DropSample> DecimateTrace(const std::vector<DropSample>& trace, int max_samples) {
  const size_t n = trace.size(), m = static_cast<size_t>(max_samples);
  if (n <= m || max_samples < 3) return trace;
  // m evenly spaced indices (distinct since n > m), ends included; the inner one nearest the
  // peak force is moved onto it, so the peak is never lost.
  std::vector<size_t> keep(m);
  for (size_t j = 0; j < m; ++j) keep[j] = j * (n - 1) / (m - 1);
  size_t peak = 0;
  for (size_t i = 1; i < n; ++i)
    if (trace[i].force_N > trace[peak].force_N) peak = i;
  if (std::find(keep.begin(), keep.end(), peak) == keep.end()) {
    const size_t b = std::upper_bound(keep.begin(), keep.end(), peak) - keep.begin(), a = b - 1;  // keep[a] < peak < keep[b]
    const size_t pick = a == 0 ? b : b == m - 1 ? a : (peak - keep[a] <= keep[b] - peak ? a : b);
    keep[pick] = peak;  // stays sorted: peak lies between the neighbours
  }
  std::vector<DropSample> out;
  for (size_t i : keep) out.push_back(trace[i]);
  return out;
}

DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index) {
  return SimulateSweepDrop(models, index, models.plan().traces);
}

DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index, TraceStorage storage) {
  const SweepPlan& plan = models.plan();
  const SweepDropParams p = plan.DropAt(index);
  DropRecord r = Describe(plan, p);
  try {
    const bool rig = p.tilt_rad == 0.0 && p.horizontal_speed_m_s == 0.0;
    const RigDropResult d = rig ? RunRigSweepDrop(models, p, r) : RunFreeSweepDrop(models, p, r);
    r.ok = true;
    r.final_penetration_m = d.final_penetration_m;
    r.peak_force_N = d.peak_force_N;
    r.time_to_rest_s = d.time_to_rest_s;
    r.max_deceleration_m_s2 = d.max_deceleration_m_s2;
    r.impact_energy_J = d.impact_energy_J;
    r.gravity_work_J = d.gravity_work_J;
    r.dissipated_energy_J = d.dissipated_energy_J;
    r.mean_conversion_rate_W = d.mean_conversion_rate_W;
    r.rest_creep_m = d.rest_creep_m;
    r.solver_steps = d.solver.steps;
    if (storage == TraceStorage::kFull) r.trace = d.trace;
    else if (storage == TraceStorage::kDecimated) r.trace = DecimateTrace(d.trace, plan.trace_max_samples);
  } catch (const std::exception& e) {
    MarkFailed(r, e.what());
  }
  return r;
}

}  // namespace touchdown::drop

#include "drop_tests/sweep/sweep_drop.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "drop_tests/scenario/lander_leg_load.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/drop/drop_columns.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "rft/units.h"

namespace touchdown::sweep {

namespace {
using units::kDeg;

// The sweep point's row (the atmosphere is the soil's), under the model's effects.
drop::DropConditions ConditionsOf(const SweepModels& models, const SweepDropParams& p) {
  const SweepPlan& plan = models.plan();
  drop::DropConditions c = drop::DropConditionsFor(p, models.effects(), plan.model ? plan.model->source : "",
                                                   plan.source + ": drop " + plan.DropId(p.index));
  // A mesh pad has no profile for the rig's integral: the free 6-DOF pad, level and straight
  // down unless tilted or sliding.
  c.free = !plan.pads[p.pad].is_axisymmetric();
  return c;
}

DropRecord Describe(const SweepPlan& plan, const SweepDropParams& p, const drop::DropConditions& c) {
  DropRecord r;
  r.index = p.index;
  r.drop_id = plan.DropId(p.index);
  r.kind = c.IsFree() ? DropKind::kFree : DropKind::kRig;
  const io::PadSpec& pad = plan.pads[p.pad];
  const rft::SoilParameters& soil = plan.soils[p.soil];
  r.pad = pad.name;
  r.soil = soil.name;
  r.atmosphere = soil.atmosphere;
  r.impact_speed_m_s = p.impact_speed_m_s;
  r.pad_mass_kg = p.mass_kg.value_or(pad.mass_kg);
  r.gravity_m_s2 = p.gravity_m_s2;
  r.tilt_deg = p.tilt_rad / kDeg;
  r.horizontal_speed_m_s = p.horizontal_speed_m_s;
  r.zeta_N_cm3 = units::ZetaToN_cm3(drop::EffectiveZeta(soil, c));
  return r;
}

// Each rig drop metric beside the record's column of the same name (results_db.h): one name for a
// metric in `touchdown drop`'s summary, the database and the exports.
struct MetricColumn {
  double pad::RigDropResult::*metric;
  const RecordNumber* column;
};
const std::vector<MetricColumn>& MetricColumns() {
  static const std::vector<MetricColumn> c = [] {
    std::vector<MetricColumn> out;
    for (const drop::ResultNumber<pad::RigDropResult>& m : drop::RigMetrics())
      out.push_back({m.member, &RecordNumberNamed(m.name)});
    return out;
  }();
  return c;
}

void MarkFailed(DropRecord& r, const std::string& reason) {
  r.ok = false;
  r.failure = reason.empty() ? "unknown failure" : reason;
  for (const MetricColumn& m : MetricColumns()) m.column->at(r) = std::nan("");
  for (double* v : {&r.final_tilt_deg, &r.horizontal_travel_m, &r.final_roll_deg, &r.final_pitch_deg,
                    &r.tipped_over, &r.max_tilt_deg, &r.peak_leg_force_N, &r.max_stroke_m, &r.max_joint_swing_deg,
                    &r.tip_over_edge, &r.tip_over_azimuth_deg})
    *v = std::nan("");
  r.pad_final_penetration_m.fill(std::nan(""));
  r.pad_peak_force_N.fill(std::nan(""));
  r.trace.clear();
}

// A drop that ran out of a work limit: failed, naming the limit and its value (so a rerun with a
// higher limit knows to retry it).
void MarkOutOfLimit(DropRecord& r, const integ::LimitExceeded& e) {
  MarkFailed(r, e.what());
  r.failure_limit = e.limit();
  r.failure_limit_value = e.value();
}

DropRecord SimulatePadSweepDrop(const SweepModels& models, const SweepDropParams& p, TraceStorage storage) {
  const SweepPlan& plan = models.plan();
  const drop::DropConditions c = ConditionsOf(models, p);
  DropRecord r = Describe(plan, p, c);
  try {
    drop::DropRunOptions options = models.drop_options();
    options.intrusion = models.has_intrusion(p.pad) ? &models.intrusion(p.pad) : nullptr;
    const io::PadSpec& pad = c.IsFree() ? models.free_pad(p.pad) : plan.pads[p.pad];
    const drop::PadDrop drop = drop::RunDrop(drop::ResolveDrop(pad, plan.soils[p.soil], c, options));
    const pad::RigDropResult& d = drop.result;
    r.ok = true;
    for (const MetricColumn& m : MetricColumns()) m.column->at(r) = d.*m.metric;
    r.solver_steps = d.solver.steps;
    // The rig stays level on its rod and does not travel.
    r.final_tilt_deg = drop.free ? drop.free->final_tilt_deg : 0.0;
    r.horizontal_travel_m = drop.free ? drop.free->horizontal_travel_m : 0.0;
    if (storage == TraceStorage::kFull) r.trace = d.trace;
    else if (storage == TraceStorage::kDecimated) r.trace = DecimateTrace(d.trace, plan.trace_max_samples);
  } catch (const integ::LimitExceeded& e) {
    MarkOutOfLimit(r, e);
  } catch (const std::exception& e) {
    MarkFailed(r, e.what());
  }
  return r;
}

// The horizontal velocity a drop sets: speed and azimuth, each the scenario's unless given (a
// drop that gives only the speed moves along world +x, as lander sweeps always did).
Eigen::Vector2d HorizontalVelocity(const scenario::LanderScenario& sc, const SweepDropParams& p) {
  const Eigen::Vector2d& v = sc.initial.horizontal_velocity_m_s;
  const double speed = p.Given(SweepParam::kHorizontalSpeed) ? p.horizontal_speed_m_s : v.norm();
  const double azimuth = p.Given(SweepParam::kHorizontalAzimuth) ? p.horizontal_azimuth_rad
                         : p.Given(SweepParam::kHorizontalSpeed) ? 0.0
                                                                 : std::atan2(v.y(), v.x());
  return speed * Eigen::Vector2d(std::cos(azimuth), std::sin(azimuth));
}

// The ground's slope and the touchdown conditions relative to it that the drop sets.
void ApplyGroundAndMotion(scenario::LanderScenario& sc, const SweepDropParams& p) {
  if (p.Given(SweepParam::kSlope)) sc.ground.slope_rad = p.slope_rad;
  if (p.Given(SweepParam::kDownhillAzimuth)) sc.ground.downhill_azimuth_rad = p.downhill_azimuth_rad;
  if (p.Given(SweepParam::kYawToSlope)) sc.initial.yaw_relative_to_slope_rad = p.yaw_to_slope_rad;
  if (p.Given(SweepParam::kHorizontalSpeed) || p.Given(SweepParam::kHorizontalAzimuth))
    sc.initial.horizontal_velocity_m_s = HorizontalVelocity(sc, p);
  const SweepParam rates[3] = {SweepParam::kRateX, SweepParam::kRateY, SweepParam::kRateZ};
  for (int k = 0; k < 3; ++k)
    if (p.Given(rates[k])) sc.initial.angular_rate_B[k] = p.angular_rate_rad_s[k];
}

// Over the trace: the peak axial leg load of any leg (compression positive: an absorber's force, or
// a rigid leg's pad force along the leg axis, hip to joint) and the largest absorber stroke (NaN if
// no leg has an absorber).
void RecordLegLoads(const scenario::LanderSpec& lander, const lander::LanderRunResult& l, DropRecord& r) {
  bool any_absorber = false;
  double peak = 0.0, stroke = 0.0;
  for (const scenario::LegLoadSummary& leg : scenario::LegLoadSummaries(lander, l.trace)) {
    peak = std::max(peak, leg.peak_axial_force_N);
    if (leg.max_stroke_m) any_absorber = true, stroke = std::max(stroke, *leg.max_stroke_m);
  }
  r.peak_leg_force_N = peak;
  r.max_stroke_m = any_absorber ? stroke : std::nan("");
}

// The conditions a lander drop ran under, as recorded (degrees).
void RecordConditions(const scenario::LanderScenario& sc, DropRecord& r) {
  r.slope_deg = sc.ground.slope_rad / kDeg;
  r.downhill_azimuth_deg = sc.ground.downhill_azimuth_rad / kDeg;
  r.yaw_relative_to_slope_deg = sc.initial.yaw_relative_to_slope_rad / kDeg;
  const Eigen::Vector2d& v = sc.initial.horizontal_velocity_m_s;
  r.horizontal_azimuth_deg = std::atan2(v.y(), v.x()) / kDeg;
  for (int k = 0; k < 3; ++k) r.angular_rate_deg_s[k] = sc.initial.angular_rate_B[k] / kDeg;
}

// One lander run: the plan's scenario with the drop's parameters.
DropRecord SimulateLanderSweepDrop(const SweepModels& models, const SweepDropParams& p) {
  const SweepPlan& plan = models.plan();
  scenario::LanderScenario sc = *plan.lander;  // the model is already in it (LoadSweepPlan)
  if (p.Given(SweepParam::kPad)) sc.lander = scenario::LanderSpecWithPad(sc.lander, plan.pads[p.pad]);
  if (p.Given(SweepParam::kGravity)) sc.gravity_m_s2 = p.gravity_m_s2;
  if (p.Given(SweepParam::kSoil)) sc.ground.default_soil = plan.soil_refs[p.soil];
  if (p.Given(SweepParam::kImpactSpeed)) {
    sc.initial.drop_height_m.reset();
    sc.initial.release_vertical_speed_m_s = 0.0;
    sc.initial.touchdown_speed_m_s = p.impact_speed_m_s;
  }
  ApplyGroundAndMotion(sc, p);
  if (p.Given(SweepParam::kRoll)) sc.initial.roll_rad = p.roll_rad;
  if (p.Given(SweepParam::kPitch)) sc.initial.pitch_rad = p.pitch_rad;
  if (p.Given(SweepParam::kPadSoils)) {
    // The scenario's patches give way to one square under each pad whose soil is not the ground's.
    sc.ground.patches.clear();
    const PadSoilSet& set = plan.pad_soil_sets[p.pad_soils];
    for (int i = 0; i < lander::kNumLegs; ++i) {
      const std::string& ref = plan.soil_refs[set.soil[i]];
      if (ref == sc.ground.default_soil) continue;
      sc.ground.patches.push_back({"pad_soils_under_pad_" + std::to_string(i + 1), ref,
                                   scenario::UnderPadSquare{i + 1, plan.pad_patch_half_width_m}});
    }
  }
  // A random patch field drawn per landing: its seed from the study's and the landing's index, so
  // the landing has the same ground whatever the threads, ranks or shards (soil_field.h).
  if (sc.ground.soil_field && sc.ground.soil_field->seed_per_landing) {
    sc.ground.soil_field->seed = scenario::PerLandingFieldSeed(plan.seed, p.index);
    sc.ground.soil_field->seed_per_landing = false;
  }
  if (plan.soil_overrides_at) {  // this landing's soil parameters, drawn by the study
    model::ModelFile m = sc.model ? *sc.model : model::ModelFile{};
    for (const auto& [soil, o] : plan.soil_overrides_at(p.index)) m.soils[soil] = o;
    sc.model = std::move(m);
  }
  // The sweep's limits replace the scenario's (none given there: a lander run has only max_num_steps).
  sc.options.integrator.max_wall_time_s = plan.rig.integrator.max_wall_time_s;
  sc.options.integrator.max_rhs_evaluations = plan.rig.integrator.max_rhs_evaluations;

  DropRecord r;
  r.index = p.index;
  r.drop_id = plan.DropId(p.index);
  r.kind = DropKind::kLander;
  const rft::SoilParameters& soil = p.Given(SweepParam::kSoil) ? plan.soils[p.soil] : models.lander_soil();
  r.pad = sc.lander.pad.name;
  r.soil = soil.name;
  r.atmosphere = soil.atmosphere;
  r.impact_speed_m_s = scenario::TouchdownSpeed(sc);
  r.pad_mass_kg = sc.lander.pad.body.mass_kg;
  r.gravity_m_s2 = sc.gravity_m_s2;
  r.roll_deg = sc.initial.roll_rad / kDeg;
  r.pitch_deg = sc.initial.pitch_rad / kDeg;
  // Body z from the vertical after roll and pitch (z_W component cos(roll) cos(pitch)).
  r.tilt_deg = std::acos(std::clamp(std::cos(sc.initial.roll_rad) * std::cos(sc.initial.pitch_rad), -1.0, 1.0)) / kDeg;
  r.horizontal_speed_m_s = sc.initial.horizontal_velocity_m_s.norm();
  r.zeta_N_cm3 = units::ZetaToN_cm3(soil.ZetaAtGravity(sc.gravity_m_s2));
  RecordConditions(sc, r);
  try {
    lander::LanderSetup setup = scenario::ResolveLander(sc, &models.lander_soils());
    // The soil under each pad's joint at release, as the ground was built.
    for (int i = 0; i < lander::kNumLegs; ++i) {
      const Eigen::Vector3d c = setup.initial.p_WB + setup.initial.R_WB * setup.model.legs[i].joint_B;
      r.pad_soil[i] = models.SoilName(setup.terrain.soils[setup.terrain.SoilAt(c.x(), c.y())].name);
    }
    r.ground_case = PaperGroundCase(r.pad_soil);
    const scenario::LanderRun run = scenario::RunLanderScenario(sc, std::move(setup));
    const lander::LanderRunResult& l = run.result;
    r.ok = true;
    for (int i = 0; i < lander::kNumLegs; ++i) r.pad_final_penetration_m[i] = l.final_penetration_m[i];
    r.final_penetration_m = *std::max_element(l.final_penetration_m.begin(), l.final_penetration_m.end());
    r.peak_force_N = *std::max_element(l.peak_pad_force_N.begin(), l.peak_pad_force_N.end());
    r.max_deceleration_m_s2 = l.max_body_deceleration_m_s2;
    r.dissipated_energy_J = l.dissipated_J;
    r.rest_creep_m = std::nan("");
    r.final_roll_deg = l.final_attitude.roll_rad / kDeg;
    r.final_pitch_deg = l.final_attitude.pitch_rad / kDeg;
    r.final_tilt_deg = l.final_attitude.tilt_rad / kDeg;
    r.tipped_over = l.tipped_over ? 1.0 : 0.0;
    r.max_tilt_deg = l.max_tilt_rad / kDeg;
    r.max_joint_swing_deg = l.max_joint_swing_rad / kDeg;
    r.min_stability_margin_m = l.min_stability_margin_m;
    if (l.tipped_over) {
      r.tip_over_edge = l.tip_over_edge + 1;
      r.tip_over_azimuth_deg = l.tip_over_azimuth_rad / kDeg;
    }
    for (int i = 0; i < lander::kNumLegs; ++i) r.pad_peak_force_N[i] = l.peak_pad_force_N[i];
    RecordLegLoads(sc.lander, l, r);
    r.solver_steps = l.solver.steps;
    r.time_to_rest_s = l.rest_time_s && l.first_touchdown_s ? *l.rest_time_s - *l.first_touchdown_s : std::nan("");
    // At the first touchdown (an event, so a trace sample): kinetic energy, potential energy and
    // position, for the impact energy, the weight's work and the horizontal travel.
    r.impact_energy_J = r.gravity_work_J = r.horizontal_travel_m = r.mean_conversion_rate_W = std::nan("");
    if (l.first_touchdown_s && !l.trace.empty()) {
      const auto td = std::find_if(l.trace.begin(), l.trace.end(),
                                   [&](const lander::LanderSample& s) { return s.t_s >= *l.first_touchdown_s; });
      if (td != l.trace.end()) {
        r.impact_energy_J = td->kinetic_J;
        r.gravity_work_J = td->potential_J - l.final_potential_J;
        r.horizontal_travel_m = (l.trace.back().p_WB.head<2>() - td->p_WB.head<2>()).norm();
        if (r.time_to_rest_s > 0.0) r.mean_conversion_rate_W = r.impact_energy_J / r.time_to_rest_s;
      }
    }
  } catch (const integ::LimitExceeded& e) {
    MarkOutOfLimit(r, e);
  } catch (const std::exception& e) {
    MarkFailed(r, e.what());
  }
  return r;
}
}  // namespace

SweepModels::SweepModels(const SweepPlan& plan) : plan_(plan) {
  for (const io::PadSpec& pad : plan.pads)  // none for a mesh pad: its drops are free drops
    intrusions_.push_back(pad.is_axisymmetric()
                              ? drop::MakeRigIntrusion(pad.profile)
                              : nullptr);
  if (plan.free_drop_model != drop::FreeDropModel::kReference)
    for (const io::PadSpec& pad : plan.pads)
      free_pads_.push_back(drop::FreeDropPad(pad, plan.free_drop_model, plan.source, "simulation.free_drop_model"));
  if (plan.model) effects_ = model::ModelEffectTerms(*plan.model);
  // The free pad's integration follows the plan's model, and the plan's sampling and work limits,
  // which the sweep states once for both kinds of drop.
  drop_options_.rig = plan.rig;
  drop_options_.free = drop::FreeDropOptionsFor(plan.free_drop_model);
  drop_options_.free.sample_rate_hz = plan.rig.sample_rate_hz;
  drop_options_.free.integrator.max_wall_time_s = plan.rig.integrator.max_wall_time_s;
  drop_options_.free.integrator.max_rhs_evaluations = plan.rig.integrator.max_rhs_evaluations;
  if (plan.lander) {
    // Every soil a landing's ground may name (the scenario's and the sweep's), read once, not per landing.
    lander_soils_ = scenario::LoadLanderSoils(*plan.lander, plan.soil_refs);
    lander_soil_ = lander_soils_.at(plan.lander->ground.default_soil);
    if (plan.model) lander_soil_ = model::ApplyModel(*plan.model, lander_soil_);
    soil_names_[plan.lander->ground.default_soil] = lander_soils_.at(plan.lander->ground.default_soil).name;
    for (const scenario::LanderPatchSpec& patch : plan.lander->ground.patches) soil_names_[patch.soil] = lander_soils_.at(patch.soil).name;
    for (size_t i = 0; i < plan.soil_refs.size(); ++i) soil_names_[plan.soil_refs[i]] = plan.soils[i].name;
  }
}

const std::string& SweepModels::SoilName(const std::string& ref) const {
  const auto it = soil_names_.find(ref);
  return it == soil_names_.end() ? ref : it->second;
}

SweepModels::~SweepModels() = default;

std::vector<pad::DropSample> DecimateTrace(const std::vector<pad::DropSample>& trace, int max_samples) {
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
  std::vector<pad::DropSample> out;
  for (size_t i : keep) out.push_back(trace[i]);
  return out;
}

DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index) {
  return SimulateSweepDrop(models, index, models.plan().traces);
}

DropRecord SimulateSweepDrop(const SweepModels& models, int64_t index, TraceStorage storage) {
  const SweepPlan& plan = models.plan();
  const SweepDropParams p = plan.DropAt(index);
  DropRecord r = plan.lander ? SimulateLanderSweepDrop(models, p) : SimulatePadSweepDrop(models, p, storage);
  if (plan.soil_parameters_at) r.soil_parameters = plan.soil_parameters_at(index);
  return r;
}

}  // namespace touchdown::sweep

#include "drop_tests/scenario/lander_outputs.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/scenario/lander_leg_load.h"
#include "drop_tests/scenario/lander_plots.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/scenario/lander_trace_columns.h"
#include "drop_tests/scenario/lander_vtk.h"
#include "lander/multibody/static_stability.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;
using units::kDeg;


nlohmann::json LanderSummaryJson(const LanderRun& run) {
  const lander::LanderRunResult& r = run.result;
  auto arr = [](const std::array<double, lander::kNumLegs>& a) { return nlohmann::json(std::vector<double>(a.begin(), a.end())); };
  // JSON numbers are never null: a pad that never touched down is absent from touchdown_pads, and
  // touchdown_time_s is aligned with it; a lander never at rest has no rest times (came_to_rest false).
  nlohmann::json touchdown = nlohmann::json::array(), touchdown_pads = nlohmann::json::array();
  for (size_t i = 0; i < r.touchdown_time_s.size(); ++i)
    if (r.touchdown_time_s[i]) {
      touchdown.push_back(*r.touchdown_time_s[i]);
      touchdown_pads.push_back(i + 1);
    }
  const double final_energy = r.final_kinetic_J + r.final_potential_J + r.dissipated_J;
  const double roll = r.final_attitude.roll_rad / kDeg, pitch = r.final_attitude.pitch_rad / kDeg;
  nlohmann::json j{
      {"scenario", run.scenario.name},
      {"lander", run.scenario.lander.name},
      {"pads_order", "clockwise from above, pad 1 front-left (paper numbering)"},
      {"soil_under_pad", run.soil_under_pad},
      {"gravity_m_s2", run.scenario.gravity_m_s2},
      {"final_penetration_m", arr(r.final_penetration_m)},
      {"final_roll_deg", roll},
      {"final_pitch_deg", pitch},
      {"max_tilt_deg", r.max_tilt_rad / kDeg},
      {"max_joint_swing_deg", r.max_joint_swing_rad / kDeg},
      {"tipped_over", r.tipped_over},
      {"peak_pad_force_N", arr(r.peak_pad_force_N)},
      {"max_body_deceleration_m_s2", r.max_body_deceleration_m_s2},
      {"came_to_rest", r.rest_time_s.has_value()},
      {"touchdown_pads", touchdown_pads},
      {"touchdown_time_s", touchdown},
      {"end_time_s", r.end_time_s},
      {"initial_energy_J", r.initial_energy_J},
      {"final_kinetic_energy_J", r.final_kinetic_J},
      {"final_potential_energy_J", r.final_potential_J},
      {"dissipated_energy_J", r.dissipated_J},
      {"capture_loss_J", r.capture_loss_J},
      {"energy_balance_error_J", final_energy - r.initial_energy_J},
      {"max_held_pad_drift_m", r.max_held_drift_m},
      {"events", r.events.size()},
      {"solver_steps", r.solver.steps},
      {"rhs_evaluations", r.solver.rhs_evaluations},
  };
  // Per leg, pads in order: what an inspection of the gear reads after the landing.
  nlohmann::json legs = nlohmann::json::array();
  const std::array<LegLoadSummary, lander::kNumLegs> loads = LegLoadSummaries(run.scenario.lander, r.trace);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    nlohmann::json leg{{"pad", i + 1}, {"peak_axial_force_N", loads[i].peak_axial_force_N}};
    if (loads[i].max_stroke_m) leg["max_stroke_m"] = *loads[i].max_stroke_m;
    if (loads[i].stroke_left_m) leg["stroke_left_m"] = *loads[i].stroke_left_m;
    if (std::isfinite(run.scenario.lander.legs[i].load_limit_N)) {
      leg["load_limit_N"] = run.scenario.lander.legs[i].load_limit_N;
      leg["over_limit"] = loads[i].over_limit_s.has_value();
      if (loads[i].over_limit_s) leg["over_limit_time_s"] = *loads[i].over_limit_s;
    }
    legs.push_back(leg);
  }
  j["legs"] = legs;
  // The support polygon's edges at the end (joint centres, pads clockwise): over each, the static
  // tip-over angle (the rotation about the edge that brings the centre of mass above it, from the
  // attitude and sinkage the landing left; negative once outside) and the energy barrier to it.
  nlohmann::json edges = nlohmann::json::array();
  const lander::StateLayout layout = lander::RunStateLayout(run.setup.model, run.setup.terrain);
  if (r.final_state.size() == layout.size)
    for (const lander::EdgeTipping& e : lander::EdgeTippings(run.setup.model, layout, r.final_state))
      edges.push_back({{"pads", {e.from_leg + 1, e.to_leg + 1}},
                       {"static_tip_angle_deg", e.tip_angle_rad / kDeg},
                       {"barrier_J", e.barrier_J}});
  j["support_edges_at_end"] = edges;
  if (r.rest_time_s) {
    j["rest_time_since_release_s"] = *r.rest_time_s;
    if (r.first_touchdown_s) j["time_to_rest_s"] = *r.rest_time_s - *r.first_touchdown_s;
  }
  if (r.tipped_over) {  // the support edge it went over (pads clockwise) and the direction it fell
    j["tip_over_edge_pads"] = {r.tip_over_edge + 1, (r.tip_over_edge + 1) % lander::kNumLegs + 1};
    j["tip_over_azimuth_deg"] = r.tip_over_azimuth_rad / kDeg;
  }
  j["touchdown_speed_m_s"] = TouchdownSpeed(run.scenario);
  if (run.scenario.model) j["model"] = model::ModelEffectsJson(*run.scenario.model);
  if (!run.scenario.paper_ground_case.empty()) j["paper_ground_case"] = run.scenario.paper_ground_case;
  if (run.scenario.paper) j["paper_check"] = LanderPaperCheckJson(*run.scenario.paper, roll, pitch);
  return j;
}

nlohmann::json LanderPaperCheckJson(const LanderPaperCheck& check, double roll_deg, double pitch_deg) {
  const double within = check.roll_pitch_within_deg;
  nlohmann::json j{{"quantity", "final roll and pitch"},
                   {"paper_within_deg", within},
                   {"simulated_roll_deg", roll_deg},
                   {"simulated_pitch_deg", pitch_deg},
                   {"within_paper_band", std::abs(roll_deg) <= within && std::abs(pitch_deg) <= within},
                   {"source", check.source},
                   {"used_for_fit", check.used_for_fit}};
  if (check.used_for_fit) j["fit_by"] = check.fit_by;
  if (check.reading) j["reading"] = std::string(PaperReadingName(*check.reading));
  return j;
}

void WriteLanderTraceCsv(const LanderRun& run, const std::string& path) {
  const std::vector<LanderTraceColumn>& columns = LanderTraceColumns();
  io::WriteFileAtomically(path, [&](std::ostream& out) {
    for (size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].name;
    out << '\n' << std::setprecision(10);
    for (const lander::LanderSample& s : run.result.trace) {
      for (size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].value(s);
      out << '\n';
    }
  });
}

void WriteLanderOutputs(const LanderRun& run, const io::OutputTarget& out, const LanderOutputOptions& options) {
  io::WriteOutputDirectory(out, io::OutputKind::kLander, [&](const std::string& staging_dir) {
    const fs::path staging = staging_dir;
    WriteLanderTraceCsv(run, (staging / "trace.csv").string());
    io::WriteFileAtomically((staging / "events.csv").string(), [&](std::ostream& out) {
      out << "t_s,event,pad\n" << std::setprecision(12);
      for (const lander::LanderEvent& e : run.result.events)
        out << e.t_s << ',' << lander::LanderEventName(e.kind) << ',' << (e.leg >= 0 ? std::to_string(e.leg + 1) : std::string()) << '\n';
    });
    io::WriteFileAtomically((staging / "summary.json").string(),
                        [&](std::ostream& out) { out << LanderSummaryJson(run).dump(2) << '\n'; });
    WriteResolvedLanderScenario(run.scenario, run.setup, (staging / "scenario_resolved.yaml").string(), out.path);
    WriteLanderPlots(run, staging.string());
    if (options.vtk) WriteLanderVtk(run, (staging / "vtk").string());
  });
}

}  // namespace touchdown::scenario

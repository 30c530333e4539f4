#include "drop_tests/drop/drop_columns.h"

namespace touchdown::drop {

const std::vector<ResultNumber<pad::RigDropResult>>& RigMetrics() {
  using R = pad::RigDropResult;
  static const std::vector<ResultNumber<R>> c = {
      {"final_penetration_m", &R::final_penetration_m},
      {"peak_force_N", &R::peak_force_N},
      {"time_to_rest_s", &R::time_to_rest_s},
      {"max_deceleration_m_s2", &R::max_deceleration_m_s2},
      {"impact_energy_J", &R::impact_energy_J},
      {"gravity_work_J", &R::gravity_work_J},
      {"dissipated_energy_J", &R::dissipated_energy_J},
      {"mean_conversion_rate_W", &R::mean_conversion_rate_W},
      {"rest_creep_m", &R::rest_creep_m}};
  return c;
}

const std::vector<ResultNumber<pad::FreeDropResult>>& FreeMetrics() {
  using F = pad::FreeDropResult;
  static const std::vector<ResultNumber<F>> c = {
      {"final_penetration_m", &F::final_penetration_m},
      {"peak_force_N", &F::peak_force_N},
      {"time_to_rest_s", &F::time_to_rest_s},
      {"max_deceleration_m_s2", &F::max_deceleration_m_s2},
      {"impact_energy_J", &F::impact_energy_J},
      {"gravity_work_J", &F::gravity_work_J},
      {"dissipated_energy_J", &F::dissipated_energy_J},
      {"touchdown_tilt_deg", &F::touchdown_tilt_deg},
      {"final_tilt_deg", &F::final_tilt_deg},
      {"horizontal_travel_m", &F::horizontal_travel_m}};
  return c;
}

const std::vector<TraceColumn<pad::DropSample>>& RigTraceColumns() {
  using S = pad::DropSample;
  static const std::vector<TraceColumn<S>> c = {
      {"t_s", [](const S& s) { return s.t_s; }},
      {"penetration_m", [](const S& s) { return s.penetration_m; }},
      {"velocity_m_s", [](const S& s) { return s.velocity_m_s; }},
      {"force_N", [](const S& s) { return s.force_N; }}};
  return c;
}

const std::vector<TraceColumn<pad::FreeDropSample>>& FreeTraceColumns() {
  using S = pad::FreeDropSample;
  static const std::vector<TraceColumn<S>> c = {
      {"t_s", [](const S& s) { return s.t_s; }},
      {"penetration_m", [](const S& s) { return s.penetration_m; }},
      {"velocity_m_s", [](const S& s) { return s.velocity_m_s; }},
      {"force_N", [](const S& s) { return s.force_N; }},
      {"force_x_N", [](const S& s) { return s.force_x_N; }},
      {"horizontal_m", [](const S& s) { return s.horizontal_m; }},
      {"tilt_deg", [](const S& s) { return s.tilt_deg; }},
      {"x_m", [](const S& s) { return s.p_WB[0]; }},
      {"y_m", [](const S& s) { return s.p_WB[1]; }},
      {"z_m", [](const S& s) { return s.p_WB[2]; }},
      {"qw", [](const S& s) { return s.q_WB[0]; }},
      {"qx", [](const S& s) { return s.q_WB[1]; }},
      {"qy", [](const S& s) { return s.q_WB[2]; }},
      {"qz", [](const S& s) { return s.q_WB[3]; }},
      {"wx_rad_s", [](const S& s) { return s.w_W[0]; }},
      {"wy_rad_s", [](const S& s) { return s.w_W[1]; }},
      {"wz_rad_s", [](const S& s) { return s.w_W[2]; }}};
  return c;
}

}  // namespace touchdown::drop

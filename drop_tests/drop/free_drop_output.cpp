#include "drop_tests/drop/free_drop_output.h"

#include <iomanip>
#include <nlohmann/json.hpp>


namespace touchdown::drop {

nlohmann::json FreeDropJson(const pad::FreeDropResult& r) {
  return nlohmann::json{
      {"mode", "free"},
      {"final_penetration_m", r.final_penetration_m},
      {"peak_force_N", r.peak_force_N},
      {"time_to_rest_s", r.time_to_rest_s},
      {"max_deceleration_m_s2", r.max_deceleration_m_s2},
      {"impact_energy_J", r.impact_energy_J},
      {"gravity_work_J", r.gravity_work_J},
      {"dissipated_energy_J", r.dissipated_energy_J},
      {"touchdown_tilt_deg", r.touchdown_tilt_deg},
      {"final_tilt_deg", r.final_tilt_deg},
      {"horizontal_travel_m", r.horizontal_travel_m},
      {"solver_steps", r.solver.steps},
  };
}

void WriteFreeDropTraceCsv(const pad::FreeDropResult& r, std::ostream& out) {
  out << "t_s,penetration_m,velocity_m_s,force_N,force_x_N,horizontal_m,tilt_deg,"
         "x_m,y_m,z_m,qw,qx,qy,qz,wx_rad_s,wy_rad_s,wz_rad_s\n"
      << std::setprecision(10);
  for (const pad::FreeDropSample& s : r.trace) {
    out << s.t_s << ',' << s.penetration_m << ',' << s.velocity_m_s << ',' << s.force_N << ',' << s.force_x_N << ','
        << s.horizontal_m << ',' << s.tilt_deg;
    for (int k = 0; k < 3; ++k) out << ',' << s.p_WB[k];
    for (int k = 0; k < 4; ++k) out << ',' << s.q_WB[k];
    for (int k = 0; k < 3; ++k) out << ',' << s.w_W[k];
    out << '\n';
  }
}

}  // namespace touchdown::drop

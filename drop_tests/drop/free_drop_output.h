#pragma once
// JSON summary and trace CSV of a free (6-DOF) pad drop. The trace starts with the rig drop's
// columns (t_s,penetration_m,velocity_m_s,force_N) so the dataset tools read it, then adds
// force_x_N, horizontal_m and tilt_deg, then the full pose so that the drop can be animated: the pad
// frame's origin x_m,y_m,z_m (its reference point, world frame), its attitude qw,qx,qy,qz (unit
// quaternion, pad to world) and the angular velocity wx_rad_s,wy_rad_s,wz_rad_s (world frame).
#include <nlohmann/json_fwd.hpp>
#include <ostream>

#include "lander/pad/free_drop.h"

namespace touchdown::drop {

nlohmann::json FreeDropJson(const pad::FreeDropResult& result);
void WriteFreeDropTraceCsv(const pad::FreeDropResult& result, std::ostream& out);

}  // namespace touchdown::drop

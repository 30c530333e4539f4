#pragma once
// One drop of a catalogued pad on a catalogued soil: the paper's rig (the pad on a vertical rod,
// lander/pad/rig_drop.h) or, when the pad is tilted, slides or spins, the free 6-DOF pad
// (lander/pad/free_drop.h) under the 3D contact: its conditions, its record and its outputs.
// DropConditionsFor turns a dataset row or a sweep point into DropConditions; ResolveDrop
// (drop_setup.h) turns them into what the rig or the free pad runs on, and RunDrop runs it.
#include <Eigen/Core>
#include <optional>
#include <ostream>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/drop/drop_row.h"
#include "drop_tests/model/effects.h"
#include "lander/pad/free_drop.h"
#include "drop_tests/formats/output_path.h"
#include "lander/pad/rig_drop.h"
#include "rft/gravity_constants.h"

namespace touchdown::drop {

// A drop's stated conditions (DropRow) with how to run it.
struct DropConditions : DropRow {
  // The free 6-DOF pad instead of the rig's rod: asked for with `free`, implied by a non-zero
  // tilt, horizontal speed or angular velocity (IsFree).
  bool free = false;
  pad::TiltAxis tilt_axis = pad::TiltAxis::kX;  // DropRow::tilt_rad is about it (world x or y)
  Eigen::Vector3d omega_W = Eigen::Vector3d::Zero();  // angular velocity at release [rad/s]
  std::optional<rft::LawKind> law_3d;   // free drop: the 3D law; none = the soil's rft_law_3d
  rft::EffectTerms effects;                  // default: none (quasi-static RFT)
  std::string effects_source;           // the model file the effects come from (for messages)

  bool IsFree() const {
    return free || tilt_rad != 0.0 || horizontal_speed_m_s != 0.0 || !omega_W.isZero(0.0);
  }
};

// The one place a row becomes the conditions of its drop: every field, the effects (with the
// model file they came from), validated (InputError naming `context`).
DropConditions DropConditionsFor(const DropRow& row, const rft::EffectTerms& effects, const std::string& effects_source,
                                 const std::string& context);

struct PadDrop {
  io::PadSpec pad;  // as loaded, without its 3D body (copying it per drop would cost more than a rig drop)
  rft::SoilParameters soil;      // atmosphere as the drop ran
  DropConditions conditions;
  double mass_kg = 0.0;          // resolved
  double zeta_effective_N_m3 = 0.0;  // at the drop's gravity (before any gas cushion)
  // The rig drop's result; for a free drop its summary and trace in the rig's terms (penetration
  // of the lowest point, vertical velocity and force; rest_creep_m = 0).
  pad::RigDropResult result;
  std::optional<pad::FreeDropResult> free;  // a free drop's own result (tilt, travel, horizontal force)
  // The law the drop ran on: a free drop's 3D law; the rig's Li 2013 (its 2D form) or Bekker.
  rft::LawKind law_3d = rft::LawKind::kLi2013;
  // A free drop's contact model as its summary names it, decorators included
  // ("li2013+rate_damping", rft::SoilContactModel::name); empty for a rig drop.
  std::string contact_model;
  bool in_air() const { return soil.atmosphere == rft::Atmosphere::kAir; }
};

// Throws InputError if a condition is out of range (naming `context`).
void ValidateConditions(const DropConditions& c, const std::string& context);
// zeta at the drop's gravity [N/m^3], as the drop uses it (before any gas cushion).
double EffectiveZeta(const rft::SoilParameters& soil, const DropConditions& c);

// The JSON summary `touchdown drop` prints (SI values, unit-suffixed keys); a free drop adds
// touchdown_tilt_deg, final_tilt_deg, horizontal_travel_m. With active effects: `effects` (those
// applied) and `effects_not_applied` ({id: reason}).
nlohmann::json SummaryJson(const PadDrop& drop);
// Writes the trace as CSV: t_s,penetration_m,velocity_m_s,force_N (a free drop adds
// force_x_N,horizontal_m,tilt_deg and the pose: free_drop_output.h).
void WriteTraceCsv(const pad::RigDropResult& result, std::ostream& out);
void WriteTraceCsv(const pad::RigDropResult& result, const std::string& path);  // a file in a directory touchdown owns
// The user's --trace file: a new file or an earlier trace of touchdown's (its first line is one of the
// traces' headers), never a file touchdown may not have written, in an existing directory.
void CheckTraceTarget(const io::OutputTarget& target);
void WriteTraceCsv(const PadDrop& drop, const io::OutputTarget& target);

}  // namespace touchdown::drop

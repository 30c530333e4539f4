#include "drop_tests/drop/force_request.h"

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "drop_tests/catalog/catalog.h"
#include "lander/pad/pad_pose.h"
#include "drop_tests/formats/vtk_pieces.h"
#include "drop_tests/formats/vtk_writer.h"
#include "drop_tests/model/contact_model.h"
#include "rft/bekker_law.h"
#include "rft/contact_wrench.h"
#include "rft/element_stresses.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::drop {

namespace {
Eigen::Vector3d FiniteVector3(const std::array<double, 3>& v, const std::string& context, const std::string& field) {
  for (double c : v)
    if (!std::isfinite(c)) throw MakeInputError(context, field, "components must be finite");
  return {v[0], v[1], v[2]};
}

// The pad's pose and motion, checked (the pad must move: RFT needs a direction of motion).
rft::PadKinematics RequestKinematics(const ForceRequest& r, const RequestNaming& n) {
  limits::Require(limits::kDepth_m, r.depth_m, n.context, n.Field("depth"));
  limits::Require(limits::kForceTilt_deg, r.tilt_deg, n.context, n.Field("tilt-deg"));
  limits::Require(limits::kGravity_m_s2, r.gravity_m_s2, n.context, "gravity_m_s2");
  if (r.zeta_N_cm3) limits::Require(limits::kZeta_N_cm3, *r.zeta_N_cm3, n.context, n.Field("zeta"));
  rft::PadKinematics k;
  k.v_WB_W = FiniteVector3(r.velocity_m_s, n.context, "velocity");
  k.w_WB_W = FiniteVector3(r.omega_rad_s, n.context, "omega");
  limits::Require(limits::kSpeed_m_s, k.v_WB_W.stableNorm(), n.context, n.Field("velocity") + " (its magnitude)");
  limits::Require(limits::kAngularSpeed_rad_s, k.w_WB_W.stableNorm(), n.context, n.Field("omega") + " (its magnitude)");
  if (k.v_WB_W.norm() == 0.0 && k.w_WB_W.norm() == 0.0)
    throw MakeInputError(n.context, "velocity", "the pad must move (RFT needs a direction of motion)");
  return k;
}

void WriteForceVtk(const io::OutputTarget& target, const geom::PadBody& body, const rft::PadKinematics& k,
                   const rft::StressLaw3D& law, const rft::DepthLaw& depth) {
  rft::ElementStresses stresses;
  rft::ComputeElementStresses(body.surface, k, rft::PlaneGround(), law, depth, &stresses);
  const io::VtkPolyData piece = io::PadSurfacePiece(io::MakePadSurfaceMesh(body.surface), k.R_WB, k.p_WB, stresses);
  io::WriteOutputFile(target, [&](std::ostream& out) { io::WriteVtp({piece}, out); });
}
}  // namespace

HeldPadWrench ComputeHeldPadWrench(const io::PadSpec& pad, const rft::SoilParameters& soil, rft::LawKind law,
                                   double gravity_m_s2, double depth_m, rft::PadKinematics& k) {
  // The contact model (law and pad-level terms): Bekker's z^n is a pad-level depth law.
  HeldPadWrench held{model::MakeContactModel(
                         {.law = law, .soil = soil, .gravity_m_s2 = gravity_m_s2, .pad_surface = &pad.body.surface}),
                     {}};
  k.p_WB = pad::PlaceAtDepth(pad.body, k.R_WB, depth_m);
  held.wrench = rft::ComputeContactWrench(pad.body.surface, k, rft::PlaneGround(), *held.model.law,
                                          held.model.pad_terms);
  return held;
}

nlohmann::json ForceJson(const ForceRequest& r, const RequestNaming& naming, const io::OutputTarget* vtk) {
  rft::PadKinematics k = RequestKinematics(r, naming);
  const pad::TiltAxis axis = pad::ParseTiltAxis(r.tilt_axis);
  k.R_WB = pad::TiltRotation(axis, units::DegToRad(r.tilt_deg));
  const io::PadSpec pad = io::LoadPad(r.pad);
  rft::SoilParameters soil = io::LoadSoil(r.soil);
  if (r.zeta_N_cm3) soil.zeta_N_m3 = units::ZetaFromN_cm3(*r.zeta_N_cm3);
  soil.dynamic_term = soil.dynamic_term && r.dynamic;
  const rft::LawKind kind = r.law ? rft::ParseLawKind(*r.law, naming.context, naming.Field("law")) : soil.rft_law_3d;
  const HeldPadWrench held = ComputeHeldPadWrench(pad, soil, kind, r.gravity_m_s2, r.depth_m, k);
  const rft::StressLaw3D& law = *held.model.law;
  const rft::ContactWrench& w = held.wrench;
  if (vtk) WriteForceVtk(*vtk, pad.body, k, law, held.model.pad_terms.depth);
  nlohmann::json out{
      {"pad", pad.name},
      {"soil", soil.name},
      {"law", std::string(law.name())},
      {"depth_m", r.depth_m},
      {"tilt_deg", r.tilt_deg},
      {"tilt_axis", pad::TiltAxisName(axis)},
      {"velocity_m_s", r.velocity_m_s},
      {"omega_rad_s", r.omega_rad_s},
      {"reference_point_m", {k.p_WB.x(), k.p_WB.y(), k.p_WB.z()}},
      {"force_N", {w.force_W.x(), w.force_W.y(), w.force_W.z()}},
      {"moment_Nm", {w.moment_W.x(), w.moment_W.y(), w.moment_W.z()}},
      {"submerged_area_m2", w.submerged_area_m2},
      {"leading_elements", w.leading_elements},
      {"surface_elements", pad.body.surface.size()},
      {"dynamic_term", soil.dynamic_term},
  };
  if (kind == rft::LawKind::kBekker) out["bekker_plate_b_m"] = rft::BekkerPlateB(pad.body.surface);  // as the law took it
  return out;
}

}  // namespace touchdown::drop

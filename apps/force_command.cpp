// touchdown force: the quasi-static soil wrench on a pad held at a depth, tilt and rigid motion.
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/commands.h"
#include "drop_tests/io/catalog.h"
#include "lander/pad/pad_pose.h"
#include "rft/bekker_law.h"
#include "rft/contact_wrench.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

namespace touchdown::app {

namespace {
struct ForceArgs {
  std::string pad, soil, tilt_axis = "x";
  std::optional<std::string> law;  // none: the soil's own law
  double depth_m = 0.0, tilt_deg = 0.0, gravity_m_s2 = 9.81;
  std::vector<double> velocity{0.0, 0.0, -1.0}, omega{0.0, 0.0, 0.0};
  std::optional<double> zeta_N_cm3;
};

Eigen::Vector3d Vector3(const std::vector<double>& v, const std::string& field) {
  for (double c : v)
    if (!std::isfinite(c)) throw MakeInputError("command line", field, "components must be finite");
  return {v[0], v[1], v[2]};
}

void RequireFinite(double v, const std::string& field, bool positive) {
  if (!std::isfinite(v) || (positive && !(v > 0.0))) {
    std::ostringstream s;
    s << "must be " << (positive ? "positive and " : "") << "finite, got " << v;
    throw MakeInputError("command line", field, s.str());
  }
}
}  // namespace

void AddForceCommand(CLI::App& app) {
  auto a = std::make_shared<ForceArgs>();
  CLI::App* cmd = app.add_subcommand("force", "Quasi-static soil force and moment on a pad at a depth, tilt and motion");
  cmd->add_option("--pad", a->pad, "pad name from data/pads or a pad YAML file")->required();
  cmd->add_option("--soil", a->soil, "soil name from data/soils or a soil YAML file")->required();
  cmd->add_option("--depth", a->depth_m, "depth of the pad's lowest point below the level surface [m]")->required();
  cmd->add_option("--tilt-deg", a->tilt_deg, "tilt of the pad about --tilt-axis [deg]");
  cmd->add_option("--tilt-axis", a->tilt_axis, "x or y (axes of the world frame, z up)");
  cmd->add_option("--velocity", a->velocity, "rigid velocity of the reference point VX,VY,VZ [m/s] (default 0,0,-1)")
      ->expected(3)->delimiter(',');
  cmd->add_option("--omega", a->omega, "angular velocity WX,WY,WZ [rad/s]")->expected(3)->delimiter(',');
  cmd->add_option("--law", a->law,
                  "li2013 (Treers et al. 2021 3D decomposition), agarwal2023 or bekker (default: the soil's own law)");
  cmd->add_option("--zeta", a->zeta_N_cm3, "override the soil's zeta [N/cm^3] (li2013)");
  cmd->add_option("--gravity", a->gravity_m_s2, "gravity [m/s^2] the soil stresses scale with (default 9.81)");
  cmd->callback([a] {
    limits::Require(limits::kDepth_m, a->depth_m, "command line", "--depth");
    limits::Require(limits::kForceTilt_deg, a->tilt_deg, "command line", "--tilt-deg");
    RequireFinite(a->gravity_m_s2, "gravity_m_s2", true);
    if (a->zeta_N_cm3) limits::Require(limits::kZeta_N_cm3, *a->zeta_N_cm3, "command line", "--zeta");
    rft::PadKinematics k;
    k.v_WB_W = Vector3(a->velocity, "velocity");
    k.w_WB_W = Vector3(a->omega, "omega");
    limits::Require(limits::kSpeed_m_s, k.v_WB_W.stableNorm(), "command line", "--velocity (its magnitude)");
    limits::Require(limits::kAngularSpeed_rad_s, k.w_WB_W.stableNorm(), "command line", "--omega (its magnitude)");
    if (k.v_WB_W.norm() == 0.0 && k.w_WB_W.norm() == 0.0)
      throw MakeInputError("command line", "velocity", "the pad must move (RFT needs a direction of motion)");
    const pad::TiltAxis axis = pad::ParseTiltAxis(a->tilt_axis);
    k.R_WB = pad::TiltRotation(axis, units::DegToRad(a->tilt_deg));
    const io::PadSpec pad = io::LoadPad(a->pad);
    rft::SoilParameters soil = io::LoadSoil(a->soil);
    if (a->zeta_N_cm3) soil.zeta_N_m3 = units::ZetaFromN_cm3(*a->zeta_N_cm3);
    const rft::LawKind kind = a->law ? rft::ParseLawKind(*a->law, "command line", "--law") : soil.rft_law_3d;
    const double plate_b_m = kind == rft::LawKind::kBekker ? rft::BekkerPlateB(pad.body.surface) : 0.0;
    // The contact model (law and pad-level terms): Bekker's z^n is a pad-level depth law.
    const rft::SoilContactModel model = rft::MakeSoilContactModel(kind, soil, a->gravity_m_s2, {}, plate_b_m);
    const rft::StressLaw3D* law = model.law.get();
    k.p_WB = pad::PlaceAtDepth(pad.body, k.R_WB, a->depth_m);
    const rft::ContactWrench w =
        rft::ComputeContactWrench(pad.body.surface, k, rft::PlaneGround(), *law, model.pad_terms);
    nlohmann::json out{
        {"pad", pad.name},
        {"soil", soil.name},
        {"law", std::string(law->name())},
        {"depth_m", a->depth_m},
        {"tilt_deg", a->tilt_deg},
        {"tilt_axis", pad::TiltAxisName(axis)},
        {"velocity_m_s", a->velocity},
        {"omega_rad_s", a->omega},
        {"reference_point_m", {k.p_WB.x(), k.p_WB.y(), k.p_WB.z()}},
        {"force_N", {w.force_W.x(), w.force_W.y(), w.force_W.z()}},
        {"moment_Nm", {w.moment_W.x(), w.moment_W.y(), w.moment_W.z()}},
        {"submerged_area_m2", w.submerged_area_m2},
        {"leading_elements", w.leading_elements},
        {"surface_elements", pad.body.surface.size()},
    };
    if (kind == rft::LawKind::kBekker) out["bekker_plate_b_m"] = plate_b_m;
    std::cout << out.dump(2) << std::endl;
  });
}

}  // namespace touchdown::app

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include <numbers>

#include "apps/commands.h"
#include "drop_tests/free_drop_output.h"
#include "drop_tests/model_file.h"
#include "drop_tests/pad_drop.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::app {

namespace {
struct DropArgs {
  std::string pad, soil, trace, model;
  double speed_m_s = 0.0;
  std::optional<double> mass_kg, zeta_N_cm3;
  double gravity_m_s2 = 9.81;
  // --free: the 6-DOF pad
  bool free = false;
  double tilt_deg = 0.0, horizontal_speed_m_s = 0.0;
  std::string tilt_axis = "x", law = "li2013";
  std::vector<double> omega{0.0, 0.0, 0.0};
};

// A free pad of another mass keeps its shape and uniform density: inertia scales with the mass.
geom::PadBody WithMass(geom::PadBody body, double mass_kg) {
  body.inertia_com_B *= mass_kg / body.mass_kg;
  body.mass_kg = mass_kg;
  return body;
}

void RunFree(const DropArgs& a, const drop::DropConditions& c, const drop::PadSpec& pad,
             const rft::SoilParameters& soil) {
  for (double v : {a.tilt_deg, a.horizontal_speed_m_s, a.omega[0], a.omega[1], a.omega[2]})
    if (!std::isfinite(v)) throw MakeInputError("command line", "--free", "tilt, horizontal speed and omega must be finite");
  rft::SoilParameters effective = soil;
  if (c.zeta_N_m3) effective.zeta_N_m3 = *c.zeta_N_m3;
  const auto law = rft::MakeStressLaw3D(a.law, effective, c.gravity_m_s2);
  drop::FreeDropInput in;
  in.impact_speed_m_s = c.impact_speed_m_s;
  in.horizontal_speed_m_s = a.horizontal_speed_m_s;
  in.tilt_rad = a.tilt_deg * std::numbers::pi / 180.0;
  in.tilt_axis = a.tilt_axis;
  in.omega_W = Eigen::Vector3d(a.omega[0], a.omega[1], a.omega[2]);
  in.gravity_m_s2 = c.gravity_m_s2;
  const geom::PadBody body = WithMass(pad.body, c.mass_kg.value_or(pad.body.mass_kg));
  const drop::FreeDropResult r = drop::RunFreeDrop(body, *law, rft::PlaneGround(), in);
  if (!a.trace.empty()) drop::WriteFreeDropTraceCsv(r, a.trace);
  nlohmann::json j = drop::FreeDropJson(r);
  j["pad"] = pad.name;
  j["soil"] = soil.name;
  j["law"] = std::string(law->name());
  j["impact_speed_m_s"] = c.impact_speed_m_s;
  j["horizontal_speed_m_s"] = a.horizontal_speed_m_s;
  j["pad_mass_kg"] = body.mass_kg;
  j["gravity_m_s2"] = c.gravity_m_s2;
  std::cout << j.dump(2) << std::endl;
}
}  // namespace

void AddDropCommand(CLI::App& app) {
  auto args = std::make_shared<DropArgs>();
  CLI::App* cmd = app.add_subcommand("drop", "One single-footpad drop on the paper's rig (vertical rod)");
  cmd->add_option("--pad", args->pad, "pad name from data/pads or a pad YAML file")->required();
  cmd->add_option("--soil", args->soil, "soil name from data/soils or a soil YAML file")->required();
  cmd->add_option("--speed", args->speed_m_s, "impact speed at touchdown [m/s], downward")->required();
  cmd->add_option("--mass", args->mass_kg, "dropped mass [kg] (default: the pad's mass)");
  cmd->add_option("--gravity", args->gravity_m_s2, "gravity [m/s^2] (default 9.81)");
  cmd->add_option("--zeta", args->zeta_N_cm3, "override the soil's RFT scaling factor zeta [N/cm^3]");
  cmd->add_option("--trace", args->trace, "write the trace CSV (t_s,penetration_m,velocity_m_s,force_N)");
  cmd->add_option("--model", args->model, "model file (MODEL.yaml, e.g. from calibrate): per-soil zeta overrides");
  cmd->add_flag("--free", args->free, "a free 6-DOF pad (3D contact) instead of the rig's vertical rod");
  cmd->add_option("--tilt-deg", args->tilt_deg, "--free: initial tilt [deg] about --tilt-axis");
  cmd->add_option("--tilt-axis", args->tilt_axis, "--free: x or y");
  cmd->add_option("--horizontal-speed", args->horizontal_speed_m_s, "--free: horizontal speed along +x [m/s]");
  cmd->add_option("--omega", args->omega, "--free: initial angular velocity WX,WY,WZ [rad/s]")
      ->expected(3)->delimiter(',');
  cmd->add_option("--law", args->law, "--free: li2013 or agarwal2023");
  cmd->callback([args] {
    drop::DropConditions c;
    c.impact_speed_m_s = args->speed_m_s;
    c.mass_kg = args->mass_kg;
    c.gravity_m_s2 = args->gravity_m_s2;
    if (args->zeta_N_cm3) c.zeta_N_m3 = *args->zeta_N_cm3 * 1e6;
    drop::ValidateConditions(c, "command line");
    const drop::PadSpec pad = drop::LoadPad(args->pad);
    rft::SoilParameters soil = drop::LoadSoil(args->soil);
    if (!args->model.empty()) soil = drop::ApplyModel(drop::LoadModelFile(args->model), soil);
    if (args->free) return RunFree(*args, c, pad, soil);
    const drop::PadDrop result = drop::RunPadDrop(pad, soil, c);
    if (!args->trace.empty()) drop::WriteTraceCsv(result.result, args->trace);
    std::cout << drop::SummaryJson(result).dump(2) << std::endl;
  });
}

}  // namespace touchdown::app

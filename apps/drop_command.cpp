#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include <sstream>

#include "apps/commands.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/drop/pad_drop.h"
#include "rft/input_error.h"
#include "rft/units.h"

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
  std::string tilt_axis = "x";
  std::optional<std::string> law;  // none: the soil's own law
  std::vector<double> omega{0.0, 0.0, 0.0};
};
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
  cmd->add_option("--model", args->model,
                  "model file (MODEL.yaml, from calibrate or diagnose): per-soil zeta overrides and effect terms");
  cmd->add_flag("--free", args->free, "a free 6-DOF pad (3D contact) instead of the rig's vertical rod");
  cmd->add_option("--tilt-deg", args->tilt_deg, "--free: initial tilt [deg] about --tilt-axis");
  cmd->add_option("--tilt-axis", args->tilt_axis, "--free: x or y");
  cmd->add_option("--horizontal-speed", args->horizontal_speed_m_s, "--free: horizontal speed along +x [m/s]");
  cmd->add_option("--omega", args->omega, "--free: initial angular velocity WX,WY,WZ [rad/s]")
      ->expected(3)->delimiter(',');
  cmd->add_option("--law", args->law,
                  "li2013, agarwal2023 (--free only) or bekker (default: the soil's own law; docs/bekker_soil.md)");
  cmd->callback([args] {
    drop::DropConditions c;
    c.impact_speed_m_s = args->speed_m_s;
    c.mass_kg = args->mass_kg;
    c.gravity_m_s2 = args->gravity_m_s2;
    if (args->zeta_N_cm3) c.zeta_N_m3 = units::ZetaFromN_cm3(*args->zeta_N_cm3);
    for (double v : {args->tilt_deg, args->horizontal_speed_m_s, args->omega[0], args->omega[1], args->omega[2]})
      if (!std::isfinite(v))
        throw MakeInputError("command line", "--free", "tilt, horizontal speed and omega must be finite");
    if (!(std::abs(args->tilt_deg) < 90.0)) {
      std::ostringstream s;
      s << "must be between -90 and 90 deg, got " << args->tilt_deg;
      throw MakeInputError("command line", "--tilt-deg", s.str());
    }
    if (args->free) {
      c.free = true;
      c.tilt_rad = units::DegToRad(args->tilt_deg);
      c.tilt_axis = pad::ParseTiltAxis(args->tilt_axis, "command line");
      c.horizontal_speed_m_s = args->horizontal_speed_m_s;
      c.omega_W = Eigen::Vector3d(args->omega[0], args->omega[1], args->omega[2]);
    } else if (args->tilt_deg != 0.0 || args->horizontal_speed_m_s != 0.0 ||
               args->omega != std::vector<double>{0.0, 0.0, 0.0}) {
      throw MakeInputError("command line", "--free",
                           "--tilt-deg, --horizontal-speed and --omega need --free (the rig drop is vertical)");
    }
    if (args->law) c.law_3d = rft::ParseLawKind(*args->law, "command line", "--law");
    drop::ValidateConditions(c, "command line");
    const io::OutputTarget trace(args->trace, {args->pad, args->soil, args->model});
    if (!args->trace.empty()) io::CheckOutputFile(trace);
    const io::PadSpec pad = io::LoadPad(args->pad);
    rft::SoilParameters soil = io::LoadSoil(args->soil);
    if (!args->model.empty()) {
      const model::ModelFile model = model::LoadModelFile(args->model);
      soil = model::ApplyModel(model, soil);
      c.effects = model::ModelEffectTerms(model);
      c.effects_source = args->model;
    }
    const drop::PadDrop result = drop::SimulateDrop(pad, soil, c, {});
    if (!args->trace.empty()) drop::WriteTraceCsv(result, trace);
    std::cout << drop::SummaryJson(result).dump(2) << std::endl;
  });
}

}  // namespace touchdown::app

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "drop_tests/pad_drop.h"

namespace touchdown::app {

namespace {
struct DropArgs {
  std::string pad, soil, trace;
  double speed_m_s = 0.0;
  std::optional<double> mass_kg, zeta_N_cm3;
  double gravity_m_s2 = 9.81;
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
  cmd->callback([args] {
    drop::DropConditions c;
    c.impact_speed_m_s = args->speed_m_s;
    c.mass_kg = args->mass_kg;
    c.gravity_m_s2 = args->gravity_m_s2;
    if (args->zeta_N_cm3) c.zeta_N_m3 = *args->zeta_N_cm3 * 1e6;
    drop::ValidateConditions(c, "command line");
    const drop::PadSpec pad = drop::LoadPad(args->pad);
    const rft::SoilParameters soil = drop::LoadSoil(args->soil);
    const drop::PadDrop result = drop::RunPadDrop(pad, soil, c);
    if (!args->trace.empty()) drop::WriteTraceCsv(result.result, args->trace);
    std::cout << drop::SummaryJson(result).dump(2) << std::endl;
  });
}

}  // namespace touchdown::app

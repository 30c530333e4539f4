#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/drop/drop_request.h"
#include "drop_tests/drop/drop_vtk.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"  // io::FormatNumber
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "drop_tests/formats/output_path.h"

namespace touchdown::app {

namespace {
// The request (drop_tests/drop/drop_request.h: checked and run there, as for the Python module)
// and where its trace goes.
struct DropArgs : drop::DropRequest {
  std::string trace, vtk;
  std::vector<double> omega{0.0, 0.0, 0.0};  // CLI11 fills a vector; the request takes its three components
};
}  // namespace

void AddDropCommand(CLI::App& app) {
  auto args = std::make_shared<DropArgs>();
  CLI::App* cmd = app.add_subcommand("drop", "One single-footpad drop on the paper's rig (vertical rod)");
  cmd->add_option("--pad", args->pad, "pad name from data/pads or a pad YAML file")->required();
  cmd->add_option("--soil", args->soil, "soil name from data/soils or a soil YAML file")->required();
  cmd->add_option("--speed", args->speed_m_s, "impact speed at touchdown [m/s], downward")->required();
  cmd->add_option("--mass", args->mass_kg, "dropped mass [kg] (default: the pad's mass)");
  cmd->add_option("--gravity", args->gravity_m_s2, "gravity [m/s^2] (default " + io::FormatNumber(rft::kEarthGravity_m_s2) + ")");
  cmd->add_option("--zeta", args->zeta_N_cm3, "override the soil's RFT scaling factor zeta [N/cm^3]");
  cmd->add_option("--trace", args->trace, "write the trace CSV (t_s,penetration_m,velocity_m_s,force_N)")->check(NonEmptyPath());
  cmd->add_option("--model", args->model,
                  "model file (MODEL.yaml, from calibrate or diagnose): per-soil zeta overrides and effect terms");
  cmd->add_flag("--free", args->free, "a free 6-DOF pad (3D contact) instead of the rig's vertical rod");
  cmd->add_option("--tilt-deg", args->tilt_deg, "--free: initial tilt [deg] about --tilt-axis");
  cmd->add_option("--tilt-axis", args->tilt_axis, "--free: x or y");
  cmd->add_option("--horizontal-speed", args->horizontal_speed_m_s, "--free: horizontal speed along +x [m/s]");
  cmd->add_option("--omega", args->omega, "--free: initial angular velocity WX,WY,WZ [rad/s]")
      ->expected(3)->delimiter(',');
  cmd->add_flag("--fast", args->fast,
                "--free: the fast model (pad re-meshed at 16 area-preserving rim segments, rtol 1e-5; depths "
                "within 0.4 % of the default, final tilts within 0.05 deg on the flat pad and 0.15 deg on the "
                "curved one; docs/lander_dynamics.md)");
  cmd->add_option("--law", args->law,
                  "li2013, agarwal2023 (--free only) or bekker (default: the soil's own law; docs/bekker_soil.md)");
  cmd->add_option("--vtk", args->vtk,
                  "--free: write a ParaView time series into this new directory (drop.pvd: the pad with its "
                  "per-element soil stresses at every trace sample, and the soil surface; docs/paraview.md)")
      ->check(NonEmptyPath());
  cmd->callback([args] {
    drop::DropRequest r = *args;
    r.omega_rad_s = {args->omega[0], args->omega[1], args->omega[2]};
    const drop::RequestNaming naming;
    const drop::DropConditions c = drop::RequestConditions(r, naming);
    const io::OutputTarget trace(args->trace, {args->pad, args->soil, args->model});
    if (!args->trace.empty()) drop::CheckTraceTarget(trace);
    const io::OutputTarget vtk(args->vtk, {args->pad, args->soil, args->model, args->trace});
    if (!args->vtk.empty()) {
      if (!c.IsFree()) throw MakeInputError("command line", "--vtk", "needs --free (the rig's pad is not drawn)");
      drop::CheckDropVtkTarget(vtk);
    }
    const io::PadSpec pad = drop::RequestPad(r, naming);
    const drop::DropSetup setup = drop::ResolveDropRequest(r, pad, c, naming);
    const drop::PadDrop result = drop::RunDrop(setup);
    if (!args->trace.empty()) drop::WriteTraceCsv(result, trace);
    if (!args->vtk.empty()) drop::WriteDropVtk(setup, result, vtk);
    std::cout << drop::RequestSummaryJson(r, result).dump(2) << std::endl;
  });
}

}  // namespace touchdown::app

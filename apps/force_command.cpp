// touchdown force: the quasi-static soil wrench on a pad held at a depth, tilt and rigid motion
// (with --dynamic, plus the soil's dynamic term at that motion).
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/drop/force_request.h"
#include "drop_tests/formats/dataset_csv.h"  // io::FormatNumber
#include "drop_tests/formats/output_path.h"
#include "rft/gravity_constants.h"

namespace touchdown::app {

namespace {
// The request (drop_tests/drop/force_request.h: checked and computed there, as for the Python
// module); CLI11 fills vectors, the request takes their three components.
struct ForceArgs : drop::ForceRequest {
  std::vector<double> velocity{0.0, 0.0, -1.0}, omega{0.0, 0.0, 0.0};
  std::string vtk;
};
}  // namespace

void AddForceCommand(CLI::App& app) {
  auto a = std::make_shared<ForceArgs>();
  CLI::App* cmd = app.add_subcommand("force", "Quasi-static soil force and moment on a pad at a depth, tilt and motion");
  cmd->add_option("--pad", a->pad, "pad name from data/pads or a pad YAML file")->required();
  cmd->add_option("--soil", a->soil, "soil name from data/soils or a soil YAML file")->required();
  cmd->add_option("--depth", a->depth_m, "depth of the pad's lowest point below the level surface [m]")->required();
  cmd->add_option("--tilt-deg", a->tilt_deg, "tilt of the pad about --tilt-axis [deg]");
  cmd->add_option("--tilt-axis", a->tilt_axis, "x or y (axes of the world frame, z up)");
  cmd->add_option("--velocity", a->velocity, "rigid velocity of the reference point VX,VY,VZ [m/s] (default 0,0,-1): the direction of motion, and the "
                  "speed of the dynamic term with --dynamic")
      ->expected(3)->delimiter(',');
  cmd->add_option("--omega", a->omega, "angular velocity WX,WY,WZ [rad/s]")->expected(3)->delimiter(',');
  cmd->add_option("--law", a->law,
                  "li2013 (Treers et al. 2021 3D decomposition), agarwal2023 or bekker (default: the soil's own law)");
  cmd->add_option("--zeta", a->zeta_N_cm3, "override the soil's zeta [N/cm^3] (li2013)");
  cmd->add_option("--gravity", a->gravity_m_s2, "gravity [m/s^2] the soil stresses scale with (default " + io::FormatNumber(rft::kEarthGravity_m_s2) + ")");
  cmd->add_flag("--dynamic", a->dynamic,
                "add the soil's dynamic term (lambda rho (v.n)^2 on leading elements) at --velocity; without it "
                "the force is quasi-static and --velocity gives only the direction of motion");
  cmd->add_option("--vtk", a->vtk,
                  "write the pad at its pose with the soil stress on each surface element to this new .vtp file "
                  "(ParaView; docs/paraview.md)")
      ->check(NonEmptyPath());
  cmd->callback([a] {
    drop::ForceRequest r = *a;
    r.velocity_m_s = {a->velocity[0], a->velocity[1], a->velocity[2]};
    r.omega_rad_s = {a->omega[0], a->omega[1], a->omega[2]};
    const io::OutputTarget vtk(a->vtk, {a->pad, a->soil});
    if (!a->vtk.empty()) io::CheckOutputFile(vtk);
    std::cout << drop::ForceJson(r, drop::RequestNaming{}, a->vtk.empty() ? nullptr : &vtk).dump(2) << std::endl;
  });
}

}  // namespace touchdown::app

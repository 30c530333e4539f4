#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "drop_tests/dataset/calibration_run.h"
#include "rft/units.h"

namespace touchdown::app {

namespace {
struct CalibrateArgs {
  std::string measured, param = "zeta", per = "soil", out, atmosphere = "all";
  double confidence = 0.95;
  // --law bekker: a Bekker soil file instead of a model file (docs/bekker_soil.md)
  std::string law = "rft", soil, pad, shear_from;
};

void PrintBekkerFit(const dataset::BekkerFit& fit, const std::string& out) {
  std::cout << "bekker: n = " << std::setprecision(4) << fit.bekker.n << ", k_c = " << fit.bekker.k_c_N_m_n1 / 1e3
            << " kN/m^(n+1), k_phi = " << fit.bekker.k_phi_N_m_n2 / 1e3 << " kN/m^(n+2) from " << fit.drops << " drops, "
            << fit.samples << " samples, residual RMS " << std::setprecision(3) << fit.residual_rms_N << " N ("
            << fit.pad_sizes << " pad size" << (fit.pad_sizes == 1 ? ": k_c = 0" : "s") << ")\nwrote " << out << "\n";
}

void PrintZetaFits(const std::vector<dataset::ZetaFit>& fits, const std::string& out) {
  for (const dataset::ZetaFit& f : fits)
    std::cout << f.group << ": zeta = " << std::fixed << std::setprecision(4) << units::ZetaToN_cm3(f.zeta_N_m3) << " N/cm^3, "
              << std::setprecision(0) << 100 * f.confidence << " % interval [" << std::setprecision(4)
              << units::ZetaToN_cm3(f.low_N_m3) << ", " << units::ZetaToN_cm3(f.high_N_m3) << "] from " << f.drops << " drops, " << f.samples
              << " samples, residual RMS " << std::setprecision(3) << f.residual_rms_N << " N\n";
  std::cout << "wrote " << out << "\n";
}
}  // namespace

void AddCalibrateCommand(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand("calibrate", "Fit zeta to measured drops (least squares of force on penetration)");
  cmd->add_option("measured", args->measured, "measured dataset directory")->required();
  cmd->add_option("--param", args->param, "parameter to fit (zeta)")->check(CLI::IsMember({"zeta"}));
  cmd->add_option("--per", args->per, "soil: one zeta per soil (default); all: one zeta for every soil")
      ->check(CLI::IsMember({"soil", "all"}));
  cmd->add_option("--atmosphere", args->atmosphere, "use only drops in vacuum, air, or all (default)")
      ->check(CLI::IsMember({"vacuum", "air", "all"}));
  cmd->add_option("--confidence", args->confidence, "confidence level of the interval (default 0.95)")
      ->check(CLI::Range(0.5, 0.9999));
  cmd->add_option("--out", args->out, "model file to write (MODEL.yaml); with --law bekker a soil file (SOIL.yaml)")
      ->required();
  cmd->add_option("--law", args->law, "rft: fit zeta (default); bekker: fit Bekker's n, k_c and k_phi (a soil file)")
      ->check(CLI::IsMember({"rft", "bekker"}));
  cmd->add_option("--soil", args->soil, "--law bekker: only the drops on this soil (as drops.csv names it)");
  cmd->add_option("--pad", args->pad, "--law bekker: only the drops of this pad (as drops.csv names it)");
  cmd->add_option("--shear-from", args->shear_from,
                  "--law bekker: the Bekker soil whose cohesion, friction angle and K the fitted soil takes");
  cmd->callback([args] {
    dataset::CalibrationRequest r;
    r.measured = args->measured, r.out = args->out;
    r.law = args->law == "bekker" ? dataset::CalibrationLaw::kBekker : dataset::CalibrationLaw::kRft;
    if (args->atmosphere != "all") r.atmosphere = rft::ParseAtmosphere(args->atmosphere);
    r.per_soil = args->per == "soil", r.confidence = args->confidence;
    r.soil = args->soil, r.pad = args->pad, r.shear_from = args->shear_from;
    const dataset::CalibrationRun run = dataset::RunCalibration(r);
    if (run.bekker)
      PrintBekkerFit(*run.bekker, args->out);
    else
      PrintZetaFits(run.fits, args->out);
  });
}

}  // namespace touchdown::app

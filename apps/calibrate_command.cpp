#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/dataset/calibrate.h"
#include "rft/units.h"

namespace touchdown::app {

namespace {
struct CalibrateArgs {
  std::string measured, param = "zeta", per = "soil", out, atmosphere = "all";
  double confidence = 0.95;
};
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
  cmd->add_option("--out", args->out, "model file to write (MODEL.yaml)")->required();
  cmd->callback([args] {
    const io::OutputTarget out(args->out, {args->measured});
    io::CheckOutputFile(out, model::kModelFileMark);
    const dataset::Dataset measured = dataset::ReadDataset(args->measured);
    dataset::CalibrationOptions options;
    options.per_soil = args->per == "soil";
    if (args->atmosphere != "all") options.atmosphere = rft::ParseAtmosphere(args->atmosphere);
    options.confidence = args->confidence;
    const std::vector<dataset::ZetaFit> fits = dataset::CalibrateZeta(measured, options);
    const model::ModelFile model =
        dataset::CalibrationModel(fits, measured, std::filesystem::path(args->out).stem().string());
    model::WriteModelFile(model, out);
    for (const dataset::ZetaFit& f : fits)
      std::cout << f.group << ": zeta = " << std::fixed << std::setprecision(4) << units::ZetaToN_cm3(f.zeta_N_m3) << " N/cm^3, "
                << std::setprecision(0) << 100 * options.confidence << " % interval [" << std::setprecision(4)
                << units::ZetaToN_cm3(f.low_N_m3) << ", " << units::ZetaToN_cm3(f.high_N_m3) << "] from " << f.drops << " drops, " << f.samples
                << " samples, residual RMS " << std::setprecision(3) << f.residual_rms_N << " N\n";
    std::cout << "wrote " << args->out << "\n";
  });
}

}  // namespace touchdown::app

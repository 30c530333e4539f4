#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/dataset/calibration_run.h"
#include "drop_tests/targets/targets_calibration.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::app {

namespace {
struct CalibrateArgs {
  std::string measured, param = "zeta", per = "soil", out, atmosphere = "all";
  double confidence = 0.95;
  // --law bekker: a Bekker soil file instead of a model file (docs/bekker_soil.md)
  std::string law = "rft", soil, pad, shear_from;
  // --targets: published scalar targets instead of a dataset (docs/calibration_targets.md)
  std::string targets, report;
  int threads = 0;
  bool evaluate_only = false;
};

// calibrate --targets: the free parameters fitted to a targets file; the model file gets the fitted
// zeta, the report every parameter and target.
void CalibrateTargets(const CalibrateArgs& args) {
  const targets::TargetsCalibration c =
      targets::RunTargetsCalibration({args.targets, args.out, args.report, args.threads, args.evaluate_only, {}});
  std::cout << targets::TargetsReportTable(c.file, c.fit) << "wrote " << args.out
            << (args.report.empty() ? "" : " and " + args.report) << "\n";
}

void PrintBekkerFit(const dataset::BekkerFit& fit, const std::string& out) {
  std::cout << "bekker: n = " << std::setprecision(4) << fit.bekker.n << ", k_c = " << fit.bekker.k_c_N_m_n1 / units::kKilo
            << " kN/m^(n+1), k_phi = " << fit.bekker.k_phi_N_m_n2 / units::kKilo << " kN/m^(n+2) from " << fit.drops << " drops, "
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
  cmd->add_option("measured", args->measured, "measured dataset directory (or --targets)");
  cmd->add_option("--targets", args->targets,
                  "a targets file: fit the free parameters it names to published scalar results instead "
                  "(docs/calibration_targets.md)");
  cmd->add_option("--report", args->report,
                  "also write the fit's report as JSON to this file: with --targets every parameter and target; "
                  "for a dataset each soil's zeta with its covariance (what a stability study's soil_uncertainty "
                  "draws from)")
      ->check(NonEmptyPath());
  cmd->add_option("--threads", args->threads, "--targets: scenarios run side by side (default: every core)")
      ->check(NumberIn(0, limits::kMaxThreads));
  cmd->add_flag("--evaluate-only", args->evaluate_only,
                "--targets: no fit; every target at the parameters' start values (use: predict for all)");
  cmd->add_option("--param", args->param, "parameter to fit (zeta)")->check(CLI::IsMember({"zeta"}));
  cmd->add_option("--per", args->per, "soil: one zeta per soil (default); all: one zeta for every soil")
      ->check(CLI::IsMember({"soil", "all"}));
  cmd->add_option("--atmosphere", args->atmosphere, "use only drops in vacuum, air, or all (default)")
      ->check(CLI::IsMember({"vacuum", "air", "all"}));
  cmd->add_option("--confidence", args->confidence, "confidence level of the interval (default 0.95)")
      ->check(NumberIn(limits::kMinConfidence, limits::kMaxConfidence));
  cmd->add_option("--out", args->out, "model file to write (MODEL.yaml); with --law bekker a soil file (SOIL.yaml)")
      ->required()
      ->check(NonEmptyPath());
  cmd->add_option("--law", args->law, "rft: fit zeta (default); bekker: fit Bekker's n, k_c and k_phi (a soil file)")
      ->check(CLI::IsMember(dataset::CalibrationLawNames()));
  cmd->add_option("--soil", args->soil, "--law bekker: only the drops on this soil (as drops.csv names it)");
  cmd->add_option("--pad", args->pad, "--law bekker: only the drops of this pad (as drops.csv names it)");
  cmd->add_option("--shear-from", args->shear_from,
                  "--law bekker: the Bekker soil whose cohesion, friction angle and K the fitted soil takes");
  cmd->callback([args] {
    if (args->targets.empty() == args->measured.empty())
      throw MakeInputError("command line", args->targets.empty() ? "measured" : "--targets",
                           "give a measured dataset directory or --targets FILE (exactly one)");
    if (!args->targets.empty()) {
      if (dataset::ParseCalibrationLaw(args->law, "command line", "--law") != dataset::CalibrationLaw::kRft)
        throw MakeInputError("command line", "--law", "--targets fits its own parameters: no --law");
      return CalibrateTargets(*args);
    }
    // The --targets options mean nothing to a dataset calibration: refused, not ignored.
    if (args->evaluate_only)
      throw MakeInputError("command line", "--evaluate-only", "evaluates a --targets file; give --targets FILE");
    if (args->threads != 0)
      throw MakeInputError("command line", "--threads", "runs a --targets fit's scenarios side by side; give --targets FILE");
    dataset::CalibrationRequest r;
    r.measured = args->measured, r.out = args->out;
    r.law = dataset::ParseCalibrationLaw(args->law, "command line", "--law");
    if (args->atmosphere != "all") r.atmosphere = rft::ParseAtmosphere(args->atmosphere);
    r.per_soil = args->per == "soil", r.confidence = args->confidence;
    r.soil = args->soil, r.pad = args->pad, r.shear_from = args->shear_from;
    r.report = args->report;
    const dataset::CalibrationRun run = dataset::RunCalibration(r);
    if (run.bekker)
      PrintBekkerFit(*run.bekker, args->out);
    else
      PrintZetaFits(run.fits, args->report.empty() ? args->out : args->out + " and " + args->report);
  });
}

}  // namespace touchdown::app

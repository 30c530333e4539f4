#include "drop_tests/dataset/calibration_run.h"

#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>
#include <ostream>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/output_path.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::dataset {

std::vector<std::string> CalibrationLawNames() {
  return NameList(kCalibrationLawNames);
}

CalibrationLaw ParseCalibrationLaw(const std::string& name, const std::string& where, const std::string& field) {
  return ParseName(kCalibrationLawNames, name, where, field);
}

namespace {

// The report's first line: a report touchdown wrote may be replaced by a rerun, a user's file never.
constexpr const char* kZetaReportMark = "{\"written_by\": \"touchdown calibrate --report (it may replace this file)\",";

// law bekker: n, k_c and k_phi fitted; c, phi and K from the soil (or shear_from).
BekkerFit CalibrateBekkerSoil(const CalibrationRequest& r) {
  const io::OutputTarget out(r.out, {r.measured});
  io::CheckOutputFile(out, kBekkerFitMark);
  const Dataset measured = ReadDataset(r.measured);
  BekkerCalibrationOptions options;
  options.atmosphere = r.atmosphere;
  options.soil = r.soil;
  options.pad = r.pad;
  const BekkerFit fit = CalibrateBekker(measured, options);
  rft::SoilParameters soil = CalibratedBekkerSoil(fit, measured, std::filesystem::path(r.out).stem().string());
  if (!r.shear_from.empty()) {
    const rft::BekkerParameters shear = io::LoadSoil(r.shear_from).bekker;
    soil.bekker.cohesion_Pa = shear.cohesion_Pa;
    soil.bekker.friction_angle_rad = shear.friction_angle_rad;
    soil.bekker.shear_modulus_K_m = shear.shear_modulus_K_m;
  }
  if (!(soil.bekker.shear_modulus_K_m > 0.0))
    throw MakeInputError(r.naming.context, r.naming.Field("shear-from"),
                         "soil '" + fit.soils.front() + "' has no bekker block: name a Bekker soil for c, phi and K");
  io::WriteOutputFile(out, [&](std::ostream& o) {
    o << kBekkerFitMark << "\n# on " << r.measured << " (soils:";
    for (const std::string& s : fit.soils) o << ' ' << s;
    o << "; " << fit.drops << " drops, " << fit.samples << " samples, residual RMS " << fit.residual_rms_N << " N)\n# fit: "
      << fit.method << "\n# c, phi and K: " << (r.shear_from.empty() ? "the soil's own" : "from " + r.shear_from)
      << ", not fitted\n";
    io::WriteSoil(soil, o);
  }, kBekkerFitMark);
  return fit;
}

// The report's target, checked before anything runs: a new file or one a calibrate report wrote,
// not the model file.
std::optional<io::OutputTarget> CheckedReport(const CalibrationRequest& r) {
  if (r.report.empty()) return std::nullopt;
  if (r.law != CalibrationLaw::kRft)
    throw MakeInputError(r.naming.context, r.naming.Field("report"),
                         "reports zeta's covariance: only with the rft law (got '" + r.report + "')");
  if (!r.per_soil)
    throw MakeInputError(r.naming.context, r.naming.Field("report"),
                         "needs one zeta per soil (" + r.naming.Field("per") +
                             " soil): a zeta shared by every soil is no soil's own to draw");
  if (std::filesystem::absolute(r.report).lexically_normal() == std::filesystem::absolute(r.out).lexically_normal())
    throw MakeInputError(r.naming.context, r.naming.Field("report"),
                         "must differ from " + r.naming.Field("out") + " (" + r.report + ")");
  io::OutputTarget report(r.report, {r.measured});
  io::CheckOutputFile(report, kZetaReportMark);
  return report;
}

std::vector<ZetaFit> CalibrateZetaModel(const CalibrationRequest& r) {
  const io::OutputTarget out(r.out, {r.measured});
  io::CheckOutputFile(out, model::kModelFileMark);
  const Dataset measured = ReadDataset(r.measured);
  CalibrationOptions options;
  options.per_soil = r.per_soil;
  options.atmosphere = r.atmosphere;
  options.confidence = r.confidence;
  std::vector<ZetaFit> fits = CalibrateZeta(measured, options);
  model::WriteModelFile(CalibrationModel(fits, measured, std::filesystem::path(r.out).stem().string()), out);
  return fits;
}

}  // namespace

CalibrationRun RunCalibration(const CalibrationRequest& request) {
  const std::optional<io::OutputTarget> report = CheckedReport(request);
  CalibrationRun run;
  run.law = request.law;
  if (request.law == CalibrationLaw::kBekker)
    run.bekker = CalibrateBekkerSoil(request);
  else
    run.fits = CalibrateZetaModel(request);
  if (report) {
    // The JSON object opens with its "written_by" entry on the mark's line.
    const std::string json = ZetaCalibrationReportJson(request, run).dump(2);
    io::WriteOutputFile(*report, [&](std::ostream& o) { o << kZetaReportMark << '\n' << json.substr(2) << '\n'; },
                        kZetaReportMark);
  }
  return run;
}

nlohmann::json ZetaCalibrationReportJson(const CalibrationRequest& r, const CalibrationRun& run) {
  nlohmann::json parameters = nlohmann::json::array();
  std::vector<double> variances;
  for (const ZetaFit& f : run.fits)
    for (size_t k = 0; k < f.soils.size(); ++k) {
      parameters.push_back({{"name", "zeta_" + f.soils[k]},
                            {"kind", "soil_zeta"},
                            {"soil", f.soils[k]},
                            {"unit", "N/cm^3"},
                            {"value", units::ZetaToN_cm3(f.zeta_N_m3)},
                            {"reference_gravity_m_s2", f.reference_gravities_m_s2.at(k)}});
      const double se = units::ZetaToN_cm3(f.standard_error_N_m3);
      variances.push_back(se * se);
    }
  nlohmann::json matrix = nlohmann::json::array();
  for (size_t a = 0; a < variances.size(); ++a) {
    nlohmann::json row = nlohmann::json::array();
    for (size_t b = 0; b < variances.size(); ++b) row.push_back(a == b ? variances[a] : 0.0);
    matrix.push_back(row);
  }
  nlohmann::json j = CalibrationJson(run);
  j["covariance"] = {{"meaning", "each soil's zeta fitted on its own drops (least squares of force on the penetration "
                                 "integral; its standard error as the fit reports it): independent, so the matrix is "
                                 "diagonal, the squared standard errors, in (N/cm^3)^2"},
                     {"parameters", parameters},
                     {"matrix", matrix}};
  std::string command = "touchdown calibrate " + r.measured + " --out " + r.out + " --report " + r.report;
  if (r.atmosphere) command += std::string(" --atmosphere ") + rft::AtmosphereName(*r.atmosphere);
  if (r.confidence != 0.95) command += " --confidence " + io::FormatNumber(r.confidence);
  j["command"] = command;
  return j;
}

nlohmann::json CalibrationJson(const CalibrationRun& run) {
  if (run.bekker) {
    const BekkerFit& f = *run.bekker;
    return {{"law", "bekker"},
            {"soils", f.soils},
            {"n", f.bekker.n},
            {"k_c_kN_m_n1", f.bekker.k_c_N_m_n1 / units::kKilo},
            {"k_phi_kN_m_n2", f.bekker.k_phi_N_m_n2 / units::kKilo},
            {"drops", f.drops},
            {"samples", f.samples},
            {"pad_sizes", f.pad_sizes},
            {"residual_rms_N", f.residual_rms_N},
            {"method", f.method}};
  }
  nlohmann::json fits = nlohmann::json::array();
  for (const ZetaFit& f : run.fits)
    fits.push_back({{"group", f.group},
                    {"soils", f.soils},
                    {"zeta_N_cm3", units::ZetaToN_cm3(f.zeta_N_m3)},
                    {"low_N_cm3", units::ZetaToN_cm3(f.low_N_m3)},
                    {"high_N_cm3", units::ZetaToN_cm3(f.high_N_m3)},
                    {"standard_error_N_cm3", units::ZetaToN_cm3(f.standard_error_N_m3)},
                    {"confidence", f.confidence},
                    {"degrees_of_freedom", f.degrees_of_freedom},
                    {"drops", f.drops},
                    {"samples", f.samples},
                    {"residual_rms_N", f.residual_rms_N},
                    {"method", f.method}});
  return {{"law", "rft"}, {"fits", fits}};
}

}  // namespace touchdown::dataset

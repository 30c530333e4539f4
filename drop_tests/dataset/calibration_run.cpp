#include "drop_tests/dataset/calibration_run.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>

#include "drop_tests/io/catalog.h"
#include "drop_tests/io/output_path.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::dataset {

std::vector<std::string> CalibrationLawNames() { return {"rft", "bekker"}; }

CalibrationLaw ParseCalibrationLaw(const std::string& name, const std::string& where, const std::string& field) {
  if (name == "rft") return CalibrationLaw::kRft;
  if (name == "bekker") return CalibrationLaw::kBekker;
  throw MakeInputError(where, field, "must be rft or bekker, got '" + name + "'");
}

namespace {

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
  CalibrationRun run;
  run.law = request.law;
  if (request.law == CalibrationLaw::kBekker)
    run.bekker = CalibrateBekkerSoil(request);
  else
    run.fits = CalibrateZetaModel(request);
  return run;
}

nlohmann::json CalibrationJson(const CalibrationRun& run) {
  if (run.bekker) {
    const BekkerFit& f = *run.bekker;
    return {{"law", "bekker"},
            {"soils", f.soils},
            {"n", f.bekker.n},
            {"k_c_kN_m_n1", f.bekker.k_c_N_m_n1 / 1e3},
            {"k_phi_kN_m_n2", f.bekker.k_phi_N_m_n2 / 1e3},
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

#pragma once
// `touchdown calibrate MEASURED --out FILE` as one call, for the command and the Python module
// (touchdown.calibrate): reads the dataset, fits, and writes the model file (law rft: zeta per
// soil, calibrate.h) or the Bekker soil file (law bekker: n, k_c, k_phi, calibrate_bekker.h) to
// `out` (a new file, or one an earlier calibrate wrote).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/dataset/calibrate.h"
#include "drop_tests/drop/drop_request.h"
#include "drop_tests/dataset/calibrate_bekker.h"
#include "rft/enum_names.h"

namespace touchdown::dataset {

enum class CalibrationLaw { kRft, kBekker };
inline constexpr std::array<EnumName<CalibrationLaw>, 2> kCalibrationLawNames{
    {{CalibrationLaw::kRft, "rft"}, {CalibrationLaw::kBekker, "bekker"}}};
// The names on the command line and in Python ("rft", "bekker"), in the enum's order.
std::vector<std::string> CalibrationLawNames();
// The law a name stands for. Throws InputError naming `where` and `field` on any other text.
CalibrationLaw ParseCalibrationLaw(const std::string& name, const std::string& where, const std::string& field);

struct CalibrationRequest {
  std::string measured;  // dataset directory
  std::string out;       // MODEL.yaml (rft) or SOIL.yaml (bekker)
  CalibrationLaw law = CalibrationLaw::kRft;
  std::optional<rft::Atmosphere> atmosphere;  // only the drops in it; none: all
  // law rft
  bool per_soil = true;
  double confidence = 0.95;
  // also the fit's report (JSON): the fits and each soil's zeta with its covariance, what a stability
  // study's `soil_uncertainty` draws from; "" none. Needs per_soil (one zeta shared by several soils
  // is no soil's own).
  std::string report;
  // law bekker: only the drops of this soil and pad ("" all); the soil whose c, phi and K the
  // fitted soil takes ("" the fitted soil's own)
  std::string soil, pad, shear_from;
  drop::RequestNaming naming;  // how errors name the options (--shear-from, or the Python module's shear_from)
};

struct CalibrationRun {
  CalibrationLaw law = CalibrationLaw::kRft;
  std::vector<ZetaFit> fits;        // law rft: one per group
  std::optional<BekkerFit> bekker;  // law bekker
};

// The first line of a soil file calibrate --law bekker writes: such a file may be replaced.
inline constexpr const char* kBekkerFitMark = "# touchdown calibrate --law bekker";

// Checks `out` first (InputError: a user's file), then fits and writes it.
CalibrationRun RunCalibration(const CalibrationRequest& request);

// The fit as JSON (what touchdown.calibrate returns): law rft {"law", "fits": [{group, soils,
// zeta_N_cm3, low_N_cm3, high_N_cm3, standard_error_N_cm3, confidence, degrees_of_freedom, drops,
// samples, residual_rms_N, method}]}; law bekker {"law", soils, n, k_c_kN_m_n1, k_phi_kN_m_n2,
// drops, samples, pad_sizes, residual_rms_N, method}. Numbers are the fit's doubles (the command
// prints them rounded).
nlohmann::json CalibrationJson(const CalibrationRun& run);

// The report `request.report` receives (law rft): CalibrationJson's fits, `covariance` in the schema
// of `calibrate --targets --report` (parameters {name zeta_<soil>, kind soil_zeta, soil, unit
// N/cm^3, value, reference_gravity_m_s2} and the matrix: each soil's zeta is fitted on its own
// drops, so the matrix is diagonal, the squared standard errors) and the command that wrote it.
nlohmann::json ZetaCalibrationReportJson(const CalibrationRequest& request, const CalibrationRun& run);

}  // namespace touchdown::dataset

#pragma once
// Fitting zeta to measured drops (`touchdown calibrate`), as the paper fits zeta to its flat pad:
// least squares of force against penetration over the loading strokes.
//
// Quasi-static RFT is linear in zeta: on the loading stroke F(d) = zeta_ref (g / g_ref) phi(d),
// phi(d) = F_RFT(d; zeta = 1) of the drop's pad, straight down (an axisymmetric pad: the profile
// integral, footpad_geom/axisymmetric_intrusion.h; a mesh pad: the 3D contact, Li 2013 in 3D, on
// the level pad, as its free drop feels it; a mesh pad on a soil whose rft_law_3d is not li2013
// is refused), and g_ref the soil's reference gravity. With x_i = (g / g_ref) phi(d_i) the fit is
// closed-form:
//
//   zeta = sum x_i F_i / sum x_i^2,   residuals e_i = F_i - zeta x_i,
//
// over every measured sample with d_i > 0 up to the drop's deepest sample or its stop but the first
// and the last of them (the loading stroke, LoadingStrokeIndices; the rest phase, where the
// reaction is the weight, is not RFT's law, and the samples astride the touchdown and the stop
// mix it in when the sensor averages over its sample period).
//
// Confidence interval (two-sided, `confidence`, default 95 %): samples within one drop are not
// independent (a sensor offset or a model gap moves a whole curve), so the standard error is
// cluster-robust with the drops as clusters:
//   Var(zeta) = G / (G - 1) * sum_g (sum_{i in g} x_i e_i)^2 / (sum x_i^2)^2,
// with Student's t on G - 1 degrees of freedom (G = drops). With one drop it falls back to the
// ordinary i.i.d. standard error s^2 / sum x_i^2, s^2 = sum e_i^2 / (n - 1), t on n - 1.
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/model/model_file.h"

namespace touchdown::dataset {

struct CalibrationOptions {
  bool per_soil = true;       // one zeta per soil; false: one zeta for every soil
  std::optional<rft::Atmosphere> atmosphere;  // only the drops in it; none: all drops
  double confidence = 0.95;
};

struct ZetaFit {
  std::string group;                   // the soil, or "all"
  std::vector<std::string> soils;      // soils in the group
  std::vector<double> reference_gravities_m_s2;  // of each soil
  double confidence = 0.95;
  double zeta_N_m3 = 0.0;              // at each soil's reference gravity
  double standard_error_N_m3 = 0.0;
  double low_N_m3 = 0.0, high_N_m3 = 0.0;
  double degrees_of_freedom = 0.0;
  int drops = 0;
  long samples = 0;
  double residual_rms_N = 0.0;
  std::string method;
};

// The regression inputs of one drop: x_i and F_i over its loading stroke.
struct StrokeSamples {
  std::vector<double> x;  // (g/g_ref) phi(d_i) [N per N/m^3]
  std::vector<double> force_N;
};
// The last sample of a trace's stroke: the deepest one, or the one before the force falls (in the
// deeper half of the stroke) below half of its largest value so far: the rest phase carries only
// the weight. 0 for an empty trace.
size_t LoadingStrokeEnd(const DatasetTrace& trace);
// Indices of a trace's loading stroke: the samples with penetration > 0 up to LoadingStrokeEnd,
// without the first and the last of them (a sensor averaging over its sample period mixes the free
// fall into the first and the weight at rest into the last); none when that leaves nothing.
std::vector<size_t> LoadingStrokeIndices(const DatasetTrace& trace);

// Closed-form fit of zeta over drops (clusters) of samples; see the header comment.
ZetaFit FitZeta(const std::vector<StrokeSamples>& drops, double confidence);

std::vector<ZetaFit> CalibrateZeta(const Dataset& measured, const CalibrationOptions& options);
// The model file calibrate writes: one soil override per fitted soil with its interval.
model::ModelFile CalibrationModel(const std::vector<ZetaFit>& fits, const Dataset& measured, const std::string& name);

}  // namespace touchdown::dataset

#include "drop_tests/dataset/calibrate_bekker.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/catalog/catalog.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "rft/input_error.h"

namespace touchdown::dataset {

namespace {

// One loading-stroke sample: depth, force and the pad's dimension b.
struct BekkerSample {
  double depth_m, force_N, plate_b_m;
  const geom::AxisymmetricIntrusion* intrusion;
};

struct LinearBekker {
  double k_c = 0.0, k_phi = 0.0, sse = 0.0;
};

// The least-squares (k_c, k_phi) >= 0 at exponent n, with its residual sum of squares.
LinearBekker SolveAtExponent(const std::vector<BekkerSample>& samples, double n, bool two_sizes) {
  double suu = 0, suw = 0, sww = 0, suf = 0, swf = 0, sff = 0;
  for (const BekkerSample& s : samples) {
    const double w = s.intrusion->PowerLawVerticalForce(s.depth_m, 1.0, n, 1.0), u = w / s.plate_b_m;
    suu += u * u, suw += u * w, sww += w * w, suf += u * s.force_N, swf += w * s.force_N, sff += s.force_N * s.force_N;
  }
  // sse(a, b) = sff - 2 (a suf + b swf) + a^2 suu + 2 a b suw + b^2 sww
  const auto sse = [&](double a, double b) {
    return sff - 2 * (a * suf + b * swf) + a * a * suu + 2 * a * b * suw + b * b * sww;
  };
  LinearBekker phi_only{0.0, sww > 0 ? std::max(0.0, swf / sww) : 0.0, 0.0};
  phi_only.sse = sse(0.0, phi_only.k_phi);
  if (!two_sizes) return phi_only;
  const double det = suu * sww - suw * suw;
  if (det > 0.0) {
    const LinearBekker both{(suf * sww - swf * suw) / det, (swf * suu - suf * suw) / det, 0.0};
    if (both.k_c >= 0.0 && both.k_phi >= 0.0) return {both.k_c, both.k_phi, sse(both.k_c, both.k_phi)};
  }
  LinearBekker c_only{suu > 0 ? std::max(0.0, suf / suu) : 0.0, 0.0, 0.0};
  c_only.sse = sse(c_only.k_c, 0.0);
  return c_only.sse < phi_only.sse ? c_only : phi_only;
}

// Golden-section search of the residual over n in [0.2, 2] (unimodal in practice; 60 steps).
double BestExponent(const std::vector<BekkerSample>& samples, bool two_sizes) {
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 0.2, hi = 2.0;
  double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
  double fa = SolveAtExponent(samples, a, two_sizes).sse, fb = SolveAtExponent(samples, b, two_sizes).sse;
  for (int i = 0; i < 60; ++i) {
    if (fa < fb) {
      hi = b, b = a, fb = fa;
      a = hi - golden * (hi - lo);
      fa = SolveAtExponent(samples, a, two_sizes).sse;
    } else {
      lo = a, a = b, fa = fb;
      b = lo + golden * (hi - lo);
      fb = SolveAtExponent(samples, b, two_sizes).sse;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

BekkerFit CalibrateBekker(const Dataset& measured, const BekkerCalibrationOptions& options) {
  std::map<std::string, std::unique_ptr<geom::AxisymmetricIntrusion>> intrusions;
  std::map<std::string, double> radii;
  std::vector<BekkerSample> samples;
  BekkerFit fit;
  for (const DatasetDrop& d : measured.drops) {
    if (options.atmosphere && d.atmosphere != *options.atmosphere) continue;
    const std::string pad_ref = measured.PadReference(d), soil_ref = measured.SoilReference(d);
    if (!options.soil.empty() && d.soil != options.soil) continue;
    if (!options.pad.empty() && d.pad != options.pad) continue;
    if (!intrusions.count(pad_ref)) {
      const io::PadSpec pad = io::LoadPad(pad_ref);
      if (!pad.is_axisymmetric())
        throw MakeInputError((std::filesystem::path(measured.directory) / "drops.csv").string() + ": drop " + d.drop_id,
                             "pad", "mesh pad '" + pad.name + "': the Bekker fit needs an axisymmetric pad's profile");
      intrusions.emplace(pad_ref, drop::MakeBekkerRigIntrusion(pad.profile));
      radii.emplace(pad_ref, pad.profile.radius_m());
    }
    const std::string soil_name = io::LoadSoil(soil_ref).name;
    if (std::find(fit.soils.begin(), fit.soils.end(), soil_name) == fit.soils.end()) fit.soils.push_back(soil_name);
    const std::vector<size_t> stroke = LoadingStrokeIndices(d.trace);
    for (size_t i : stroke)
      samples.push_back({d.trace.penetration_m[i], d.trace.force_N[i], radii.at(pad_ref), intrusions.at(pad_ref).get()});
    fit.drops += stroke.empty() ? 0 : 1;
  }
  if (samples.size() < 3) throw MakeInputError(measured.directory, "", "fewer than three loading-stroke samples to fit");
  std::vector<double> sizes;
  for (const auto& [ref, r] : radii)
    if (std::find(sizes.begin(), sizes.end(), r) == sizes.end()) sizes.push_back(r);
  fit.pad_sizes = static_cast<int>(sizes.size());
  const bool two_sizes = fit.pad_sizes >= 2;
  fit.bekker.n = BestExponent(samples, two_sizes);
  const LinearBekker lin = SolveAtExponent(samples, fit.bekker.n, two_sizes);
  fit.bekker.k_c_N_m_n1 = lin.k_c;
  fit.bekker.k_phi_N_m_n2 = lin.k_phi;
  fit.samples = static_cast<long>(samples.size());
  fit.residual_rms_N = std::sqrt(std::max(0.0, lin.sse) / fit.samples);
  fit.method = std::string("least squares of force on the Bekker footprint integral over the loading strokes; n by "
                           "golden-section search in [0.2, 2], (k_c, k_phi) >= 0 in closed form at each n; ") +
               (two_sizes ? "k_c and k_phi from pads of different radius b"
                          : "one pad size: k_c and k_phi cannot be told apart, k_c = 0 and k_phi is the modulus k_c/b + k_phi");
  return fit;
}

rft::SoilParameters CalibratedBekkerSoil(const BekkerFit& fit, const Dataset& measured, const std::string& name) {
  rft::SoilParameters soil;
  for (const DatasetDrop& d : measured.drops)
    if (io::LoadSoil(measured.SoilReference(d)).name == fit.soils.front()) {
      soil = io::LoadSoil(measured.SoilReference(d));
      break;
    }
  soil.name = name;
  soil.rft_law_3d = rft::LawKind::kBekker;
  soil.bekker.n = fit.bekker.n;
  soil.bekker.k_c_N_m_n1 = fit.bekker.k_c_N_m_n1;
  soil.bekker.k_phi_N_m_n2 = fit.bekker.k_phi_N_m_n2;
  return soil;
}

}  // namespace touchdown::dataset

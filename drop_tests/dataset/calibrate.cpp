#include "drop_tests/dataset/calibrate.h"


#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/contact_model.h"
#include "drop_tests/util/student_t.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "rft/contact_wrench.h"
#include "rft/ground.h"
#include "rft/input_error.h"
#include "rft/soil_contact_model.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::dataset {

namespace {
// The regressor of one pad: its quasi-static vertical RFT force at depth d for zeta = 1 N/m^3
// (at the soil's reference gravity), moving straight down. An axisymmetric pad: the profile
// integral. A mesh pad: the 3D contact (Li 2013 in 3D, Treers et al. 2021) on the level pad
// whose lowest point is at depth d, moving straight down at 1 m/s - the force its free drop
// feels, and for a revolved profile exactly the profile integral.
// A soil's own dynamic term (dynamic RFT's lambda rho (v.n)^2, which does not scale with zeta) is
// taken off the measured force first (DynamicForce): left in, zeta would absorb it and come out
// too high by the term's share of the force (2 % on fjs1_lp at 1 m/s).
class UnitZetaForce {
 public:
  explicit UnitZetaForce(const io::PadSpec& pad) : pad_(pad) {
    if (pad.is_axisymmetric()) intrusion_ = drop::MakeRigIntrusion(pad.profile);
  }
  // Throws InputError (naming `where`) for a mesh pad on a soil whose 3D law is not linear in zeta.
  double At(double depth_m, const rft::SoilParameters& soil, const std::string& where) {
    if (intrusion_) return intrusion_->VerticalForce(depth_m, 1.0);
    return MeshForce(depth_m, 1.0, *Laws(soil, where).quasi_static);
  }
  // The soil's dynamic term on the pad at depth d sinking at speed v [N], as every drop on the
  // soil feels it (rft::WithSoilDynamicTerm; the rig: lambda rho v^2 I_3(d)); 0 without one.
  double DynamicForce(double depth_m, double speed_m_s, const rft::SoilParameters& soil, const std::string& where) {
    const double lambda = rft::WithSoilDynamicTerm({}, soil).inertial_lambda;
    if (lambda == 0.0 || !(speed_m_s > 0.0) || !(depth_m > 0.0)) return 0.0;
    if (intrusion_)
      return lambda * soil.bulk_density_kg_m3 * speed_m_s * speed_m_s * intrusion_->CosinePowerIntegral(depth_m, 3);
    const UnitLaws& laws = Laws(soil, where);
    return MeshForce(depth_m, speed_m_s, *laws.dynamic.law) - MeshForce(depth_m, speed_m_s, *laws.quasi_static);
  }

 private:
  struct UnitLaws {
    std::unique_ptr<rft::StressLaw3D> quasi_static;
    rft::SoilContactModel dynamic;  // zeta = 1 with the soil's dynamic term: minus quasi_static, the term alone
  };
  const UnitLaws& Laws(const rft::SoilParameters& soil, const std::string& where) {
    if (soil.rft_law_3d != rft::LawKind::kLi2013)
      throw MakeInputError(where, "soil",
                           "mesh pad '" + pad_.name + "' on soil '" + soil.name + "' with rft_law_3d '" +
                               std::string(rft::LawKindName(soil.rft_law_3d)) + "': only li2013 scales with zeta, so only it can be calibrated");
    UnitLaws& laws = laws_[soil.name];
    if (!laws.quasi_static) {
      rft::SoilParameters unit = soil;
      unit.zeta_N_m3 = 1.0;
      laws.quasi_static = rft::MakeStressLaw3D(rft::LawKind::kLi2013, unit, unit.reference_gravity_m_s2);
      laws.dynamic = model::MakeContactModel(
          {.law = rft::LawKind::kLi2013, .soil = unit, .gravity_m_s2 = unit.reference_gravity_m_s2});
    }
    return laws;
  }
  double MeshForce(double depth_m, double speed_m_s, const rft::StressLaw3D& law) const {
    rft::PadKinematics k;
    k.p_WB.z() = -depth_m - pad_.body.lowest_z_B;  // the lowest point at depth d below z = 0
    k.v_WB_W = Eigen::Vector3d(0.0, 0.0, -speed_m_s);
    return rft::ComputeContactWrench(pad_.body.surface, k, rft::PlaneGround(), law).force_W.z();
  }

  io::PadSpec pad_;
  std::unique_ptr<geom::AxisymmetricIntrusion> intrusion_;
  std::map<std::string, UnitLaws> laws_;
};

// The sink rate at sample i of a trace [m/s], by central differences of the penetration (one-sided
// at the ends): the dynamic term needs it and datasets record penetration, not speed.
double SinkRate(const DatasetTrace& trace, size_t i) {
  const size_t a = i > 0 ? i - 1 : i, b = i + 1 < trace.size() ? i + 1 : i;
  if (a == b || !(trace.t_s[b] > trace.t_s[a])) return 0.0;
  return (trace.penetration_m[b] - trace.penetration_m[a]) / (trace.t_s[b] - trace.t_s[a]);
}
}  // namespace

namespace fs = std::filesystem;

size_t LoadingStrokeEnd(const DatasetTrace& trace) {
  if (trace.size() == 0) return 0;
  const size_t deepest = static_cast<size_t>(
      std::max_element(trace.penetration_m.begin(), trace.penetration_m.end()) - trace.penetration_m.begin());
  // The stroke ends where the pad stops: the force falls from the soil's capacity F(d) to the
  // weight carried at rest. With noise on the penetration a rest sample may be the deepest one;
  // without this cut the rest samples (force m g against F(d) in the regressor) would pull zeta
  // down (the shipped synthetic dataset: 1.1 instead of 3.48 N/cm^3). Looked for in the deeper
  // half of the stroke only, so an impact transient at shallow depth does not end it.
  const double half_depth = 0.5 * trace.penetration_m[deepest];
  double peak = 0.0;
  for (size_t i = 0; i <= deepest; ++i) {
    if (trace.penetration_m[i] < half_depth) continue;
    if (peak > 0.0 && trace.force_N[i] < 0.5 * peak) return i - 1;
    peak = std::max(peak, trace.force_N[i]);
  }
  return deepest;
}

std::vector<size_t> LoadingStrokeIndices(const DatasetTrace& trace) {
  std::vector<size_t> out;
  if (trace.size() == 0) return out;
  const size_t end = LoadingStrokeEnd(trace);
  for (size_t i = 0; i <= end; ++i)
    if (trace.penetration_m[i] > 0.0) out.push_back(i);
  // A sensor that averages over its sample period (pad::SensorSampling::kPeriodMean) records, in
  // the sample astride the touchdown, the free fall's zero force mixed with the stroke's, and in
  // the one astride the stop the stroke's force mixed with the weight: neither is the law at its
  // depth. A dataset does not say how its sensors sample, so the first and the last samples of the
  // stroke are always left out: from a sensor that samples instantaneously they are good samples,
  // and leaving them out costs two of the stroke's tens of samples, no bias.
  if (out.size() <= 2) return {};
  return std::vector<size_t>(out.begin() + 1, out.end() - 1);
}

ZetaFit FitZeta(const std::vector<StrokeSamples>& drops, double confidence) {
  ZetaFit fit;
  double sxx = 0.0, sxy = 0.0;
  for (const StrokeSamples& d : drops) {
    for (size_t i = 0; i < d.x.size(); ++i) sxx += d.x[i] * d.x[i], sxy += d.x[i] * d.force_N[i];
    fit.samples += static_cast<long>(d.x.size());
    fit.drops += d.x.empty() ? 0 : 1;
  }
  if (!(sxx > 0.0) || fit.samples < 2) throw InputError("calibrate: fewer than two loading-stroke samples to fit");
  fit.zeta_N_m3 = sxy / sxx;
  double sse = 0.0, score_sq = 0.0;
  for (const StrokeSamples& d : drops) {
    double score = 0.0;
    for (size_t i = 0; i < d.x.size(); ++i) {
      const double e = d.force_N[i] - fit.zeta_N_m3 * d.x[i];
      sse += e * e;
      score += d.x[i] * e;
    }
    score_sq += score * score;
  }
  fit.residual_rms_N = std::sqrt(sse / fit.samples);
  if (fit.drops >= 2) {
    const double g = fit.drops;
    fit.standard_error_N_m3 = std::sqrt(g / (g - 1.0) * score_sq) / sxx;
    fit.degrees_of_freedom = g - 1.0;
    fit.method = "least squares of force on the quasi-static RFT force per unit zeta over the loading strokes; "
                 "cluster-robust standard error (drops as clusters), Student t with drops - 1 dof";
  } else {
    fit.standard_error_N_m3 = std::sqrt(sse / (fit.samples - 1.0) / sxx);
    fit.degrees_of_freedom = fit.samples - 1.0;
    fit.method = "least squares of force on the quasi-static RFT force per unit zeta over the loading stroke; "
                 "i.i.d. standard error (one drop), Student t with samples - 1 dof";
  }
  const double q = io::StudentTTwoSided(confidence, fit.degrees_of_freedom);
  fit.low_N_m3 = fit.zeta_N_m3 - q * fit.standard_error_N_m3;
  fit.high_N_m3 = fit.zeta_N_m3 + q * fit.standard_error_N_m3;
  return fit;
}

std::vector<ZetaFit> CalibrateZeta(const Dataset& measured, const CalibrationOptions& options) {
  if (!(options.confidence > 0.0 && options.confidence < 1.0))
    throw MakeInputError("", "confidence", "must be between 0 and 1");
  std::map<std::string, std::unique_ptr<UnitZetaForce>> pads;
  std::map<std::string, rft::SoilParameters> soils;
  std::map<std::string, std::vector<StrokeSamples>> groups;
  std::map<std::string, std::vector<std::pair<std::string, double>>> group_soils;
  std::set<std::string> dynamic_groups;
  for (const DatasetDrop& d : measured.drops) {
    if (options.atmosphere && d.atmosphere != *options.atmosphere) continue;
    const std::string pad_ref = measured.PadReference(d), soil_ref = measured.SoilReference(d);
    if (!pads.count(pad_ref)) pads.emplace(pad_ref, std::make_unique<UnitZetaForce>(io::LoadPad(pad_ref)));
    if (!soils.count(soil_ref)) soils.emplace(soil_ref, io::LoadSoil(soil_ref));
    UnitZetaForce& unit_force = *pads.at(pad_ref);
    const std::string where = (std::filesystem::path(measured.directory) / "drops.csv").string() + ": drop " + d.drop_id;
    const rft::SoilParameters& soil = soils.at(soil_ref);
    // g / g_ref: a unit zeta at the drop's gravity, scaled as every drop scales it.
    const double gravity_scale = drop::ZetaAtGravity(drop::DropSoil(soil, 1.0, std::nullopt), d.gravity_m_s2);
    StrokeSamples s;
    for (size_t i : LoadingStrokeIndices(d.trace)) {
      const double depth_m = d.trace.penetration_m[i];
      s.x.push_back(gravity_scale * unit_force.At(depth_m, soil, where));
      s.force_N.push_back(d.trace.force_N[i] - unit_force.DynamicForce(depth_m, SinkRate(d.trace, i), soil, where));
    }
    const std::string group = options.per_soil ? soil.name : "all";
    groups[group].push_back(std::move(s));
    if (rft::WithSoilDynamicTerm({}, soil).inertial_lambda != 0.0) dynamic_groups.insert(group);
    auto& names = group_soils[group];
    const std::pair<std::string, double> entry{soil.name, soil.reference_gravity_m_s2};
    if (std::find(names.begin(), names.end(), entry) == names.end()) names.push_back(entry);
  }
  if (groups.empty())
    throw MakeInputError(measured.directory, "", "no drops to calibrate on" +
                                                     (options.atmosphere
                                                          ? std::string(" in ") + rft::AtmosphereName(*options.atmosphere)
                                                          : std::string()));
  std::vector<ZetaFit> fits;
  for (const auto& [group, samples] : groups) {
    ZetaFit fit;
    try {
      fit = FitZeta(samples, options.confidence);
    } catch (const InputError& e) {
      throw MakeInputError(measured.directory, "soil " + group, e.what());
    }
    fit.group = group;
    if (dynamic_groups.count(group))
      fit.method += "; the soil's dynamic term (lambda rho v^2, v by central differences of the penetration) "
                    "taken off the measured force first";
    for (const auto& [soil_name, g_ref] : group_soils.at(group)) {
      fit.soils.push_back(soil_name);
      fit.reference_gravities_m_s2.push_back(g_ref);
    }
    fit.confidence = options.confidence;
    fits.push_back(fit);
  }
  return fits;
}

model::ModelFile CalibrationModel(const std::vector<ZetaFit>& fits, const Dataset& measured, const std::string& name) {
  model::ModelFile m;
  m.name = name;
  m.description = "zeta calibrated by touchdown calibrate on the dataset " +
                  fs::path(measured.directory).lexically_normal().filename().string() + " (each soil's fit.dataset)";
  for (const ZetaFit& f : fits)
    for (size_t k = 0; k < f.soils.size(); ++k) {
      const std::string& soil_name = f.soils[k];
      model::SoilOverride o;
      o.zeta_N_m3 = f.zeta_N_m3;
      o.reference_gravity_m_s2 = f.reference_gravities_m_s2[k];
      o.confidence = f.confidence;
      o.zeta_low_N_m3 = f.low_N_m3;
      o.zeta_high_N_m3 = f.high_N_m3;
      model::SoilFit fit{f.method, f.drops, f.samples, f.residual_rms_N, measured.directory};
      o.fit = fit;
      m.soils[soil_name] = o;
    }
  return m;
}

}  // namespace touchdown::dataset

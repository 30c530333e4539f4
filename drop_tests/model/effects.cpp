#include "drop_tests/model/effects.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "drop_tests/io/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::model {

namespace {
constexpr double kPi = std::numbers::pi;

EffectParameterInfo Param(std::string key, std::string symbol, std::string unit, double file_to_si, double lower,
                          double upper, double scale, double start, std::vector<double> scan = {}) {
  return {std::move(key), std::move(symbol), std::move(unit), file_to_si, lower, upper, scale, start, std::move(scan)};
}

std::string Text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
}  // namespace

const std::vector<EffectInfo>& EffectLibrary() {
  // Ranges are physical bounds (no negative damping, chi < 1); scales and starts are typical
  // magnitudes for 0.1 m pads at ~1 m/s on lunar simulants (a 100 N term), used by fits only.
  static const std::vector<EffectInfo> library = {
      {"inertial_drag", "stress lambda rho (v.n)^2 on leading elements: F += lambda rho v^2 I3(d)",
       {Param("lambda", "lambda", "-", 1.0, 0.0, 1e3, 1.0, 1.0)}, false, false},
      {"rate_damping", "stress c (v.n) on leading elements: F += c v I2(d)",
       {Param("c_N_s_m3", "c", "N s/m^3", 1.0, 0.0, 1e7, 1e4, 2e3)}, false, false},
      {"added_mass",
       "grains carried with the pad: m_a(d) = c_a rho (pi/3) a(d)^2 min(d, a(d)), entering as d(m_a v)/dt",
       {Param("c_a", "c_a", "-", 1.0, 0.0, 1e2, 1.0, 0.5)}, false, false},
      {"compaction_peak", "stress k_c (v.n)^2 exp(-d/d_c) on leading elements: F += k_c v^2 exp(-d/d_c) I3(d)",
       {Param("k_c_kg_m3", "k_c", "kg/m^3", 1.0, 0.0, 1e7, 1e4, 1e4),
        Param("d_c_mm", "d_c", "m", 1e-3, 1e-4, 0.1, 3e-3, 3e-3)},
       false, false},
      {"depth_exponent", "stress zeta alpha z_ref (z/z_ref)^p instead of zeta alpha z (z_ref = 10 mm)",
       {Param("p", "p", "-", 1.0, 0.2, 3.0, 0.2, 1.0)}, false, false},
      {"gas_cushion", "air drops only: zeta -> (1 - chi) zeta, plus stress c_g (v.n): F += c_g v I2(d)",
       {Param("chi", "chi", "-", 1.0, 0.0, 0.95, 0.1, 0.1), Param("c_g_N_s_m3", "c_g", "N s/m^3", 1.0, 0.0, 1e7, 1e4, 2e3)},
       true, false},
      {"sensor_offset",
       "measurement: recorded penetration = true + dz; recorded t = 0 lies dt after the true touchdown",
       {Param("dz_mm", "dz", "m", 1e-3, -0.05, 0.05, 1e-3, 0.0), Param("dt_ms", "dt", "s", 1e-3, -0.05, 0.05, 1e-3, 0.0,
              {-0.008, -0.004, 0.0, 0.004, 0.008, 0.012})},
       false, true},
  };
  return library;
}

const EffectInfo& FindEffect(const std::string& id, const std::string& context) {
  for (const EffectInfo& e : EffectLibrary())
    if (e.id == id) return e;
  std::string known;
  for (const EffectInfo& e : EffectLibrary()) known += (known.empty() ? "" : ", ") + e.id;
  throw MakeInputError(context, "", "unknown effect '" + id + "' (known: " + known + ")");
}

EffectTerms MakeEffectTerms(const std::vector<Effect>& effects, const std::string& context) {
  EffectTerms t;
  std::set<std::string> seen;
  for (const Effect& e : effects) {
    const EffectInfo& info = FindEffect(e.id, context);
    if (!seen.insert(e.id).second) throw MakeInputError(context, e.id, "effect listed twice");
    if (e.values.size() != info.parameters.size())
      throw MakeInputError(context, e.id, "expects " + std::to_string(info.parameters.size()) + " parameters");
    for (size_t i = 0; i < e.values.size(); ++i) {
      const EffectParameterInfo& p = info.parameters[i];
      const double v = e.values[i];
      if (!(std::isfinite(v) && v >= p.lower && v <= p.upper))
        throw MakeInputError(context, e.id + "." + p.key,
                             "must be in [" + Text(p.lower / p.file_to_si) + ", " + Text(p.upper / p.file_to_si) +
                                 "], got " + Text(v / p.file_to_si));
    }
    const std::vector<double>& v = e.values;
    if (e.id == "inertial_drag") t.inertial_lambda = v[0];
    else if (e.id == "rate_damping") t.damping_c_N_s_m3 = v[0];
    else if (e.id == "added_mass") t.added_mass_ca = v[0];
    else if (e.id == "compaction_peak") t.compaction_k_kg_m3 = v[0], t.compaction_depth_m = v[1];
    else if (e.id == "depth_exponent") t.depth_exponent = v[0];
    else if (e.id == "gas_cushion") t.gas_chi = v[0], t.gas_c_N_s_m3 = v[1];
    else if (e.id == "sensor_offset") t.sensor_dz_m = v[0], t.sensor_dt_s = v[1];
  }
  return t;
}

std::vector<std::string> ActiveEffects(const EffectTerms& t) {
  std::vector<std::string> out;
  if (t.inertial_lambda != 0.0) out.push_back("inertial_drag");
  if (t.damping_c_N_s_m3 != 0.0) out.push_back("rate_damping");
  if (t.added_mass_ca != 0.0) out.push_back("added_mass");
  if (t.compaction_k_kg_m3 != 0.0) out.push_back("compaction_peak");
  if (t.depth_exponent && *t.depth_exponent != 1.0) out.push_back("depth_exponent");
  if (t.gas_chi != 0.0 || t.gas_c_N_s_m3 != 0.0) out.push_back("gas_cushion");
  if (t.HasSensorOffset()) out.push_back("sensor_offset");
  return out;
}

std::vector<std::pair<std::string, std::string>> EffectsNotApplied(const EffectTerms& t, bool in_air) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& id : ActiveEffects(t)) {
    if (id == "sensor_offset")
      out.emplace_back(id, "a measurement effect, not physics: the simulated drop is the true one; `compare` "
                           "applies it to the simulated traces it compares with recorded ones");
    else if (id == "gas_cushion" && !in_air)
      out.emplace_back(id, "acts only on drops in air; this drop is in vacuum");
  }
  return out;
}

std::unique_ptr<rft::StressLaw3D> MakeEffectLaw3D(std::string_view law, const rft::SoilParameters& soil,
                                                  double gravity_m_s2, const EffectTerms& t, bool in_air,
                                                  const std::string& model_source) {
  rft::EffectTerms3D terms;
  terms.inertial_lambda = t.inertial_lambda;
  terms.inertial_density_kg_m3 = soil.bulk_density_kg_m3;
  terms.damping_c_N_s_m3 = t.damping_c_N_s_m3;
  if (t.depth_exponent) terms.depth_exponent = *t.depth_exponent;
  terms.depth_reference_m = t.depth_reference_m;
  terms.compaction_k_kg_m3 = t.compaction_k_kg_m3;
  terms.compaction_depth_m = t.compaction_depth_m;
  terms.added_mass_ca = t.added_mass_ca;
  if (in_air) {
    terms.gas_chi = t.gas_chi;
    terms.gas_c_N_s_m3 = t.gas_c_N_s_m3;
  }
  if ((terms.inertial_lambda > 0.0 || terms.added_mass_ca > 0.0) && !(soil.bulk_density_kg_m3 > 0.0))
    throw MakeInputError(soil.name, "bulk_density_kg_m3",
                         "the soil must state its bulk density for inertial_drag and added_mass (model " +
                             model_source + ")");
  return rft::MakeStressLaw3D(law, soil, gravity_m_s2, terms);
}

EffectSoilResponse::EffectSoilResponse(const geom::AxisymmetricIntrusion& pad, const SoilResponseInputs& inputs)
    : pad_(pad), in_(inputs) {
  if (in_.terms.NeedsDensity() && !(in_.bulk_density_kg_m3 > 0.0))
    throw MakeInputError("", "bulk_density_kg_m3",
                         "the soil must state its bulk density for inertial_drag and added_mass");
  zeta_qs_ = in_.zeta_N_m3 * (in_.in_air ? 1.0 - in_.terms.gas_chi : 1.0);
  i2_coefficient_ = in_.terms.damping_c_N_s_m3 + (in_.in_air ? in_.terms.gas_c_N_s_m3 : 0.0);
}

double EffectSoilResponse::QuasiStaticForce(double d) const {
  // p = 1 is the linear law itself: computed as such, so a neutral depth_exponent changes nothing.
  if (in_.terms.depth_exponent && *in_.terms.depth_exponent != 1.0)
    return pad_.PowerLawVerticalForce(d, zeta_qs_, *in_.terms.depth_exponent, in_.terms.depth_reference_m);
  return pad_.VerticalForce(d, zeta_qs_);
}

double EffectSoilResponse::Force(double d, double v) const {
  double f = QuasiStaticForce(d);
  if (!(v > 0.0) || !(d > 0.0)) return f;
  const EffectTerms& t = in_.terms;
  const double quadratic =
      t.inertial_lambda * in_.bulk_density_kg_m3 +
      (t.compaction_k_kg_m3 != 0.0 ? t.compaction_k_kg_m3 * std::exp(-d / t.compaction_depth_m) : 0.0);
  if (quadratic != 0.0) f += quadratic * v * v * pad_.CosinePowerIntegral(d, 3);
  if (i2_coefficient_ != 0.0) f += i2_coefficient_ * v * pad_.CosinePowerIntegral(d, 2);
  return f;
}

double EffectSoilResponse::AddedMass(double d) const {
  if (in_.terms.added_mass_ca == 0.0 || !(d > 0.0)) return 0.0;
  const double a = pad_.FootprintRadius(d);
  return in_.terms.added_mass_ca * in_.bulk_density_kg_m3 * kPi / 3 * a * a * std::min(d, a);
}

double EffectSoilResponse::AddedMassSlope(double d) const {
  if (in_.terms.added_mass_ca == 0.0 || !(d > 0.0)) return 0.0;
  const double a = pad_.FootprintRadius(d), a_slope = pad_.FootprintRadiusSlope(d);
  const double dv = d < a ? 2 * a * a_slope * d + a * a : 3 * a * a * a_slope;
  return in_.terms.added_mass_ca * in_.bulk_density_kg_m3 * kPi / 3 * dv;
}

RecordedSample RecordedAt(const pad::RigDropResult& r, double gravity_m_s2, const EffectTerms& terms, double t_rec) {
  const double t = t_rec + terms.sensor_dt_s;
  RecordedSample s;
  const std::vector<pad::DropSample>& tr = r.trace;
  if (tr.empty()) return s;
  if (t <= tr.front().t_s) {
    const double dt = t - tr.front().t_s;  // free fall before touchdown
    s.penetration_m = tr.front().penetration_m + tr.front().velocity_m_s * dt + 0.5 * gravity_m_s2 * dt * dt;
    s.force_N = 0.0;
  } else if (t >= tr.back().t_s) {
    s.penetration_m = tr.back().penetration_m;
    s.force_N = tr.back().force_N;
  } else {
    const auto it = std::upper_bound(tr.begin(), tr.end(), t, [](double x, const pad::DropSample& a) { return x < a.t_s; });
    const pad::DropSample& b = *it;
    const pad::DropSample& a = *(it - 1);
    const double w = (t - a.t_s) / (b.t_s - a.t_s);
    s.penetration_m = a.penetration_m + w * (b.penetration_m - a.penetration_m);
    s.force_N = a.force_N + w * (b.force_N - a.force_N);
  }
  s.penetration_m += terms.sensor_dz_m;
  return s;
}

}  // namespace touchdown::model

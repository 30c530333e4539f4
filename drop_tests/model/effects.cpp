#include "drop_tests/model/effects.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::model {

namespace {

EffectParameterInfo Param(std::string key, std::string symbol, std::string unit, double file_to_si, double lower,
                          double upper, double scale, double start, std::vector<double> scan = {},
                          double neutral = 0.0, std::string file_unit = {}) {
  return {std::move(key), std::move(symbol), std::move(unit), file_to_si, lower, upper, scale, start, std::move(scan),
          neutral, std::move(file_unit)};
}

// The index in rft::RegisteredEffects() of a registered effect's kind.
size_t RegisteredIndex(EffectId kind) {
  return static_cast<size_t>(kind) - static_cast<size_t>(EffectId::kRegisteredBegin);
}

// Sets the terms of effect `kind` from its values (SI, in EffectInfo::parameters order).
void SetTerm(EffectId kind, const std::vector<double>& v, rft::EffectTerms& t) {
  switch (kind) {
    case EffectId::kInertialDrag:
      t.inertial_lambda = v[0], t.inertial_replaces_soil = true;
      return;
    case EffectId::kRateDamping:
      t.damping_c_N_s_m3 = v[0];
      return;
    case EffectId::kAddedMass:
      t.added_mass_ca = v[0];
      return;
    case EffectId::kAddedMassPlug:
      t.added_mass_plug_cp = v[0];
      return;
    case EffectId::kCompactionPeak:
      t.compaction_k_kg_m3 = v[0], t.compaction_depth_m = v[1];
      return;
    case EffectId::kDepthExponent:
      t.depth_exponent = v[0];
      return;
    case EffectId::kGasCushion:
      t.gas_chi = v[0], t.gas_c_N_s_m3 = v[1];
      return;
    case EffectId::kSensorOffset:
      t.sensor_dz_m = v[0], t.sensor_dt_s = v[1];
      return;
    default: {  // a registered effect
      rft::RegisteredEffectValues& r = t.registered[RegisteredIndex(kind)];
      r.active = true;
      std::copy(v.begin(), v.end(), r.values.begin());
      return;
    }
  }
}

// Whether effect `kind` acts under `t` (its parameters not all neutral).
bool IsActive(EffectId kind, const rft::EffectTerms& t) {
  switch (kind) {
    case EffectId::kInertialDrag:
      return t.inertial_lambda != 0.0;
    case EffectId::kRateDamping:
      return t.damping_c_N_s_m3 != 0.0;
    case EffectId::kAddedMass:
      return t.added_mass_ca != 0.0;
    case EffectId::kAddedMassPlug:
      return t.added_mass_plug_cp != 0.0;
    case EffectId::kCompactionPeak:
      return t.compaction_k_kg_m3 != 0.0;
    case EffectId::kDepthExponent:
      return t.HasDepthExponent();
    case EffectId::kGasCushion:
      return t.gas_chi != 0.0 || t.gas_c_N_s_m3 != 0.0;
    case EffectId::kSensorOffset:
      return t.HasSensorOffset();
    default: {  // a registered effect: on, and not all of its parameters neutral
      const size_t i = RegisteredIndex(kind);
      const std::vector<rft::EffectParameter>& params = rft::RegisteredEffects()[i].parameters;
      if (!t.registered[i].active) return false;
      for (size_t k = 0; k < params.size(); ++k)
        if (t.registered[i].values[k] != params[k].neutral) return true;
      return false;
    }
  }
}

}  // namespace

const std::vector<EffectInfo>& EffectLibrary() {
  // Ranges are physical bounds (no negative damping, chi < 1); scales and starts are typical
  // magnitudes for 0.1 m pads at ~1 m/s on lunar simulants (a 100 N term), used by fits only.
  using enum EffectId;
  static const std::vector<EffectInfo> library = [] {
    std::vector<EffectInfo> built_in = {
      {kInertialDrag, "inertial_drag", "stress lambda rho (v.n)^2 on leading elements: F += lambda rho v^2 I3(d)",
       {Param("lambda", "lambda", "-", 1.0, 0.0, 1e3, 1.0, 1.0)}, false, false, true},
      {kRateDamping, "rate_damping", "stress c (v.n) on leading elements: F += c v I2(d)",
       {Param("c_N_s_m3", "c", "N s/m^3", 1.0, 0.0, 1e7, 1e4, 2e3)}, false, false, false},
      {kAddedMass, "added_mass",
       "grains carried with the pad: m_a(d) = c_a rho (pi/3) a(d)^2 min(d, a(d)), entering as d(m_a v)/dt",
       {Param("c_a", "c_a", "-", 1.0, 0.0, 1e2, 1.0, 0.5)}, false, false, true},
      {kAddedMassPlug, "added_mass_plug",
       "dead zone under the pad: m_p(d) = c_p rho (pi/3) a(d)^3 min(1, d/d_f), d_f = 1 mm, entering as d(m_p v)/dt",
       {Param("c_p", "c_p", "-", 1.0, 0.0, 1e2, 1.0, 0.5)}, false, false, true},
      {kCompactionPeak, "compaction_peak",
       "stress k_c (v.n)^2 exp(-d/d_c) on leading elements: F += k_c v^2 exp(-d/d_c) I3(d)",
       {Param("k_c_kg_m3", "k_c", "kg/m^3", 1.0, 0.0, 1e7, 1e4, 1e4),
        Param("d_c_mm", "d_c", "m", units::kMm, 1e-4, 0.1, 3e-3, 3e-3, {}, 0.0, "mm")},
       false, false, false},
      {kDepthExponent, "depth_exponent", "stress zeta alpha z_ref (z/z_ref)^p instead of zeta alpha z (z_ref = 10 mm)",
       {Param("p", "p", "-", 1.0, 0.2, 3.0, 0.2, 1.0, {}, 1.0)}, false, false, false},
      {kGasCushion, "gas_cushion", "air drops only: zeta -> (1 - chi) zeta, plus stress c_g (v.n): F += c_g v I2(d)",
       {Param("chi", "chi", "-", 1.0, 0.0, 0.95, 0.1, 0.1), Param("c_g_N_s_m3", "c_g", "N s/m^3", 1.0, 0.0, 1e7, 1e4, 2e3)},
       true, false, false},
      {kSensorOffset, "sensor_offset",
       "measurement: recorded penetration = true + dz; recorded t = 0 lies dt after the true touchdown",
       {Param("dz_mm", "dz", "m", units::kMm, -0.05, 0.05, 1e-3, 0.0, {}, 0.0, "mm"), Param("dt_ms", "dt", "s", units::kMs, -0.05, 0.05, 1e-3, 0.0,
              {-0.008, -0.004, 0.0, 0.004, 0.008, 0.012}, 0.0, "ms")},
       false, true, false},
    };
    for (size_t i = 0; i < rft::RegisteredEffects().size(); ++i) {
      const rft::EffectDefinition& e = rft::RegisteredEffects()[i];
      built_in.push_back({static_cast<EffectId>(static_cast<size_t>(kRegisteredBegin) + i), e.id, e.form, e.parameters,
                          e.air_only, false, e.needs_bulk_density, &e});
    }
    return built_in;
  }();
  return library;
}

const EffectInfo& FindEffect(const std::string& id, const std::string& context) {
  for (const EffectInfo& e : EffectLibrary())
    if (e.id == id) return e;
  std::string known;
  for (const EffectInfo& e : EffectLibrary()) known += (known.empty() ? "" : ", ") + e.id;
  throw MakeInputError(context, "", "unknown effect '" + id + "' (known: " + known + ")");
}

const EffectInfo& FindEffect(EffectId kind) { return EffectLibrary()[static_cast<size_t>(kind)]; }

rft::EffectTerms MakeEffectTerms(const std::vector<Effect>& effects, const std::string& context) {
  rft::EffectTerms t;
  std::set<std::string> seen;
  for (const Effect& e : effects) {
    const EffectInfo& info = FindEffect(e.id, context);
    if (!seen.insert(e.id).second) throw MakeInputError(context, e.id, "effect listed twice");
    if (e.values.size() != info.parameters.size())
      throw MakeInputError(context, e.id, "expects " + std::to_string(info.parameters.size()) + " parameters");
    for (size_t i = 0; i < e.values.size(); ++i) {
      const EffectParameterInfo& p = info.parameters[i];
      const double v = e.values[i];
      if (const std::string why = p.RangeProblem(v); !why.empty())
        throw MakeInputError(context, e.id + "." + p.key, why);
    }
    SetTerm(info.kind, e.values, t);
  }
  return t;
}

std::vector<EffectId> ActiveEffectIds(const rft::EffectTerms& t) {
  std::vector<EffectId> out;
  for (const EffectInfo& e : EffectLibrary())
    if (IsActive(e.kind, t)) out.push_back(e.kind);
  return out;
}

std::vector<std::string> ActiveEffects(const rft::EffectTerms& t) {
  std::vector<std::string> out;
  for (const EffectId kind : ActiveEffectIds(t)) out.push_back(FindEffect(kind).id);
  return out;
}

std::vector<std::pair<std::string, std::string>> EffectsNotApplied(const rft::EffectTerms& t, bool in_air) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const EffectId kind : ActiveEffectIds(t)) {
    const std::string& id = FindEffect(kind).id;
    if (FindEffect(kind).measurement_only)
      out.emplace_back(id, "a measurement effect, not physics: the simulated drop is the true one; `compare` "
                           "applies it to the simulated traces it compares with recorded ones");
    else if (FindEffect(kind).air_only && !in_air)
      out.emplace_back(id, "acts only on drops in air; this drop is in vacuum");
  }
  return out;
}

}  // namespace touchdown::model

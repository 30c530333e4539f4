#include "drop_tests/sweep/sweep_plan.h"


#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/util/splitmix.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/model/contact_model.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "drop_tests/sweep/sweep_file_keys.h"
#include "rft/bekker_law.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"
#include "drop_tests/sweep/sweep_param_table.h"

// The sweep plan (sweep_plan.h): its drops by index, their ids, its digest; the parameters' keys
// and values. Reading it from its file: sweep_plan_file.cpp.
namespace touchdown::sweep {

namespace fs = std::filesystem;
using namespace param_table;

const char* TraceStorageName(TraceStorage t) { return NameIn(kTraceStorageNames, t); }

std::optional<SweepParam> SweepParamFromKey(const std::string& key) { return ParamFromKey(key); }
double SweepParamFromSi(SweepParam p, double si) { return FromSi(p, si); }
double SweepParamToSi(SweepParam p, double file_value) { return ToSi(p, file_value); }
bool IsLanderNumber(SweepParam p) {
  return !IsName(p) && !IsSinglePadOnly(p);
}

double ParamValue(const SweepDropParams& d, SweepParam p) {
  switch (p) {
    case SweepParam::kImpactSpeed: return d.impact_speed_m_s;
    case SweepParam::kGravity: return d.gravity_m_s2;
    case SweepParam::kTilt: return d.tilt_rad;
    case SweepParam::kHorizontalSpeed: return d.horizontal_speed_m_s;
    case SweepParam::kRoll: return d.roll_rad;
    case SweepParam::kPitch: return d.pitch_rad;
    case SweepParam::kSlope: return d.slope_rad;
    case SweepParam::kDownhillAzimuth: return d.downhill_azimuth_rad;
    case SweepParam::kYawToSlope: return d.yaw_to_slope_rad;
    case SweepParam::kHorizontalAzimuth: return d.horizontal_azimuth_rad;
    case SweepParam::kRateX: return d.angular_rate_rad_s[0];
    case SweepParam::kRateY: return d.angular_rate_rad_s[1];
    case SweepParam::kRateZ: return d.angular_rate_rad_s[2];
    case SweepParam::kMass: return d.mass_kg.value_or(std::nan(""));
    case SweepParam::kZeta: return d.zeta_N_m3.value_or(std::nan(""));
    case SweepParam::kPad: return d.pad;
    case SweepParam::kSoil: return d.soil;
    case SweepParam::kPadSoils: return d.pad_soils;
  }
  return std::nan("");
}

const char* SweepParamKey(SweepParam p) {
  switch (p) {
    case SweepParam::kPad: return "pad";
    case SweepParam::kSoil: return "soil";
    case SweepParam::kImpactSpeed: return "impact_speed_m_s";
    case SweepParam::kMass: return "pad_mass_kg";
    case SweepParam::kGravity: return "gravity_m_s2";
    case SweepParam::kTilt: return "tilt_deg";
    case SweepParam::kHorizontalSpeed: return "horizontal_speed_m_s";
    case SweepParam::kZeta: return "zeta_N_cm3";
    case SweepParam::kRoll: return "roll_deg";
    case SweepParam::kPitch: return "pitch_deg";
    case SweepParam::kPadSoils: return "pad_soils";
    case SweepParam::kSlope: return "slope_deg";
    case SweepParam::kDownhillAzimuth: return "downhill_azimuth_deg";
    case SweepParam::kYawToSlope: return "yaw_relative_to_slope_deg";
    case SweepParam::kHorizontalAzimuth: return "horizontal_azimuth_deg";
    case SweepParam::kRateX: return "angular_rate_x_deg_s";
    case SweepParam::kRateY: return "angular_rate_y_deg_s";
    case SweepParam::kRateZ: return "angular_rate_z_deg_s";
  }
  return "?";
}

std::string PaperGroundCase(const std::array<std::string, 4>& soil_names) {
  for (const PaperCase& c : kPaperCases)
    if (std::equal(soil_names.begin(), soil_names.end(), c.soils.begin())) return c.label;
  return "";
}

uint64_t Fnv1a64(const std::string& text) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

double CounterUniform(uint64_t seed, uint64_t sample, uint64_t stream) {
  const auto mix = io::SplitMix64;
  const uint64_t z = mix(mix(mix(seed) ^ sample) ^ (stream * 0x632be59bd9b4e019ull));
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

namespace {
// The value a choice's uniform draw u in [0, 1) picks: uniformly, or by its probabilities
// (cumulative; a value of probability 0 is never picked).
size_t ChoicePick(const SweepRandom& r, double u) {
  if (r.probabilities.empty()) return std::min(r.values.size() - 1, static_cast<size_t>(u * r.values.size()));
  double cumulative = 0.0;
  size_t last = 0;
  for (size_t i = 0; i < r.probabilities.size(); ++i) {
    if (r.probabilities[i] <= 0.0) continue;
    cumulative += r.probabilities[i];
    last = i;
    if (u < cumulative) return i;
  }
  return last;  // u above a sum rounded below 1
}
}  // namespace

int64_t SweepPlan::size() const {
  int64_t n = samples;
  for (const SweepAxis& a : grid) n *= static_cast<int64_t>(a.values.size());
  return n;
}

SweepDropParams SweepPlan::DropAt(int64_t index) const {
  double value[kSweepParamCount] = {};
  bool set[kSweepParamCount] = {};
  for (int p = 0; p < kSweepParamCount; ++p)
    if (fixed[p]) value[p] = *fixed[p], set[p] = true;
  int64_t g = index / samples;
  const uint64_t s = static_cast<uint64_t>(index % samples);
  for (size_t k = grid.size(); k-- > 0;) {  // the last-listed axis varies fastest
    const int64_t n = static_cast<int64_t>(grid[k].values.size());
    value[static_cast<int>(grid[k].param)] = grid[k].values[g % n];
    set[static_cast<int>(grid[k].param)] = true;
    g /= n;
  }
  const std::vector<double>* given = nullptr;
  if (given_uniforms)
    if (const auto it = given_uniforms->find(static_cast<int64_t>(s)); it != given_uniforms->end()) given = &it->second;
  for (size_t k = 0; k < random.size(); ++k) {
    const SweepRandom& r = random[k];
    const double u = given ? (*given)[k] : CounterUniform(seed, s, static_cast<uint64_t>(r.param));
    double v;
    if (r.per_pad) {
      // One draw per pad, each on its own stream: pad i's soil does not depend on the others'.
      const size_t k = r.values.size();
      size_t set = 0, weight = 1;
      for (uint64_t pad = 0; pad < 4; ++pad, weight *= k)
        set += weight * ChoicePick(r, CounterUniform(seed, s, kPerPadStream * (pad + 1) + static_cast<uint64_t>(r.param)));
      v = static_cast<double>(r.first_set + static_cast<int64_t>(set));
    } else if (r.choice) {
      v = r.values[ChoicePick(r, u)];
    } else {
      v = r.low + (r.high - r.low) * u;
    }
    value[static_cast<int>(r.param)] = v;
    set[static_cast<int>(r.param)] = true;
  }
  auto at = [&](SweepParam p) { return value[static_cast<int>(p)]; };
  auto has = [&](SweepParam p) { return set[static_cast<int>(p)]; };
  SweepDropParams d;
  d.index = index;
  d.pad = static_cast<int>(at(SweepParam::kPad));
  d.soil = static_cast<int>(at(SweepParam::kSoil));
  d.impact_speed_m_s = at(SweepParam::kImpactSpeed);
  if (has(SweepParam::kMass)) d.mass_kg = at(SweepParam::kMass);
  if (has(SweepParam::kGravity)) d.gravity_m_s2 = at(SweepParam::kGravity);
  if (has(SweepParam::kTilt)) d.tilt_rad = at(SweepParam::kTilt);
  if (has(SweepParam::kHorizontalSpeed)) d.horizontal_speed_m_s = at(SweepParam::kHorizontalSpeed);
  if (has(SweepParam::kZeta)) d.zeta_N_m3 = at(SweepParam::kZeta);
  if (has(SweepParam::kRoll)) d.roll_rad = at(SweepParam::kRoll);
  if (has(SweepParam::kPitch)) d.pitch_rad = at(SweepParam::kPitch);
  if (has(SweepParam::kPadSoils)) d.pad_soils = static_cast<int>(at(SweepParam::kPadSoils));
  d.slope_rad = at(SweepParam::kSlope);
  d.downhill_azimuth_rad = at(SweepParam::kDownhillAzimuth);
  d.yaw_to_slope_rad = at(SweepParam::kYawToSlope);
  d.horizontal_azimuth_rad = at(SweepParam::kHorizontalAzimuth);
  d.angular_rate_rad_s = {at(SweepParam::kRateX), at(SweepParam::kRateY), at(SweepParam::kRateZ)};
  for (SweepParam p : kAll)
    if (has(p)) d.given |= 1u << static_cast<int>(p);
  return d;
}

std::string SweepPlan::DropId(int64_t index) const {
  const int width = std::max<int>(1, static_cast<int>(std::to_string(std::max<int64_t>(size() - 1, 0)).size()));
  std::string digits = std::to_string(index);
  if (static_cast<int>(digits.size()) < width) digits.insert(0, width - digits.size(), '0');
  return "d" + digits;
}

std::string SweepPlan::DigestText() const {
  std::string s = "sweep-v1;samples=" + std::to_string(samples) + ";seed=" + std::to_string(seed) +
                  ";traces=" + TraceStorageName(traces) + ";max=" + std::to_string(trace_max_samples) +
                  ";rest=" + io::FormatNumber(rig.rest_duration_s) + ";rate=" + io::FormatNumber(rig.sample_rate_hz) + ";";
  for (const io::PadSpec& p : pads) {
    s += "pad:" + p.name + ":" + io::FormatNumber(p.mass_kg) + ":" +
         (p.is_axisymmetric() ? io::FormatNumber(p.profile.thickness_m()) : std::string("mesh")) + ":";
    for (const auto& pt : p.profile.points) s += io::FormatNumber(pt.x_m) + "/" + io::FormatNumber(pt.u_m) + ",";
    // The pad file (mesh, segments, inertia, reference point) and a mesh pad's mesh shape free drops.
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016" PRIx64, Fnv1a64(FileText(p.source) + '\0' + FileText(p.mesh_file)));
    s += std::string(":files=") + hex + ";";
  }
  for (const PadSoilSet& set : pad_soil_sets)
    s += "pad_soils:" + set.label + "=" + std::to_string(set.soil[0]) + "," + std::to_string(set.soil[1]) + "," +
         std::to_string(set.soil[2]) + "," + std::to_string(set.soil[3]) + ";";
  if (!pad_soil_sets.empty()) s += "pad_patch_half_width=" + io::FormatNumber(pad_patch_half_width_m) + ";";
  for (const rft::SoilParameters& soil : soils)
    s += "soil:" + soil.name + ":" + rft::AtmosphereName(soil.atmosphere) + ":" + io::FormatNumber(soil.zeta_N_m3) + ":" +
         io::FormatNumber(soil.reference_gravity_m_s2) +
         (soil.gravity_scaling == rft::GravityScaling::kLithostatic ? "" : ":gravity_scaling=none") + ";";
  for (int p = 0; p < kSweepParamCount; ++p)
    if (fixed[p]) s += std::string("fixed:") + SweepParamKey(kAll[p]) + "=" + io::FormatNumber(*fixed[p]) + ";";
  for (const SweepAxis& a : grid) {
    s += std::string("grid:") + SweepParamKey(a.param) + "=";
    for (double v : a.values) s += io::FormatNumber(v) + ",";
    s += ";";
  }
  for (const SweepRandom& r : random) {
    s += std::string("random:") + SweepParamKey(r.param) + (r.choice ? "=choice:" : "=uniform:") +
         io::FormatNumber(r.low) + ":" + io::FormatNumber(r.high) + ":";
    for (double v : r.values) s += io::FormatNumber(v) + ",";
    if (r.per_pad) s += "per_pad:" + std::to_string(r.first_set) + ",";  // only when used: older digests stay
    if (!r.probabilities.empty()) s += "p:";
    for (double v : r.probabilities) s += io::FormatNumber(v) + ",";
    s += ";";
  }
  if (model) s += model::ModelDigestText(*model);
  if (lander) s += "lander:" + lander->name + ":" + lander_digest + ";";
  // Only when fast: a reference plan's digest stays, and neither resumes the other's database.
  if (free_drop_model == drop::FreeDropModel::kFast) s += "free_drop_model=fast;";
  if (!variant.empty()) s += "variant:" + variant + ";";  // only when set: a loaded plan's digest stays
  return s;
}

}  // namespace touchdown::sweep

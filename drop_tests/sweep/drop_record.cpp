#include "drop_tests/sweep/results_db.h"

#include <cstring>
#include <stdexcept>

// A drop's record as numbers by name (the drops table's groups), compared bit for bit, and as
// bytes between MPI ranks. The database that stores records: results_db.cpp.
namespace touchdown::sweep {

namespace {
bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Serialisation helpers: fixed-size values by memcpy, strings with a length prefix.
template <typename T>
void Put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
void PutString(std::string& out, const std::string& s) {
  Put<uint64_t>(out, s.size());
  out += s;
}
struct Reader {
  const std::string& in;
  size_t pos = 0;
  template <typename T>
  T Get() {
    if (pos + sizeof(T) > in.size()) throw std::runtime_error("DeserializeRecords: truncated message");
    T v;
    std::memcpy(&v, in.data() + pos, sizeof v);
    pos += sizeof v;
    return v;
  }
  std::string GetString() {
    const uint64_t n = Get<uint64_t>();
    if (pos + n > in.size()) throw std::runtime_error("DeserializeRecords: truncated message");
    std::string s = in.substr(pos, n);
    pos += n;
    return s;
  }
};
static_assert(sizeof(pad::DropSample) == 4 * sizeof(double), "traces are stored as 4 doubles per sample");
}  // namespace

const std::vector<RecordNumber>& RigNumbers() {
  static const std::vector<RecordNumber> c = {
      {"impact_speed_m_s", [](DropRecord& r) -> double& { return r.impact_speed_m_s; }},
      {"pad_mass_kg", [](DropRecord& r) -> double& { return r.pad_mass_kg; }},
      {"gravity_m_s2", [](DropRecord& r) -> double& { return r.gravity_m_s2; }},
      {"tilt_deg", [](DropRecord& r) -> double& { return r.tilt_deg; }},
      {"horizontal_speed_m_s", [](DropRecord& r) -> double& { return r.horizontal_speed_m_s; }},
      {"zeta_N_cm3", [](DropRecord& r) -> double& { return r.zeta_N_cm3; }},
      {"final_penetration_m", [](DropRecord& r) -> double& { return r.final_penetration_m; }},
      {"peak_force_N", [](DropRecord& r) -> double& { return r.peak_force_N; }},
      {"time_to_rest_s", [](DropRecord& r) -> double& { return r.time_to_rest_s; }},
      {"max_deceleration_m_s2", [](DropRecord& r) -> double& { return r.max_deceleration_m_s2; }},
      {"impact_energy_J", [](DropRecord& r) -> double& { return r.impact_energy_J; }},
      {"gravity_work_J", [](DropRecord& r) -> double& { return r.gravity_work_J; }},
      {"dissipated_energy_J", [](DropRecord& r) -> double& { return r.dissipated_energy_J; }},
      {"mean_conversion_rate_W", [](DropRecord& r) -> double& { return r.mean_conversion_rate_W; }},
      {"rest_creep_m", [](DropRecord& r) -> double& { return r.rest_creep_m; }}};
  return c;
}
const std::vector<RecordNumber>& FreeAndLanderNumbers() {
  static const std::vector<RecordNumber> c = {
      {"final_tilt_deg", [](DropRecord& r) -> double& { return r.final_tilt_deg; }},
      {"horizontal_travel_m", [](DropRecord& r) -> double& { return r.horizontal_travel_m; }},
      {"roll_deg", [](DropRecord& r) -> double& { return r.roll_deg; }},
      {"pitch_deg", [](DropRecord& r) -> double& { return r.pitch_deg; }},
      {"pad1_final_penetration_m", [](DropRecord& r) -> double& { return r.pad_final_penetration_m[0]; }},
      {"pad2_final_penetration_m", [](DropRecord& r) -> double& { return r.pad_final_penetration_m[1]; }},
      {"pad3_final_penetration_m", [](DropRecord& r) -> double& { return r.pad_final_penetration_m[2]; }},
      {"pad4_final_penetration_m", [](DropRecord& r) -> double& { return r.pad_final_penetration_m[3]; }},
      {"final_roll_deg", [](DropRecord& r) -> double& { return r.final_roll_deg; }},
      {"final_pitch_deg", [](DropRecord& r) -> double& { return r.final_pitch_deg; }},
      {"tipped_over", [](DropRecord& r) -> double& { return r.tipped_over; }}};
  return c;
}
const std::vector<RecordNumber>& StabilityNumbers() {
  static const std::vector<RecordNumber> c = {
      {"max_tilt_deg", [](DropRecord& r) -> double& { return r.max_tilt_deg; }},
      {"peak_leg_force_N", [](DropRecord& r) -> double& { return r.peak_leg_force_N; }},
      {"max_stroke_m", [](DropRecord& r) -> double& { return r.max_stroke_m; }},
      {"pad1_peak_force_N", [](DropRecord& r) -> double& { return r.pad_peak_force_N[0]; }},
      {"pad2_peak_force_N", [](DropRecord& r) -> double& { return r.pad_peak_force_N[1]; }},
      {"pad3_peak_force_N", [](DropRecord& r) -> double& { return r.pad_peak_force_N[2]; }},
      {"pad4_peak_force_N", [](DropRecord& r) -> double& { return r.pad_peak_force_N[3]; }},
      {"slope_deg", [](DropRecord& r) -> double& { return r.slope_deg; }},
      {"downhill_azimuth_deg", [](DropRecord& r) -> double& { return r.downhill_azimuth_deg; }},
      {"yaw_relative_to_slope_deg", [](DropRecord& r) -> double& { return r.yaw_relative_to_slope_deg; }},
      {"horizontal_azimuth_deg", [](DropRecord& r) -> double& { return r.horizontal_azimuth_deg; }},
      {"angular_rate_x_deg_s", [](DropRecord& r) -> double& { return r.angular_rate_deg_s[0]; }},
      {"angular_rate_y_deg_s", [](DropRecord& r) -> double& { return r.angular_rate_deg_s[1]; }},
      {"angular_rate_z_deg_s", [](DropRecord& r) -> double& { return r.angular_rate_deg_s[2]; }},
      {"max_joint_swing_deg", [](DropRecord& r) -> double& { return r.max_joint_swing_deg; }},
      {"tip_over_edge", [](DropRecord& r) -> double& { return r.tip_over_edge; }},
      {"tip_over_azimuth_deg", [](DropRecord& r) -> double& { return r.tip_over_azimuth_deg; }},
      {"min_stability_margin_m", [](DropRecord& r) -> double& { return r.min_stability_margin_m; }}};
  return c;
}

const RecordNumber& RecordNumberNamed(const std::string& name) {
  for (const std::vector<RecordNumber>* group : {&RigNumbers(), &FreeAndLanderNumbers(), &StabilityNumbers()})
    for (const RecordNumber& n : *group)
      if (name == n.name) return n;
  throw std::logic_error("results database: no number column '" + name + "'");
}

bool SameRecord(const DropRecord& a, const DropRecord& b, bool compare_traces) {
  for (const std::vector<RecordNumber>* group : {&RigNumbers(), &FreeAndLanderNumbers(), &StabilityNumbers()})
    for (const RecordNumber& n : *group)
      if (!SameBits(n.Of(a), n.Of(b))) return false;
  if (a.index != b.index || a.drop_id != b.drop_id || a.ok != b.ok || a.failure != b.failure || a.kind != b.kind ||
      a.pad != b.pad || a.soil != b.soil || a.atmosphere != b.atmosphere || a.solver_steps != b.solver_steps ||
      a.pad_soil != b.pad_soil || a.ground_case != b.ground_case || a.failure_limit != b.failure_limit ||
      !SameBits(a.failure_limit_value, b.failure_limit_value) || a.soil_parameters.size() != b.soil_parameters.size())
    return false;
  for (size_t k = 0; k < a.soil_parameters.size(); ++k)
    if (a.soil_parameters[k].first != b.soil_parameters[k].first ||
        !SameBits(a.soil_parameters[k].second, b.soil_parameters[k].second))
      return false;
  if (!compare_traces) return true;
  return a.trace.size() == b.trace.size() &&
         (a.trace.empty() || std::memcmp(a.trace.data(), b.trace.data(), a.trace.size() * sizeof(pad::DropSample)) == 0);
}

const char* DropKindName(DropKind kind) { return NameIn(kDropKindNames, kind); }

rft::Atmosphere ParseRecordAtmosphere(const std::string& text, const std::string& where) {
  if (const std::optional<rft::Atmosphere> a = rft::ParseAtmosphere(text)) return *a;
  throw InputError(where + ": atmosphere '" + text + "' is neither vacuum nor air");
}

DropKind ParseDropKind(const std::string& text, const std::string& where) {
  return ParseName(kDropKindNames, text, where, "drop_kind");
}

std::string SerializeRecords(const std::vector<DropRecord>& records) {
  std::string out;
  Put<uint64_t>(out, records.size());
  for (const DropRecord& r : records) {
    Put(out, r.index);
    PutString(out, r.drop_id);
    Put<uint8_t>(out, r.ok ? 1 : 0);
    const std::string kind = DropKindName(r.kind), atmosphere = rft::AtmosphereName(r.atmosphere);
    for (const std::string* s : {&r.failure, &kind, &r.pad, &r.soil, &atmosphere}) PutString(out, *s);
    for (const RecordNumber& n : RigNumbers()) Put(out, n.Of(r));
    for (const RecordNumber& n : FreeAndLanderNumbers()) Put(out, n.Of(r));
    for (const std::string* t : DropRecordTexts(r)) PutString(out, *t);
    PutString(out, r.failure_limit);
    Put(out, r.failure_limit_value);
    for (const RecordNumber& n : StabilityNumbers()) Put(out, n.Of(r));
    Put(out, r.solver_steps);
    Put<uint64_t>(out, r.soil_parameters.size());
    for (const auto& [name, value] : r.soil_parameters) {
      PutString(out, name);
      Put(out, value);
    }
    Put<uint64_t>(out, r.trace.size());
    out.append(reinterpret_cast<const char*>(r.trace.data()), r.trace.size() * sizeof(pad::DropSample));
  }
  return out;
}

std::vector<DropRecord> DeserializeRecords(const std::string& bytes) {
  Reader in{bytes};
  std::vector<DropRecord> records(in.Get<uint64_t>());
  for (DropRecord& r : records) {
    r.index = in.Get<int64_t>();
    r.drop_id = in.GetString();
    r.ok = in.Get<uint8_t>() != 0;
    std::string kind, atmosphere;
    for (std::string* s : {&r.failure, &kind, &r.pad, &r.soil, &atmosphere}) *s = in.GetString();
    r.kind = ParseDropKind(kind, "drop " + r.drop_id);
    r.atmosphere = ParseRecordAtmosphere(atmosphere, "drop " + r.drop_id);
    for (const RecordNumber& n : RigNumbers()) n.at(r) = in.Get<double>();
    for (const RecordNumber& n : FreeAndLanderNumbers()) n.at(r) = in.Get<double>();
    for (std::string* t : DropRecordTexts(r)) *t = in.GetString();
    r.failure_limit = in.GetString();
    r.failure_limit_value = in.Get<double>();
    for (const RecordNumber& n : StabilityNumbers()) n.at(r) = in.Get<double>();
    r.solver_steps = in.Get<int64_t>();
    r.soil_parameters.resize(in.Get<uint64_t>());
    for (auto& [name, value] : r.soil_parameters) {
      name = in.GetString();
      value = in.Get<double>();
    }
    r.trace.resize(in.Get<uint64_t>());
    for (pad::DropSample& s : r.trace) s = in.Get<pad::DropSample>();
  }
  return records;
}

}  // namespace touchdown::sweep

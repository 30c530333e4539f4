#pragma once
// The SQLite database of a sweep (DIR/results.sqlite): one row per drop with all its
// parameters and summary metrics, plus optional traces, written in transactions.
//
//   meta(key, value)   sweep name, digest of the plan, total drops, shard, format version
//   drops(drop_index PRIMARY KEY, drop_id, status 'ok'|'failed', failure, pad, soil,
//         atmosphere, impact_speed_m_s, pad_mass_kg, gravity_m_s2, tilt_deg,
//         horizontal_speed_m_s, zeta_N_cm3, final_penetration_m, peak_force_N,
//         time_to_rest_s, max_deceleration_m_s2, impact_energy_J, gravity_work_J,
//         dissipated_energy_J, mean_conversion_rate_W, rest_creep_m, solver_steps,
//         drop_kind 'rig'|'free'|'lander', final_tilt_deg, horizontal_travel_m,
//         roll_deg, pitch_deg, pad1..pad4_final_penetration_m, final_roll_deg,
//         final_pitch_deg, tipped_over, pad1_soil..pad4_soil, ground_case,
//         failure_limit, failure_limit_value,
//         max_tilt_deg, peak_leg_force_N, max_stroke_m, pad1..pad4_peak_force_N,
//         slope_deg, downhill_azimuth_deg, yaw_relative_to_slope_deg, horizontal_azimuth_deg,
//         angular_rate_x_deg_s, angular_rate_y_deg_s, angular_rate_z_deg_s,
//         max_joint_swing_deg, tip_over_edge, tip_over_azimuth_deg, min_stability_margin_m)
//   traces(drop_index PRIMARY KEY, samples, data BLOB of float64 [t, d, v, F] per sample)
//   soil_parameters(drop_index, position, name, value; PRIMARY KEY (drop_index, position))
//                      a stability study's drawn soil parameters per landing, in the draws'
//                      order; the table exists only in databases of studies that draw them
//
// A batch of drops and their traces go in one transaction (WAL journal), so a process killed
// at any moment leaves every drop either fully written or absent; a restart computes only the
// absent ones. Doubles are stored as 8-byte IEEE values, so rows compare bit for bit.
#include <array>
#include <cstdint>
#include <limits>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "rft/atmosphere.h"
#include "rft/enum_names.h"
#include "lander/pad/rig_drop.h"

struct sqlite3;

namespace touchdown::sweep {

// The database format written, in meta's format_version. It goes up by one whenever columns are
// added; they are added at the end of the table (results_db.cpp, AddedColumns), so that a database
// of an older format can still be read: opening it adds the missing columns, NULL or ''. `sweep`
// resumes only a database of this format. Which columns each format added: docs/reference.md,
// "Sweep results".
inline constexpr int kResultsDbVersion = 8;

// What was dropped: the pad on the vertical rod, the free 6-DOF pad, or the four-legged lander.
// The database keeps it as text (drop_kind 'rig'|'free'|'lander'), converted where it is read
// and written.
enum class DropKind { kRig, kFree, kLander };
inline constexpr std::array<EnumName<DropKind>, 3> kDropKindNames{
    {{DropKind::kRig, "rig"}, {DropKind::kFree, "free"}, {DropKind::kLander, "lander"}}};
const char* DropKindName(DropKind kind);
// Throws InputError naming `where` on a text that is no drop kind.
DropKind ParseDropKind(const std::string& text, const std::string& where);
// The atmosphere a stored record names; InputError naming `where` for any other text.
rft::Atmosphere ParseRecordAtmosphere(const std::string& text, const std::string& where);

// One drop as stored. Metrics are NaN (NULL in SQL) for a failed drop, and for quantities a kind
// of drop does not have.
struct DropRecord {
  int64_t index = 0;
  std::string drop_id;
  bool ok = false;
  std::string failure;  // the reason, for a failed drop
  // A drop that failed because a work limit ran out (integ::LimitExceeded): which one
  // ("max_rhs_evaluations" or "max_wall_time_s") and its value; "" and NaN otherwise.
  std::string failure_limit;
  double failure_limit_value = std::numeric_limits<double>::quiet_NaN();
  DropKind kind = DropKind::kRig;
  std::string pad, soil;
  rft::Atmosphere atmosphere = rft::Atmosphere::kVacuum;  // its name in the database and exports
  double impact_speed_m_s = 0.0, pad_mass_kg = 0.0, gravity_m_s2 = 0.0;
  double tilt_deg = 0.0, horizontal_speed_m_s = 0.0;
  double zeta_N_cm3 = 0.0;  // as used, at the drop's gravity
  double final_penetration_m = 0.0, peak_force_N = 0.0, time_to_rest_s = 0.0, max_deceleration_m_s2 = 0.0;
  double impact_energy_J = 0.0, gravity_work_J = 0.0, dissipated_energy_J = 0.0, mean_conversion_rate_W = 0.0;
  double rest_creep_m = 0.0;
  int64_t solver_steps = 0;
  // Pad (rig: 0, 0) or lander body: tilt from the vertical at rest, horizontal travel of the
  // centre of mass from touchdown to rest (lander: to the end of the run).
  double final_tilt_deg = 0.0, horizontal_travel_m = 0.0;
  // Lander drops only (NaN otherwise): the initial attitude (aerospace roll and pitch), each pad's
  // final penetration (pads clockwise from above, pad 1 front-left), the final attitude, and
  // whether it tipped over (1) or not (0).
  double roll_deg = std::numeric_limits<double>::quiet_NaN(), pitch_deg = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 4> pad_final_penetration_m{std::numeric_limits<double>::quiet_NaN(),
                                                std::numeric_limits<double>::quiet_NaN(),
                                                std::numeric_limits<double>::quiet_NaN(),
                                                std::numeric_limits<double>::quiet_NaN()};
  double final_roll_deg = std::numeric_limits<double>::quiet_NaN();
  double final_pitch_deg = std::numeric_limits<double>::quiet_NaN();
  double tipped_over = std::numeric_limits<double>::quiet_NaN();
  // Lander drops only ("" otherwise): the soil under each pad's ball joint at release (soil names,
  // pads clockwise from pad 1 front-left) and the paper's Table II ground case they make ("A",
  // "B", "C"; "" for another combination).
  std::array<std::string, 4> pad_soil;
  std::string ground_case;
  // Lander drops only (NaN otherwise). Over the run: the largest tilt of the body from
  // the vertical, the peak axial leg load (compression positive; an absorber leg's absorber force,
  // a rigid leg's soil force on its pad along the leg axis, hip to joint, the pad's inertia
  // neglected; at the trace's samples), the largest absorber stroke (NaN without absorbers), each
  // pad's peak soil force. The conditions: ground slope, its downhill azimuth (from world +x
  // towards +y), body x from the downhill direction, the horizontal velocity's azimuth (world),
  // the body-axis angular rates at release.
  double max_tilt_deg = std::numeric_limits<double>::quiet_NaN();
  // The largest swing of any pad on its ball joint, its axis from the body's z axis (lander::
  // LanderRunResult::max_joint_swing_rad); past 90 deg a pad turned beyond edge-on.
  double max_joint_swing_deg = std::numeric_limits<double>::quiet_NaN();
  // Landers that tipped over (NaN otherwise): the support edge they went over, from pad
  // tip_over_edge to the next one clockwise (1-4: 1 is the edge of pads 1 and 2), and the azimuth of
  // that edge's outward horizontal normal, the direction the lander fell (world, as
  // horizontal_azimuth_deg) (lander::LanderRunResult::tip_over_edge, tip_over_azimuth_rad).
  double tip_over_edge = std::numeric_limits<double>::quiet_NaN();
  double tip_over_azimuth_deg = std::numeric_limits<double>::quiet_NaN();
  // Landers only (NaN otherwise): the least distance of the centre of mass inside the support
  // polygon over the run (lander::LanderRunResult::min_stability_margin_m), <= 0 exactly when it
  // tipped over.
  double min_stability_margin_m = std::numeric_limits<double>::quiet_NaN();
  double peak_leg_force_N = std::numeric_limits<double>::quiet_NaN();
  double max_stroke_m = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 4> pad_peak_force_N{std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN()};
  double slope_deg = std::numeric_limits<double>::quiet_NaN();
  double downhill_azimuth_deg = std::numeric_limits<double>::quiet_NaN();
  double yaw_relative_to_slope_deg = std::numeric_limits<double>::quiet_NaN();
  double horizontal_azimuth_deg = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> angular_rate_deg_s{std::numeric_limits<double>::quiet_NaN(),
                                           std::numeric_limits<double>::quiet_NaN(),
                                           std::numeric_limits<double>::quiet_NaN()};
  std::vector<pad::DropSample> trace;  // empty unless stored
  // A stability study's drawn soil parameters for this landing (column name, value in the
  // column's unit), in the draws' order (drop_tests/stability/soil_uncertainty.h); empty otherwise.
  std::vector<std::pair<std::string, double>> soil_parameters;
};

// A number a record keeps, as a column: its name (with its unit suffix) beside where the record
// keeps it. A group's table drives the database's schema, binding and reading, SameRecord and the MPI
// serialisation; the exports' number columns and a rig drop's metrics (drop_tests/drop/drop_columns.h)
// find their column here by name, so a name and its field cannot drift apart.
struct RecordNumber {
  const char* name;
  double& (*at)(DropRecord&);
  double Of(const DropRecord& r) const { return at(const_cast<DropRecord&>(r)); }  // reads only
};
// The record's text fields after its numbers (the soil under each lander pad, the ground case),
// in table order: the database's and the byte serialisation's one list of them.
template <typename R>
auto DropRecordTexts(R& r) {
  return std::array{&r.pad_soil[0], &r.pad_soil[1], &r.pad_soil[2], &r.pad_soil[3], &r.ground_case};
}
// The drops table's numbers in groups, in table order. A drop's conditions and the rig drop's
// metrics (impact_speed_m_s .. rest_creep_m; the metrics are drop::RigMetrics(), by name):
const std::vector<RecordNumber>& RigNumbers();
// The free pad's and the lander's (final_tilt_deg .. tipped_over):
const std::vector<RecordNumber>& FreeAndLanderNumbers();
// The lander's stability metrics and conditions, the joints' swing and the tip-over edge: the last
// column group of the drops table, and of lander_drops.csv.
const std::vector<RecordNumber>& StabilityNumbers();
// The number of any group by its column name, for outputs that pick a record's columns by name
// (exports, a single drop's metrics). A name no group holds is a bug: std::logic_error.
const RecordNumber& RecordNumberNamed(const std::string& name);

// Bitwise equality of every field (NaN equals NaN of the same bits).
bool SameRecord(const DropRecord& a, const DropRecord& b, bool compare_traces = true);

// Byte serialisation of records, for sending between MPI ranks.
std::string SerializeRecords(const std::vector<DropRecord>& records);
std::vector<DropRecord> DeserializeRecords(const std::string& bytes);

class ResultsDb {
 public:
  // kReadWrite: a sweep's own database, created if needed and brought up to this format.
  // kReadOnly: a reader's (export, merge's shards): nothing is written (PRAGMA query_only; opened
  // SQLITE_OPEN_READONLY where the file or its directory may not be written), so results on
  // read-only storage can be read; an older format reads with the newer columns NULL or ''.
  enum class Access { kReadWrite, kReadOnly };
  // Opens the database file. Throws InputError when SQLite cannot use it, std::runtime_error on
  // other SQLite errors.
  explicit ResultsDb(const std::string& path, Access access = Access::kReadWrite);
  ~ResultsDb();
  ResultsDb(const ResultsDb&) = delete;
  ResultsDb& operator=(const ResultsDb&) = delete;

  const std::string& path() const { return path_; }
  std::map<std::string, std::string> Meta() const;
  // Writes the meta rows in one transaction (only keys given; others kept).
  void SetMeta(const std::map<std::string, std::string>& meta);
  // Inserts the records (and their traces) in one transaction. An index already present
  // must hold an identical record (a merge of overlapping shards); otherwise it throws.
  void Insert(const std::vector<DropRecord>& records);
  int64_t Count() const;
  int64_t CountFailed() const;
  // Stored drops with index < total.
  int64_t CountBelow(int64_t total) const;
  // Stored drop indices in [begin, end), ascending (a range scan of the primary key).
  std::vector<int64_t> StoredIndices(int64_t begin, int64_t end) const;
  // Removes, in one transaction, the failed drops that ran out of a work limit lower than the
  // one given now (0: no limit, so every drop that ran out of that kind of limit), so that they
  // are computed again; returns how many.
  int64_t ForgetDropsBelowLimits(long max_rhs_evaluations, double max_wall_time_s);
  // Every record in index order; traces when asked.
  void ForEach(const std::function<void(const DropRecord&)>& visit, bool with_traces) const;
  std::vector<DropRecord> ReadAll(bool with_traces) const;
  // At most `limit` records with index >= `from`, in index order: read a database page by page
  // in bounded memory (next page: from the last index + 1).
  std::vector<DropRecord> ReadPage(int64_t from, size_t limit, bool with_traces) const;

 private:
  void Exec(const std::string& sql) const;
  void CreateTables();  // the schema, created or brought up to date (older formats gain their columns)
  void AdaptTables();   // read-only: TEMP stand-ins for the tables and columns an older file lacks
  bool HasSoilParameters() const;  // whether the file has the soil_parameters table
  void ReadSoilParameters(DropRecord& r) const;
  std::string path_;
  sqlite3* db_ = nullptr;
};

// The database file of a sweep output directory.
std::string ResultsDbPath(const std::string& out_dir);

}  // namespace touchdown::sweep

#include "drop_tests/results_db.h"

#include <sqlite3.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace touchdown::drop {

namespace {
// The drops columns after drop_index, in the order of the INSERT statement.
constexpr const char* kColumns =
    "drop_id, status, failure, pad, soil, atmosphere, impact_speed_m_s, pad_mass_kg, gravity_m_s2, tilt_deg, "
    "horizontal_speed_m_s, zeta_N_cm3, final_penetration_m, peak_force_N, time_to_rest_s, max_deceleration_m_s2, "
    "impact_energy_J, gravity_work_J, dissipated_energy_J, mean_conversion_rate_W, rest_creep_m, solver_steps";

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s_, nullptr) != SQLITE_OK)
      throw std::runtime_error(std::string("sqlite prepare: ") + sqlite3_errmsg(db) + " in: " + sql);
  }
  ~Statement() { sqlite3_finalize(s_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  sqlite3_stmt* get() { return s_; }
  void Reset() {
    sqlite3_reset(s_);
    sqlite3_clear_bindings(s_);
  }
  void Text(int i, const std::string& v) { sqlite3_bind_text(s_, i, v.c_str(), static_cast<int>(v.size()), SQLITE_TRANSIENT); }
  void Real(int i, double v) {
    if (std::isnan(v)) sqlite3_bind_null(s_, i);
    else sqlite3_bind_double(s_, i, v);
  }
  void Int(int i, int64_t v) { sqlite3_bind_int64(s_, i, v); }
  int Step() { return sqlite3_step(s_); }
  std::string ColumnText(int i) {
    const unsigned char* t = sqlite3_column_text(s_, i);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  double ColumnReal(int i) {
    return sqlite3_column_type(s_, i) == SQLITE_NULL ? std::nan("") : sqlite3_column_double(s_, i);
  }

 private:
  sqlite3* db_;
  sqlite3_stmt* s_ = nullptr;
};

void BindRecord(Statement& st, const DropRecord& r) {
  int i = 1;
  st.Int(i++, r.index);
  st.Text(i++, r.drop_id);
  st.Text(i++, r.ok ? "ok" : "failed");
  st.Text(i++, r.failure);
  st.Text(i++, r.pad);
  st.Text(i++, r.soil);
  st.Text(i++, r.atmosphere);
  for (double v : {r.impact_speed_m_s, r.pad_mass_kg, r.gravity_m_s2, r.tilt_deg, r.horizontal_speed_m_s, r.zeta_N_cm3,
                   r.final_penetration_m, r.peak_force_N, r.time_to_rest_s, r.max_deceleration_m_s2, r.impact_energy_J,
                   r.gravity_work_J, r.dissipated_energy_J, r.mean_conversion_rate_W, r.rest_creep_m})
    st.Real(i++, v);
  st.Int(i++, r.solver_steps);
}

DropRecord ReadRecord(Statement& st) {
  DropRecord r;
  int i = 0;
  r.index = sqlite3_column_int64(st.get(), i++);
  r.drop_id = st.ColumnText(i++);
  r.ok = st.ColumnText(i++) == "ok";
  r.failure = st.ColumnText(i++);
  r.pad = st.ColumnText(i++);
  r.soil = st.ColumnText(i++);
  r.atmosphere = st.ColumnText(i++);
  for (double* v : {&r.impact_speed_m_s, &r.pad_mass_kg, &r.gravity_m_s2, &r.tilt_deg, &r.horizontal_speed_m_s,
                    &r.zeta_N_cm3, &r.final_penetration_m, &r.peak_force_N, &r.time_to_rest_s,
                    &r.max_deceleration_m_s2, &r.impact_energy_J, &r.gravity_work_J, &r.dissipated_energy_J,
                    &r.mean_conversion_rate_W, &r.rest_creep_m})
    *v = st.ColumnReal(i++);
  r.solver_steps = sqlite3_column_int64(st.get(), i++);
  return r;
}

std::vector<DropSample> ReadTraceBlob(Statement& st, int column) {
  const int bytes = sqlite3_column_bytes(st.get(), column);
  std::vector<DropSample> trace(static_cast<size_t>(bytes) / sizeof(DropSample));
  if (!trace.empty()) std::memcpy(trace.data(), sqlite3_column_blob(st.get(), column), trace.size() * sizeof(DropSample));
  return trace;
}

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
static_assert(sizeof(DropSample) == 4 * sizeof(double), "traces are stored as 4 doubles per sample");
}  // namespace

bool SameRecord(const DropRecord& a, const DropRecord& b, bool compare_traces) {
  const double da[] = {a.impact_speed_m_s, a.pad_mass_kg, a.gravity_m_s2, a.tilt_deg, a.horizontal_speed_m_s,
                       a.zeta_N_cm3, a.final_penetration_m, a.peak_force_N, a.time_to_rest_s, a.max_deceleration_m_s2,
                       a.impact_energy_J, a.gravity_work_J, a.dissipated_energy_J, a.mean_conversion_rate_W,
                       a.rest_creep_m};
  const double db[] = {b.impact_speed_m_s, b.pad_mass_kg, b.gravity_m_s2, b.tilt_deg, b.horizontal_speed_m_s,
                       b.zeta_N_cm3, b.final_penetration_m, b.peak_force_N, b.time_to_rest_s, b.max_deceleration_m_s2,
                       b.impact_energy_J, b.gravity_work_J, b.dissipated_energy_J, b.mean_conversion_rate_W,
                       b.rest_creep_m};
  for (size_t i = 0; i < std::size(da); ++i)
    if (!SameBits(da[i], db[i])) return false;
  if (a.index != b.index || a.drop_id != b.drop_id || a.ok != b.ok || a.failure != b.failure || a.pad != b.pad ||
      a.soil != b.soil || a.atmosphere != b.atmosphere || a.solver_steps != b.solver_steps)
    return false;
  if (!compare_traces) return true;
  return a.trace.size() == b.trace.size() &&
         (a.trace.empty() || std::memcmp(a.trace.data(), b.trace.data(), a.trace.size() * sizeof(DropSample)) == 0);
}

std::string SerializeRecords(const std::vector<DropRecord>& records) {
  std::string out;
  Put<uint64_t>(out, records.size());
  for (const DropRecord& r : records) {
    Put(out, r.index);
    PutString(out, r.drop_id);
    Put<uint8_t>(out, r.ok ? 1 : 0);
    for (const std::string* s : {&r.failure, &r.pad, &r.soil, &r.atmosphere}) PutString(out, *s);
    for (double v : {r.impact_speed_m_s, r.pad_mass_kg, r.gravity_m_s2, r.tilt_deg, r.horizontal_speed_m_s,
                     r.zeta_N_cm3, r.final_penetration_m, r.peak_force_N, r.time_to_rest_s, r.max_deceleration_m_s2,
                     r.impact_energy_J, r.gravity_work_J, r.dissipated_energy_J, r.mean_conversion_rate_W,
                     r.rest_creep_m})
      Put(out, v);
    Put(out, r.solver_steps);
    Put<uint64_t>(out, r.trace.size());
    out.append(reinterpret_cast<const char*>(r.trace.data()), r.trace.size() * sizeof(DropSample));
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
    for (std::string* s : {&r.failure, &r.pad, &r.soil, &r.atmosphere}) *s = in.GetString();
    for (double* v : {&r.impact_speed_m_s, &r.pad_mass_kg, &r.gravity_m_s2, &r.tilt_deg, &r.horizontal_speed_m_s,
                      &r.zeta_N_cm3, &r.final_penetration_m, &r.peak_force_N, &r.time_to_rest_s,
                      &r.max_deceleration_m_s2, &r.impact_energy_J, &r.gravity_work_J, &r.dissipated_energy_J,
                      &r.mean_conversion_rate_W, &r.rest_creep_m})
      *v = in.Get<double>();
    r.solver_steps = in.Get<int64_t>();
    r.trace.resize(in.Get<uint64_t>());
    for (DropSample& s : r.trace) s = in.Get<DropSample>();
  }
  return records;
}

std::string ResultsDbPath(const std::string& out_dir) {
  return (std::filesystem::path(out_dir) / "results.sqlite").string();
}

ResultsDb::ResultsDb(const std::string& path) : path_(path) {
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr) !=
      SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw std::runtime_error("cannot open " + path + ": " + message);
  }
  sqlite3_busy_timeout(db_, 10000);
  // WAL + synchronous=NORMAL: a committed transaction survives the process being killed
  // (only an OS crash may lose the last ones, never half of one).
  Exec("PRAGMA journal_mode=WAL");
  Exec("PRAGMA synchronous=NORMAL");
  Exec(std::string("CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
                   "CREATE TABLE IF NOT EXISTS drops(drop_index INTEGER PRIMARY KEY, drop_id TEXT NOT NULL, "
                   "status TEXT NOT NULL, failure TEXT NOT NULL, pad TEXT NOT NULL, soil TEXT NOT NULL, "
                   "atmosphere TEXT NOT NULL, impact_speed_m_s REAL, pad_mass_kg REAL, gravity_m_s2 REAL, "
                   "tilt_deg REAL, horizontal_speed_m_s REAL, zeta_N_cm3 REAL, final_penetration_m REAL, "
                   "peak_force_N REAL, time_to_rest_s REAL, max_deceleration_m_s2 REAL, impact_energy_J REAL, "
                   "gravity_work_J REAL, dissipated_energy_J REAL, mean_conversion_rate_W REAL, rest_creep_m REAL, "
                   "solver_steps INTEGER);"
                   "CREATE TABLE IF NOT EXISTS traces(drop_index INTEGER PRIMARY KEY, samples INTEGER NOT NULL, "
                   "data BLOB NOT NULL);"));
}

ResultsDb::~ResultsDb() { sqlite3_close(db_); }

void ResultsDb::Exec(const std::string& sql) const {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw std::runtime_error("sqlite (" + path_ + "): " + message);
  }
}

std::map<std::string, std::string> ResultsDb::Meta() const {
  Statement st(db_, "SELECT key, value FROM meta");
  std::map<std::string, std::string> meta;
  while (st.Step() == SQLITE_ROW) meta[st.ColumnText(0)] = st.ColumnText(1);
  return meta;
}

void ResultsDb::SetMeta(const std::map<std::string, std::string>& meta) {
  Exec("BEGIN IMMEDIATE");
  try {
    Statement st(db_, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
    for (const auto& [k, v] : meta) {
      st.Reset();
      st.Text(1, k);
      st.Text(2, v);
      if (st.Step() != SQLITE_DONE) throw std::runtime_error(std::string("sqlite meta: ") + sqlite3_errmsg(db_));
    }
    Exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

void ResultsDb::Insert(const std::vector<DropRecord>& records) {
  if (records.empty()) return;
  Exec("BEGIN IMMEDIATE");
  try {
    Statement drop(db_, std::string("INSERT INTO drops(drop_index, ") + kColumns +
                            ") VALUES(?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
    Statement trace(db_, "INSERT INTO traces(drop_index, samples, data) VALUES(?,?,?)");
    for (const DropRecord& r : records) {
      drop.Reset();
      BindRecord(drop, r);
      const int rc = drop.Step();
      if (rc == SQLITE_CONSTRAINT) {  // already stored: must be the same drop, bit for bit
        Statement old(db_, std::string("SELECT drop_index, ") + kColumns + " FROM drops WHERE drop_index = ?");
        old.Int(1, r.index);
        if (old.Step() != SQLITE_ROW || !SameRecord(ReadRecord(old), r, false))
          throw std::runtime_error(path_ + ": drop " + r.drop_id + " is already stored with different results");
        continue;
      }
      if (rc != SQLITE_DONE) throw std::runtime_error(std::string("sqlite insert: ") + sqlite3_errmsg(db_));
      if (!r.trace.empty()) {
        trace.Reset();
        trace.Int(1, r.index);
        trace.Int(2, static_cast<int64_t>(r.trace.size()));
        sqlite3_bind_blob(trace.get(), 3, r.trace.data(), static_cast<int>(r.trace.size() * sizeof(DropSample)),
                          SQLITE_STATIC);
        if (trace.Step() != SQLITE_DONE) throw std::runtime_error(std::string("sqlite trace: ") + sqlite3_errmsg(db_));
      }
    }
    Exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

int64_t ResultsDb::Count() const {
  Statement st(db_, "SELECT COUNT(*) FROM drops");
  st.Step();
  return sqlite3_column_int64(st.get(), 0);
}

int64_t ResultsDb::CountFailed() const {
  Statement st(db_, "SELECT COUNT(*) FROM drops WHERE status != 'ok'");
  st.Step();
  return sqlite3_column_int64(st.get(), 0);
}

std::vector<uint8_t> ResultsDb::DoneMask(int64_t total) const {
  std::vector<uint8_t> done(static_cast<size_t>(total), 0);
  Statement st(db_, "SELECT drop_index FROM drops");
  while (st.Step() == SQLITE_ROW) {
    const int64_t i = sqlite3_column_int64(st.get(), 0);
    if (i >= 0 && i < total) done[static_cast<size_t>(i)] = 1;
  }
  return done;
}

void ResultsDb::ForEach(const std::function<void(const DropRecord&)>& visit, bool with_traces) const {
  const int n_columns = 23;
  Statement st(db_, std::string("SELECT d.drop_index, ") + kColumns +
                        (with_traces ? ", t.data FROM drops d LEFT JOIN traces t ON t.drop_index = d.drop_index"
                                     : " FROM drops d") +
                        " ORDER BY d.drop_index");
  int rc;
  while ((rc = st.Step()) == SQLITE_ROW) {
    DropRecord r = ReadRecord(st);
    if (with_traces && sqlite3_column_type(st.get(), n_columns) != SQLITE_NULL) r.trace = ReadTraceBlob(st, n_columns);
    visit(r);
  }
  if (rc != SQLITE_DONE) throw std::runtime_error(std::string("sqlite read: ") + sqlite3_errmsg(db_));
}

std::vector<DropRecord> ResultsDb::ReadAll(bool with_traces) const {
  std::vector<DropRecord> out;
  ForEach([&](const DropRecord& r) { out.push_back(r); }, with_traces);
  return out;
}

}  // namespace touchdown::drop

#include "drop_tests/sweep/results_db.h"

#include <sqlite3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <unistd.h>

#include "drop_tests/catalog/paths_in_outputs.h"
#include "rft/input_error.h"

namespace touchdown::sweep {

namespace {
// Meta values that name files (the sweep file, the model): stored relative to the database's
// directory, or under $TOUCHDOWN_DATA_DIR, never as this machine's absolute path
// (drop_tests/catalog/paths_in_outputs.h); Meta() gives them back as the working directory reaches them.
constexpr const char* kMetaPathKeys[] = {"source", "model"};
std::string Directory(const std::string& file) { return std::filesystem::path(file).parent_path().string(); }
// The database file itself unusable (missing, unreadable, not a database, corrupt, disk full,
// read-only, locked): the user's to fix, so an InputError naming the file and SQLite's reason
// (exit 2). Any other SQLite error (a malformed statement) is a bug.
[[noreturn]] void ThrowSqlite(sqlite3* db, int rc, const std::string& what) {
  const char* file = db ? sqlite3_db_filename(db, "main") : nullptr;
  const std::string path = file && *file ? file : "results database";
  const std::string reason = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
  switch (rc & 0xff) {
    case SQLITE_CANTOPEN: case SQLITE_NOTADB: case SQLITE_CORRUPT: case SQLITE_IOERR: case SQLITE_FULL:
    case SQLITE_READONLY: case SQLITE_PERM: case SQLITE_AUTH: case SQLITE_BUSY: case SQLITE_LOCKED:
    case SQLITE_NOLFS: case SQLITE_NOMEM:
      throw MakeInputError(path, "", "SQLite cannot use this database: " + reason);
    default:
      throw std::runtime_error("sqlite " + what + " (" + path + "): " + reason);
  }
}

// The soil under each lander pad and the ground case: text columns after the numbers.
constexpr const char* kTextColumns3[] = {"pad1_soil", "pad2_soil", "pad3_soil", "pad4_soil", "ground_case"};
constexpr size_t kTexts3 = std::size(kTextColumns3);
// The work limit a failed drop ran out of, so a rerun with a higher limit retries it.
constexpr const char* kLimitColumn = "failure_limit";
constexpr const char* kLimitValueColumn = "failure_limit_value";

static_assert(std::tuple_size_v<decltype(DropRecordTexts(std::declval<DropRecord&>()))> == kTexts3);

// The drops columns after drop_index, in the order of the INSERT statement.
std::string Columns() {
  std::string c = "drop_id, status, failure, pad, soil, atmosphere";
  for (const RecordNumber& n : RigNumbers()) c += std::string(", ") + n.name;
  c += ", solver_steps, drop_kind";
  for (const RecordNumber& n : FreeAndLanderNumbers()) c += std::string(", ") + n.name;
  for (const char* n : kTextColumns3) c += std::string(", ") + n;
  c += std::string(", ") + kLimitColumn + ", " + kLimitValueColumn;
  for (const RecordNumber& n : StabilityNumbers()) c += std::string(", ") + n.name;
  return c;
}
// The drops columns after drop_index.
int ColumnCount() {
  return 6 + static_cast<int>(RigNumbers().size()) + 2 + static_cast<int>(FreeAndLanderNumbers().size()) +
         static_cast<int>(kTexts3) + 2 + static_cast<int>(StabilityNumbers().size());
}

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) {
    if (const int rc = sqlite3_prepare_v2(db, sql.c_str(), -1, &s_, nullptr); rc != SQLITE_OK)
      ThrowSqlite(db, rc, "prepare of '" + sql + "'");
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
  st.Text(i++, rft::AtmosphereName(r.atmosphere));
  for (const RecordNumber& n : RigNumbers()) st.Real(i++, n.Of(r));
  st.Int(i++, r.solver_steps);
  st.Text(i++, DropKindName(r.kind));
  for (const RecordNumber& n : FreeAndLanderNumbers()) st.Real(i++, n.Of(r));
  for (const std::string* t : DropRecordTexts(r)) st.Text(i++, *t);
  st.Text(i++, r.failure_limit);
  st.Real(i++, r.failure_limit_value);
  for (const RecordNumber& n : StabilityNumbers()) st.Real(i++, n.Of(r));
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
  const std::string atmosphere = st.ColumnText(i++);
  for (const RecordNumber& n : RigNumbers()) n.at(r) = st.ColumnReal(i++);
  r.solver_steps = sqlite3_column_int64(st.get(), i++);
  const std::string kind = st.ColumnText(i++);
  // A format-1 row read through the added columns has none: a rig drop.
  r.kind = kind.empty() ? DropKind::kRig : ParseDropKind(kind, "drop " + r.drop_id);
  r.atmosphere = ParseRecordAtmosphere(atmosphere, "drop " + r.drop_id);
  for (const RecordNumber& n : FreeAndLanderNumbers()) n.at(r) = st.ColumnReal(i++);
  for (std::string* t : DropRecordTexts(r)) *t = st.ColumnText(i++);
  r.failure_limit = st.ColumnText(i++);
  r.failure_limit_value = st.ColumnReal(i++);
  for (const RecordNumber& n : StabilityNumbers()) n.at(r) = st.ColumnReal(i++);
  return r;
}

std::vector<pad::DropSample> ReadTraceBlob(Statement& st, int column) {
  const int bytes = sqlite3_column_bytes(st.get(), column);
  std::vector<pad::DropSample> trace(static_cast<size_t>(bytes) / sizeof(pad::DropSample));
  if (!trace.empty()) std::memcpy(trace.data(), sqlite3_column_blob(st.get(), column), trace.size() * sizeof(pad::DropSample));
  return trace;
}

}  // namespace

std::string ResultsDbPath(const std::string& out_dir) {
  return (std::filesystem::path(out_dir) / "results.sqlite").string();
}

namespace {
// The CREATE statements of the three tables, for the file (`kind` "TABLE IF NOT EXISTS") or as a
// reader's TEMP stand-ins ("TEMP TABLE").
std::string MetaTableSql(const std::string& kind) {
  return "CREATE " + kind + " meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)";
}
std::string SoilParametersTableSql(const std::string& kind) {
  return "CREATE " + kind + " soil_parameters(drop_index INTEGER NOT NULL, position INTEGER NOT NULL, "
         "name TEXT NOT NULL, value REAL NOT NULL, PRIMARY KEY (drop_index, position))";
}
std::string TracesTableSql(const std::string& kind) {
  return "CREATE " + kind + " traces(drop_index INTEGER PRIMARY KEY, samples INTEGER NOT NULL, data BLOB NOT NULL)";
}
// The drops columns after the format-1 ones, each with its type and default: what an older
// database gains (ALTER TABLE ... ADD COLUMN) or a reader of one sees in its place.
struct AddedColumn {
  std::string name, declaration, value_when_absent;
};
std::vector<AddedColumn> AddedColumns() {
  std::vector<AddedColumn> c{{"drop_kind", "TEXT NOT NULL DEFAULT 'rig'", "'rig'"}};
  for (const RecordNumber& n : FreeAndLanderNumbers()) c.push_back({n.name, "REAL", "NULL"});
  for (const char* n : kTextColumns3) c.push_back({n, "TEXT NOT NULL DEFAULT ''", "''"});
  c.push_back({kLimitColumn, "TEXT NOT NULL DEFAULT ''", "''"});
  c.push_back({kLimitValueColumn, "REAL", "NULL"});
  for (const RecordNumber& n : StabilityNumbers()) c.push_back({n.name, "REAL", "NULL"});
  return c;
}
std::string DropsTableSql(const std::string& kind) {
  std::string drops = "CREATE " + kind + " drops(drop_index INTEGER PRIMARY KEY, drop_id TEXT NOT NULL, "
                      "status TEXT NOT NULL, failure TEXT NOT NULL, pad TEXT NOT NULL, soil TEXT NOT NULL, "
                      "atmosphere TEXT NOT NULL";
  for (const RecordNumber& n : RigNumbers()) drops += std::string(", ") + n.name + " REAL";
  drops += ", solver_steps INTEGER";
  for (const AddedColumn& c : AddedColumns()) drops += ", " + c.name + " " + c.declaration;
  return drops + ")";
}

// A percent-encoded file: URI (RFC 8089, as sqlite3_open_v2 reads it with SQLITE_OPEN_URI).
std::string FileUri(const std::string& path, const std::string& query) {
  static const char* hex = "0123456789ABCDEF";
  std::string uri = "file:";
  for (size_t i = 0; i < path.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(path[i]);
    // '/' as it is, except a second leading one (file:// starts an authority).
    const bool plain = std::isalnum(c) || std::strchr("-._~", c) || (c == '/' && i != 1);
    if (c != 0 && plain) uri += static_cast<char>(c);
    else uri += {'%', hex[c >> 4], hex[c & 15]};
  }
  return uri + "?" + query;
}

// How a reader opens the file: read-write where this process may write the file and its directory
// (query_only then keeps the reader from writing; SQLite's -wal and -shm files come and go as for
// any connection, the last to close removing them), else read-only storage: SQLITE_OPEN_READONLY. There
// SQLite reads a WAL database through a -shm index it must create beside the file; where it
// cannot (the directory not writable) and no -wal file holds commits, the file alone is the whole
// database and is opened immutable (no -shm, no locks; nobody can write there either).
struct ReaderOpen {
  std::string uri;
  int flags;
};
ReaderOpen HowReaderOpens(const std::string& path) {
  const std::filesystem::path file(path);
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  const bool writable_dir = ::access(dir.c_str(), W_OK) == 0;
  if (writable_dir && ::access(path.c_str(), W_OK) == 0) return {FileUri(path, "mode=rw"), SQLITE_OPEN_READWRITE};
  std::error_code ec;
  const bool wal = std::filesystem::exists(path + "-wal", ec);
  return {FileUri(path, !wal && !writable_dir ? "mode=ro&immutable=1" : "mode=ro"), SQLITE_OPEN_READONLY};
}
}  // namespace

ResultsDb::ResultsDb(const std::string& path, Access access) : path_(path) {
  const bool read_only = access == Access::kReadOnly;
  const ReaderOpen reader = read_only ? HowReaderOpens(path) : ReaderOpen{};
  const std::string& name = read_only ? reader.uri : path;
  const int flags = read_only ? reader.flags | SQLITE_OPEN_URI : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  if (const int rc = sqlite3_open_v2(name.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr); rc != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw MakeInputError(path, "", "SQLite cannot open this database: " + message);
  }
  sqlite3_busy_timeout(db_, 10000);
  try {
    if (read_only) AdaptTables();
    else CreateTables();
  } catch (...) {  // the destructor does not run for a constructor that throws
    sqlite3_close(db_);
    db_ = nullptr;
    throw;
  }
}

void ResultsDb::CreateTables() {
  // WAL + synchronous=NORMAL: a committed transaction survives the process being killed
  // (only an OS crash may lose the last ones, never half of one).
  Exec("PRAGMA journal_mode=WAL");
  Exec("PRAGMA synchronous=NORMAL");
  const std::string kind = "TABLE IF NOT EXISTS";
  Exec(MetaTableSql(kind) + ";" + DropsTableSql(kind) + ";" + TracesTableSql(kind) + ";");
  // A database of an older format lacks the columns added since; they are added, NULL or '', so it
  // can still be read (export, merge); `sweep` refuses to resume it (format_version in meta).
  std::vector<std::string> present;
  {
    Statement info(db_, "PRAGMA table_info(drops)");
    while (info.Step() == SQLITE_ROW) present.push_back(info.ColumnText(1));
  }
  for (const AddedColumn& c : AddedColumns())
    if (std::find(present.begin(), present.end(), c.name) == present.end())
      Exec("ALTER TABLE drops ADD COLUMN " + c.name + " " + c.declaration);
}

void ResultsDb::AdaptTables() {
  // TEMP objects live in the connection's own temporary database, which a read-only connection
  // may write, and an unqualified name finds them before main's: a missing table reads as empty,
  // an older drops table through a view with the newer columns at their defaults.
  std::vector<std::string> tables;
  {
    Statement st(db_, "SELECT name FROM main.sqlite_master WHERE type = 'table'");
    while (st.Step() == SQLITE_ROW) tables.push_back(st.ColumnText(0));
  }
  auto has_table = [&](const char* t) { return std::find(tables.begin(), tables.end(), t) != tables.end(); };
  if (!has_table("meta")) Exec(MetaTableSql("TEMP TABLE"));
  if (!has_table("traces")) Exec(TracesTableSql("TEMP TABLE"));
  if (!has_table("drops")) return Exec(DropsTableSql("TEMP TABLE") + ";PRAGMA query_only=1");
  std::vector<std::string> present;
  {
    Statement info(db_, "PRAGMA main.table_info(drops)");
    while (info.Step() == SQLITE_ROW) present.push_back(info.ColumnText(1));
  }
  std::string view = "CREATE TEMP VIEW drops AS SELECT drop_index, drop_id, status, failure, pad, soil, atmosphere";
  for (const RecordNumber& n : RigNumbers()) view += std::string(", ") + n.name;
  view += ", solver_steps";
  bool complete = true;
  for (const AddedColumn& c : AddedColumns()) {
    const bool has = std::find(present.begin(), present.end(), c.name) != present.end();
    complete = complete && has;
    view += ", " + (has ? c.name : c.value_when_absent + " AS " + c.name);
  }
  if (!complete) Exec(view + " FROM main.drops");
  Exec("PRAGMA query_only=1");  // whichever way the file was opened, this connection writes nothing
}

ResultsDb::~ResultsDb() { sqlite3_close(db_); }

void ResultsDb::Exec(const std::string& sql) const {
  char* error = nullptr;
  if (const int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error); rc != SQLITE_OK) {
    sqlite3_free(error);
    ThrowSqlite(db_, rc, "exec");
  }
}

std::map<std::string, std::string> ResultsDb::Meta() const {
  Statement st(db_, "SELECT key, value FROM meta");
  std::map<std::string, std::string> meta;
  while (st.Step() == SQLITE_ROW) meta[st.ColumnText(0)] = st.ColumnText(1);
  for (const char* key : kMetaPathKeys)
    if (auto it = meta.find(key); it != meta.end()) it->second = io::PathFromOutput(it->second, Directory(path_));
  return meta;
}

void ResultsDb::SetMeta(const std::map<std::string, std::string>& meta) {
  Exec("BEGIN IMMEDIATE");
  try {
    Statement st(db_, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
    for (const auto& [k, v] : meta) {
      st.Reset();
      st.Text(1, k);
      const bool is_path = std::find(std::begin(kMetaPathKeys), std::end(kMetaPathKeys), k) != std::end(kMetaPathKeys);
      st.Text(2, is_path ? io::PathForOutput(v, Directory(path_)) : v);
      if (st.Step() != SQLITE_DONE) throw std::runtime_error(std::string("sqlite meta: ") + sqlite3_errmsg(db_));
      st.Text(2, v);
      if (const int rc = st.Step(); rc != SQLITE_DONE) ThrowSqlite(db_, rc, "meta");
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
    std::string marks = "?";
    for (int i = 0; i < ColumnCount(); ++i) marks += ",?";
    Statement drop(db_, "INSERT INTO drops(drop_index, " + Columns() + ") VALUES(" + marks + ")");
    Statement trace(db_, "INSERT INTO traces(drop_index, samples, data) VALUES(?,?,?)");
    // Created with the first record that has drawn soil parameters: other databases stay as they were.
    bool soil_table = HasSoilParameters();
    for (const DropRecord& r : records) {
      drop.Reset();
      BindRecord(drop, r);
      const int rc = drop.Step();
      if (rc == SQLITE_CONSTRAINT) {  // already stored: must be the same drop, bit for bit
        Statement old(db_, "SELECT drop_index, " + Columns() + " FROM drops WHERE drop_index = ?");
        old.Int(1, r.index);
        DropRecord stored;
        if (old.Step() == SQLITE_ROW) {
          stored = ReadRecord(old);
          ReadSoilParameters(stored);
        }
        if (stored.drop_id.empty() || !SameRecord(stored, r, false))
          throw std::runtime_error(path_ + ": drop " + r.drop_id + " is already stored with different results");
        continue;
      }
      if (rc != SQLITE_DONE) ThrowSqlite(db_, rc, "insert");
      if (!r.soil_parameters.empty()) {
        if (!soil_table) Exec(SoilParametersTableSql("TABLE IF NOT EXISTS"));
        soil_table = true;
        Statement soil(db_, "INSERT INTO soil_parameters(drop_index, position, name, value) VALUES(?,?,?,?)");
        for (size_t k = 0; k < r.soil_parameters.size(); ++k) {
          soil.Reset();
          soil.Int(1, r.index);
          soil.Int(2, static_cast<int64_t>(k));
          soil.Text(3, r.soil_parameters[k].first);
          soil.Real(4, r.soil_parameters[k].second);
          if (const int src = soil.Step(); src != SQLITE_DONE) ThrowSqlite(db_, src, "soil parameters");
        }
      }
      if (!r.trace.empty()) {
        trace.Reset();
        trace.Int(1, r.index);
        trace.Int(2, static_cast<int64_t>(r.trace.size()));
        sqlite3_bind_blob(trace.get(), 3, r.trace.data(), static_cast<int>(r.trace.size() * sizeof(pad::DropSample)),
                          SQLITE_STATIC);
        if (const int rc = trace.Step(); rc != SQLITE_DONE) ThrowSqlite(db_, rc, "trace");
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

int64_t ResultsDb::CountBelow(int64_t total) const {
  Statement st(db_, "SELECT COUNT(*) FROM drops WHERE drop_index >= 0 AND drop_index < ?");
  st.Int(1, total);
  st.Step();
  return sqlite3_column_int64(st.get(), 0);
}

std::vector<int64_t> ResultsDb::StoredIndices(int64_t begin, int64_t end) const {
  Statement st(db_, "SELECT drop_index FROM drops WHERE drop_index >= ? AND drop_index < ? ORDER BY drop_index");
  st.Int(1, begin);
  st.Int(2, end);
  std::vector<int64_t> out;
  int rc;
  while ((rc = st.Step()) == SQLITE_ROW) out.push_back(sqlite3_column_int64(st.get(), 0));
  if (rc != SQLITE_DONE) throw std::runtime_error(std::string("sqlite read: ") + sqlite3_errmsg(db_));
  return out;
}

int64_t ResultsDb::ForgetDropsBelowLimits(long max_rhs_evaluations, double max_wall_time_s) {
  // A limit of 0 is no limit: larger than any recorded one.
  const std::string where =
      "status != 'ok' AND ((failure_limit = 'max_rhs_evaluations' AND (?1 = 0 OR failure_limit_value < ?1)) OR "
      "(failure_limit = 'max_wall_time_s' AND (?2 = 0 OR failure_limit_value < ?2)))";
  Exec("BEGIN IMMEDIATE");
  try {
    Statement traces(db_, "DELETE FROM traces WHERE drop_index IN (SELECT drop_index FROM drops WHERE " + where + ")");
    traces.Int(1, max_rhs_evaluations);
    traces.Real(2, max_wall_time_s);
    if (traces.Step() != SQLITE_DONE) throw std::runtime_error(std::string("sqlite delete: ") + sqlite3_errmsg(db_));
    if (HasSoilParameters()) {  // the drawn parameters go with their drops, and come back with the rerun
      Statement soil(db_, "DELETE FROM soil_parameters WHERE drop_index IN (SELECT drop_index FROM drops WHERE " + where + ")");
      soil.Int(1, max_rhs_evaluations);
      soil.Real(2, max_wall_time_s);
      if (soil.Step() != SQLITE_DONE) throw std::runtime_error(std::string("sqlite delete: ") + sqlite3_errmsg(db_));
    }
    Statement drops(db_, "DELETE FROM drops WHERE " + where);
    drops.Int(1, max_rhs_evaluations);
    drops.Real(2, max_wall_time_s);
    if (drops.Step() != SQLITE_DONE) throw std::runtime_error(std::string("sqlite delete: ") + sqlite3_errmsg(db_));
    const int64_t removed = sqlite3_changes(db_);
    Exec("COMMIT");
    return removed;
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

namespace {
std::string SelectRecords(bool with_traces, const std::string& where_and_order) {
  return "SELECT d.drop_index, " + Columns() +
         (with_traces ? ", t.data FROM drops d LEFT JOIN traces t ON t.drop_index = d.drop_index" : " FROM drops d") +
         " " + where_and_order;
}
}  // namespace

bool ResultsDb::HasSoilParameters() const {
  Statement st(db_, "SELECT COUNT(*) FROM main.sqlite_master WHERE type = 'table' AND name = 'soil_parameters'");
  return st.Step() == SQLITE_ROW && sqlite3_column_int64(st.get(), 0) > 0;
}

void ResultsDb::ReadSoilParameters(DropRecord& r) const {
  r.soil_parameters.clear();
  if (!HasSoilParameters()) return;
  Statement st(db_, "SELECT name, value FROM soil_parameters WHERE drop_index = ? ORDER BY position");
  st.Int(1, r.index);
  int rc;
  while ((rc = st.Step()) == SQLITE_ROW) r.soil_parameters.emplace_back(st.ColumnText(0), sqlite3_column_double(st.get(), 1));
  if (rc != SQLITE_DONE) ThrowSqlite(db_, rc, "read soil parameters");
}

std::vector<DropRecord> ResultsDb::ReadPage(int64_t from, size_t limit, bool with_traces) const {
  const int n_columns = 1 + ColumnCount();
  Statement st(db_, SelectRecords(with_traces, "WHERE d.drop_index >= ? ORDER BY d.drop_index LIMIT ?"));
  st.Int(1, from);
  st.Int(2, static_cast<int64_t>(limit));
  std::vector<DropRecord> out;
  int rc;
  while ((rc = st.Step()) == SQLITE_ROW) {
    out.push_back(ReadRecord(st));
    if (with_traces && sqlite3_column_type(st.get(), n_columns) != SQLITE_NULL)
      out.back().trace = ReadTraceBlob(st, n_columns);
  }
  if (rc != SQLITE_DONE) throw std::runtime_error(std::string("sqlite read: ") + sqlite3_errmsg(db_));
  if (HasSoilParameters())
    for (DropRecord& r : out) ReadSoilParameters(r);
  return out;
}

void ResultsDb::ForEach(const std::function<void(const DropRecord&)>& visit, bool with_traces) const {
  const int n_columns = 1 + ColumnCount();
  Statement st(db_, SelectRecords(with_traces, "ORDER BY d.drop_index"));
  const bool soil = HasSoilParameters();
  int rc;
  while ((rc = st.Step()) == SQLITE_ROW) {
    DropRecord r = ReadRecord(st);
    if (with_traces && sqlite3_column_type(st.get(), n_columns) != SQLITE_NULL) r.trace = ReadTraceBlob(st, n_columns);
    if (soil) ReadSoilParameters(r);
    visit(r);
  }
  if (rc != SQLITE_DONE) ThrowSqlite(db_, rc, "read");
}

std::vector<DropRecord> ResultsDb::ReadAll(bool with_traces) const {
  std::vector<DropRecord> out;
  ForEach([&](const DropRecord& r) { out.push_back(r); }, with_traces);
  return out;
}

}  // namespace touchdown::sweep

// A reader's ResultsDb (kReadOnly: export, merge's shards) writes nothing: not the columns an older
// format lacks, not a -wal or -shm file in a directory it may not write, and any write it is asked
// for is refused by SQLite. tests/python/test_errors.py runs export and merge on a read-only mount.
#include <gtest/gtest.h>

#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "drop_tests/sweep/results_db.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace {

namespace fs = std::filesystem;
using touchdown::InputError;
using touchdown::sweep::DropRecord;
using touchdown::sweep::ResultsDb;

class ResultsDbReadOnly : public touchdown::testing_scratch::ScratchDirTest {
 protected:
  // A format-1 database (no drop_kind, no lander columns) with two drops, in WAL mode as a sweep
  // leaves it, closed (no -wal, no -shm beside it).
  fs::path MakeFormat1Db(const fs::path& dir) {
    fs::create_directories(dir);
    const fs::path path = dir / "results.sqlite";
    sqlite3* db = nullptr;
    EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    const char* sql =
        "PRAGMA journal_mode=WAL;"
        "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
        "INSERT INTO meta VALUES('format_version', '1'), ('sweep_name', 'old');"
        "CREATE TABLE drops(drop_index INTEGER PRIMARY KEY, drop_id TEXT NOT NULL, status TEXT NOT NULL, "
        "failure TEXT NOT NULL, pad TEXT NOT NULL, soil TEXT NOT NULL, atmosphere TEXT NOT NULL, "
        "impact_speed_m_s REAL, pad_mass_kg REAL, gravity_m_s2 REAL, tilt_deg REAL, horizontal_speed_m_s REAL, "
        "zeta_N_cm3 REAL, final_penetration_m REAL, peak_force_N REAL, time_to_rest_s REAL, "
        "max_deceleration_m_s2 REAL, impact_energy_J REAL, gravity_work_J REAL, dissipated_energy_J REAL, "
        "mean_conversion_rate_W REAL, rest_creep_m REAL, solver_steps INTEGER);"
        "CREATE TABLE traces(drop_index INTEGER PRIMARY KEY, samples INTEGER NOT NULL, data BLOB NOT NULL);"
        "INSERT INTO drops(drop_index, drop_id, status, failure, pad, soil, atmosphere, impact_speed_m_s, "
        "final_penetration_m, solver_steps) VALUES(0, '0', 'ok', '', 'flat', 'fjs1_lp', 'vacuum', 1.0, 0.0125, 7),"
        "(1, '1', 'failed', 'why', 'flat', 'fjs1_lp', 'vacuum', 2.0, NULL, 0);";
    EXPECT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
    sqlite3_close(db);
    return path;
  }

  static std::vector<std::string> Listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  // The drops table's columns, read immutable so that this look leaves no -wal or -shm behind.
  static std::vector<std::string> DropsColumns(const fs::path& path) {
    sqlite3* db = nullptr;
    sqlite3_open_v2(("file:" + path.string() + "?immutable=1").c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI,
                    nullptr);
    sqlite3_stmt* st = nullptr;
    std::vector<std::string> columns;
    sqlite3_prepare_v2(db, "PRAGMA table_info(drops)", -1, &st, nullptr);
    while (sqlite3_step(st) == SQLITE_ROW) columns.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(st, 1)));
    sqlite3_finalize(st);
    sqlite3_close(db);
    return columns;
  }

  // Reads the database as export does and checks the two drops, the newer columns at their defaults.
  static void ExpectTheTwoDrops(const ResultsDb& db) {
    EXPECT_EQ(db.Meta().at("sweep_name"), "old");
    const std::vector<DropRecord> records = db.ReadAll(/*with_traces=*/true);
    ASSERT_EQ(records.size(), 2u);
    EXPECT_TRUE(records[0].ok);
    EXPECT_EQ(records[0].final_penetration_m, 0.0125);
    EXPECT_EQ(records[0].kind, touchdown::sweep::DropKind::kRig);
    EXPECT_TRUE(std::isnan(records[0].tipped_over));
    EXPECT_TRUE(std::isnan(records[0].max_joint_swing_deg));
    EXPECT_TRUE(std::isnan(records[0].tip_over_edge));
    EXPECT_EQ(records[0].pad_soil[0], "");
    EXPECT_EQ(records[1].failure, "why");
    EXPECT_EQ(db.Count(), 2);
    EXPECT_EQ(db.ReadPage(1, 10, false).size(), 1u);
  }
};

TEST_F(ResultsDbReadOnly, ReadsAnOlderFormatWithoutChangingTheFile) {
  const fs::path path = MakeFormat1Db(dir_ / "old");
  const std::vector<std::string> columns = DropsColumns(path);
  {
    const ResultsDb db(path.string(), ResultsDb::Access::kReadOnly);
    ExpectTheTwoDrops(db);
  }
  EXPECT_EQ(DropsColumns(path), columns);  // no column added to the user's file
  EXPECT_EQ(Listing(dir_ / "old"), std::vector<std::string>{"results.sqlite"});
}

TEST_F(ResultsDbReadOnly, RefusesEveryWriteAsInputError) {
  const fs::path path = MakeFormat1Db(dir_ / "old");
  ResultsDb db(path.string(), ResultsDb::Access::kReadOnly);
  DropRecord r;
  r.index = 5, r.drop_id = "5", r.ok = true;
  EXPECT_THROW(db.Insert({r}), InputError);  // "attempt to write a readonly database"
  EXPECT_THROW(db.SetMeta({{"sweep_name", "new"}}), InputError);
  EXPECT_EQ(db.Count(), 2);
}

TEST_F(ResultsDbReadOnly, AFileWithoutTablesReadsAsEmpty) {
  // An empty file (or another program's SQLite database) has no meta: export and merge say so.
  const std::string path = Write("results.sqlite", "");
  const ResultsDb db(path, ResultsDb::Access::kReadOnly);
  EXPECT_TRUE(db.Meta().empty());
  EXPECT_EQ(db.Count(), 0);
  EXPECT_EQ(Slurp(path), "");
}

TEST_F(ResultsDbReadOnly, APathWithUriCharactersOpens) {
  // The reader opens a file: URI; '?', '#', '%' and spaces in the path are the file's name.
  const fs::path path = MakeFormat1Db(dir_ / "a?b#c%41 d" / "sub");
  const ResultsDb db(path.string(), ResultsDb::Access::kReadOnly);
  ExpectTheTwoDrops(db);
}

TEST_F(ResultsDbReadOnly, ReadsInADirectoryItCannotWrite) {
  // Permissions stop no write for root; the read-only mount of tests/python/test_errors.py
  // covers that case.
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into a 0555 directory";
  const fs::path dir = dir_ / "archive";
  const fs::path path = MakeFormat1Db(dir);
  ::chmod(dir.c_str(), 0555);
  {
    const ResultsDb db(path.string(), ResultsDb::Access::kReadOnly);
    ExpectTheTwoDrops(db);
  }
  ::chmod(dir.c_str(), 0755);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"results.sqlite"});
}

}  // namespace

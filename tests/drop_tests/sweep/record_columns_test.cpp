// One record, one set of names: a rig drop's metrics are the same numbers under the same names in
// `touchdown drop`'s summary, the results database and the exports (drops.csv, lander_drops.csv,
// whose lander half sweep_drop_test.cpp checks).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "drop_tests/drop/drop_columns.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_export.h"
#include "tests/drop_tests/sweep/sweep_test_support.h"

namespace touchdown::sweep {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> CsvCells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

TEST(RecordColumns, EveryRigMetricIsARigColumnOfTheDatabase) {
  for (const drop::ResultNumber<pad::RigDropResult>& m : drop::RigMetrics()) {
    bool found = false;
    for (const RecordNumber& n : RigNumbers()) found = found || std::string(n.name) == m.name;
    EXPECT_TRUE(found) << m.name;
  }
  EXPECT_THROW(RecordNumberNamed("no_such_column"), std::logic_error);
}

TEST(RecordColumns, SummaryDatabaseAndExportHoldTheSameRigDrop) {
  const fs::path dir = fs::temp_directory_path() / ("touchdown_record_columns_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "one.yaml") << "schema_version: 1\ntype: sweep\nname: one\ntraces: none\n"
                                     "fixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1.0}\n";
  const SweepPlan plan = LoadSweepPlan((dir / "one.yaml").string());
  RunSweep(plan, (dir / "out").string(), testing_sweep::Quiet(1));
  const std::vector<DropRecord> records = testing_sweep::Records(dir / "out");
  ASSERT_EQ(records.size(), 1u);
  const DropRecord& r = records[0];
  ASSERT_TRUE(r.ok) << r.failure;

  // The same drop as `touchdown drop` runs it: its summary's key of each metric holds the
  // database's column of that name, bit for bit.
  drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  drop::DropRunOptions o;
  o.rig = plan.rig;
  const nlohmann::json j = drop::SummaryJson(drop::RunDrop(drop::ResolveDrop(plan.pads[0], plan.soils[0], c, o)));
  for (const drop::ResultNumber<pad::RigDropResult>& m : drop::RigMetrics())
    EXPECT_EQ(j[m.name].get<double>(), RecordNumberNamed(m.name).Of(r)) << m.name;
  EXPECT_EQ(j["solver_steps"].get<int64_t>(), r.solver_steps);

  // drops.csv: every column the database has by that name holds its number.
  ExportSweep((dir / "out").string(), (dir / "export").string(), {});
  std::ifstream in(dir / "export" / "drops.csv");
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  const std::vector<std::string> names = CsvCells(header), cells = CsvCells(row);
  ASSERT_EQ(names.size(), cells.size());
  int numbers = 0;
  for (size_t k = 0; k < names.size(); ++k) {
    if (names[k] == "solver_steps") {
      EXPECT_EQ(cells[k], std::to_string(r.solver_steps));
    }
    try {
      EXPECT_EQ(cells[k], io::FormatNumber(RecordNumberNamed(names[k]).Of(r))) << names[k];
      ++numbers;
    } catch (const std::logic_error&) {  // a text column, or solver_steps
    }
  }
  EXPECT_EQ(numbers, 17);  // speed, mass and gravity, the two summaries, the 13 extra less solver_steps
  fs::remove_all(dir);
}

}  // namespace
}  // namespace touchdown::sweep

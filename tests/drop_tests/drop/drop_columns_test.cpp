// A single drop's outputs written from one table per record (drop_columns.h): the summary's keys,
// the trace's header and its cells name and hold the same numbers as the result.
#include "drop_tests/drop/drop_columns.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/drop/free_drop_output.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"

namespace touchdown::drop {
namespace {

std::vector<std::string> ColumnCells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

template <typename Sample>
std::vector<std::string> ColumnNames(const std::vector<TraceColumn<Sample>>& columns) {
  std::vector<std::string> names;
  for (const TraceColumn<Sample>& c : columns) names.push_back(c.name);
  return names;
}

TEST(DropColumns, RigSummaryAndTraceAreTheirTables) {
  DropConditions conditions;
  conditions.impact_speed_m_s = 1.0;
  const PadDrop d = RunDrop(ResolveDrop(io::LoadPad("flat"), io::LoadSoil("fjs1_lp"), conditions));
  const nlohmann::json j = SummaryJson(d);
  for (const ResultNumber<pad::RigDropResult>& n : RigMetrics()) {
    ASSERT_TRUE(j.contains(n.name)) << n.name;
    EXPECT_EQ(j[n.name].get<double>(), d.result.*n.member) << n.name;  // the same double, bit for bit
  }
  EXPECT_EQ(j["solver_steps"].get<long>(), d.result.solver.steps);
  EXPECT_GT(d.result.final_penetration_m, 1e-3);

  std::ostringstream csv;
  WriteTraceCsv(d.result, csv);
  std::stringstream lines(csv.str());
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  EXPECT_EQ(header, "t_s,penetration_m,velocity_m_s,force_N");
  EXPECT_EQ(ColumnCells(header), ColumnNames(RigTraceColumns()));
  ASSERT_FALSE(d.result.trace.empty());
  const std::vector<std::string> cells = ColumnCells(row);
  ASSERT_EQ(cells.size(), RigTraceColumns().size());
  for (size_t c = 0; c < cells.size(); ++c)  // written to 10 significant digits
    EXPECT_NEAR(std::stod(cells[c]), RigTraceColumns()[c].value(d.result.trace[0]),
                1e-9 * std::abs(RigTraceColumns()[c].value(d.result.trace[0])) + 1e-300)
        << RigTraceColumns()[c].name;
}

TEST(DropColumns, FreeSummaryAndTraceAreTheirTables) {
  pad::FreeDropResult r;
  double next = 1.0;
  for (const ResultNumber<pad::FreeDropResult>& n : FreeMetrics()) r.*n.member = next++;
  r.solver.steps = 42;
  pad::FreeDropSample s;
  s.t_s = 0.5, s.penetration_m = 0.25, s.velocity_m_s = 0.125, s.force_N = 3, s.force_x_N = 4, s.horizontal_m = 5;
  s.tilt_deg = 6, s.p_WB = {7, 8, 9}, s.q_WB = {10, 11, 12, 13}, s.w_W = {14, 15, 16};
  r.trace = {s};

  const nlohmann::json j = FreeDropJson(r);
  EXPECT_EQ(j["mode"], "free");
  EXPECT_EQ(j["solver_steps"].get<long>(), 42);
  EXPECT_EQ(j.size(), FreeMetrics().size() + 2);
  for (const ResultNumber<pad::FreeDropResult>& n : FreeMetrics()) EXPECT_EQ(j[n.name].get<double>(), r.*n.member) << n.name;

  std::ostringstream csv;
  WriteFreeDropTraceCsv(r, csv);
  EXPECT_EQ(csv.str(),
            "t_s,penetration_m,velocity_m_s,force_N,force_x_N,horizontal_m,tilt_deg,x_m,y_m,z_m,qw,qx,qy,qz,"
            "wx_rad_s,wy_rad_s,wz_rad_s\n0.5,0.25,0.125,3,4,5,6,7,8,9,10,11,12,13,14,15,16\n");
  // The dataset tools read a free trace by the rig's columns, which come first.
  const std::vector<std::string> free = ColumnNames(FreeTraceColumns()), rig = ColumnNames(RigTraceColumns());
  EXPECT_EQ(std::vector<std::string>(free.begin(), free.begin() + rig.size()), rig);
}

}  // namespace
}  // namespace touchdown::drop

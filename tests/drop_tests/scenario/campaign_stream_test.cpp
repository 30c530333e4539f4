// A campaign's memory does not grow with its traces or its pads. Its cases
// share one loaded pad each (the revolved body is megabytes), and RunCampaignToDirectory writes
// each trace as its drop finishes and keeps the summaries only, with the same files as running the
// whole campaign in memory and writing it afterwards.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "drop_tests/scenario/campaign.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::scenario {
namespace {

namespace fs = std::filesystem;

using testing_scratch::Slurp;

TEST(CampaignStream, CasesShareTheirPad) {
  const CampaignScenario s = LoadCampaignScenario(io::DataDirectory() + "/scenarios/sutoh2017_single_footpad.yaml");
  ASSERT_GE(s.cases.size(), 2u);
  for (const CampaignCase& a : s.cases)
    for (const CampaignCase& b : s.cases)
      if (a.pad->name == b.pad->name) {
        EXPECT_EQ(a.pad.get(), b.pad.get()) << a.drop_id << " / " << b.drop_id;
      }
}

TEST(CampaignStream, StreamedOutputsEqualTheInMemoryOnesAndKeepNoTraces) {
  const fs::path dir = fs::temp_directory_path() / ("touchdown_campaign_stream_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "c.yaml") << "schema_version: 1\ntype: campaign\nname: stream\ndrops:\n"
                                   "  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [0.7, 1.0]}\n"
                                   "  - {pad: curved, soil: fjs1_cp, impact_speeds_m_s: [1.0]}\n";
  const CampaignScenario s = LoadCampaignScenario((dir / "c.yaml").string());
  const CampaignResult in_memory = RunCampaign(s);
  WriteCampaignOutputs(in_memory, (dir / "a").string());
  const CampaignResult streamed = RunCampaignToDirectory(s, (dir / "b").string());
  ASSERT_EQ(streamed.drops.size(), 3u);
  for (size_t i = 0; i < streamed.drops.size(); ++i) {
    EXPECT_TRUE(streamed.drops[i].result.trace.empty());
    EXPECT_FALSE(in_memory.drops[i].result.trace.empty());
    EXPECT_EQ(streamed.drops[i].result.final_penetration_m, in_memory.drops[i].result.final_penetration_m);
    EXPECT_EQ(streamed.drops[i].result.peak_force_N, in_memory.drops[i].result.peak_force_N);
  }
  int files = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir / "a")) {
    if (!e.is_regular_file() || e.path().extension() == ".png") continue;  // PNGs: gnuplot's, if installed
    const fs::path rel = e.path().lexically_relative(dir / "a");
    EXPECT_EQ(Slurp(e.path()), Slurp(dir / "b" / rel)) << rel;
    ++files;
  }
  EXPECT_GE(files, 3 + 3);  // three traces, summary.csv, summary.json, scenario_resolved.yaml (+ plot files)

  // summary.csv's columns are summary.json's fields of the same names, drop by drop (the CSV to 10
  // significant digits).
  const nlohmann::json summary = nlohmann::json::parse(Slurp(dir / "a" / "summary.json"));
  std::ifstream csv(dir / "a" / "summary.csv");
  std::string line;
  std::getline(csv, line);
  auto cells_of = [](const std::string& text) {
    std::vector<std::string> cells;
    std::stringstream in(text);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    return cells;
  };
  const std::vector<std::string> names = cells_of(line);
  ASSERT_EQ(summary["drops"].size(), 3u);
  for (const nlohmann::json& drop : summary["drops"]) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> cells = cells_of(line);
    ASSERT_EQ(cells.size(), names.size()) << line;
    for (size_t c = 0; c < names.size(); ++c) {
      const nlohmann::json& v = drop.at(names[c]);
      if (v.is_string()) EXPECT_EQ(cells[c], v.get<std::string>()) << names[c];
      else EXPECT_NEAR(std::stod(cells[c]), v.get<double>(), 1e-9 * std::abs(v.get<double>())) << names[c];
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace touchdown::scenario

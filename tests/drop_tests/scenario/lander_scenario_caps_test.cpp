// A lander run keeps its trace in memory, so duration x rate is capped at load
// (1e6 samples take about 0.4 GB, so ten times that would need over 4 GB), the refusal naming the
// field and the limit.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "drop_tests/scenario/lander_scenario_file.h"
#include "rft/input_error.h"

namespace touchdown::scenario {
namespace {

std::string LoadError(const std::string& simulation) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("touchdown_lander_caps_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << "schema_version: 1\ntype: lander\nlander: sutoh2017_lander\nground: {soil: fjs1_lp}\n"
                         "initial: {drop_height_m: 0.1}\nsimulation: "
                      << simulation << "\n";
  std::string message;
  try {
    LoadLanderScenario(path.string());
  } catch (const InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

TEST(LanderScenarioCaps, TraceSamplesAtMostOneMillion) {
  EXPECT_EQ(LoadError("{duration_s: 1.0, sample_rate_hz: 1000000}"), "");  // exactly at the cap
  const std::string e = LoadError("{duration_s: 10.0, sample_rate_hz: 1000000}");
  EXPECT_NE(e.find("sample_rate_hz"), std::string::npos) << e;
  EXPECT_NE(e.find("1e+07 trace samples, at most 1e+06"), std::string::npos) << e;
}

}  // namespace
}  // namespace touchdown::scenario

#pragma once
// What `touchdown lander` writes for a landing: summary.json, trace.csv, events.csv,
// scenario_resolved.yaml, plots/ and vtk/.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/scenario/lander_scenario_types.h"

namespace touchdown::scenario {

// The JSON summary `touchdown lander` prints (pads in the paper's clockwise order).
nlohmann::json LanderSummaryJson(const LanderRun& run);
// The paper check's entry of the summary (`paper_check`), at the run's final roll and pitch.
nlohmann::json LanderPaperCheckJson(const LanderPaperCheck& check, double roll_deg, double pitch_deg);
void WriteLanderTraceCsv(const LanderRun& run, const std::string& path);
// What WriteLanderOutputs writes beside the summary, traces and plots: the ParaView series vtk/
// (about 35 MB and 1 s a landing) only when asked (`touchdown lander --no-vtk` leaves it out).
struct LanderOutputOptions {
  bool vtk = true;
};
// summary.json, trace.csv, events.csv, scenario_resolved.yaml, plots/ and vtk/ (lander_vtk.h) into a
// staging directory renamed to out_dir when complete.
void WriteLanderOutputs(const LanderRun& run, const io::OutputTarget& out, const LanderOutputOptions& options = {});

}  // namespace touchdown::scenario

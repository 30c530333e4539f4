#include "drop_tests/targets/targets_calibration.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/util/work_pool.h"
#include "drop_tests/model/model_file.h"
#include "rft/input_error.h"

namespace touchdown::targets {

namespace {
// The report's first line: a report touchdown wrote may be replaced by a rerun, a user's file never.
constexpr const char* kTargetsReportMark = "{\"written_by\": \"touchdown calibrate --targets (it may replace this file)\",";
}  // namespace

TargetsCalibration RunTargetsCalibration(const TargetsCalibrationRequest& r) {
  const io::OutputTarget out(r.out, {r.targets});
  io::CheckOutputFile(out, model::kModelFileMark);
  std::optional<io::OutputTarget> report;
  if (!r.report.empty()) {
    report.emplace(r.report, std::vector<std::string>{r.targets});
    if (std::filesystem::absolute(r.report).lexically_normal() == std::filesystem::absolute(r.out).lexically_normal())
      throw MakeInputError(r.naming.context, r.naming.Field("report"),
                           "must differ from " + r.naming.Field("out") + " (" + r.report + ")");
    io::CheckOutputFile(*report, kTargetsReportMark);
  }
  TargetsCalibration c{LoadTargetsFile(r.targets), {}};
  if (r.evaluate_only)
    for (Target& t : c.file.targets) t.fit = false;
  TargetsFitOptions options;
  options.threads = io::ThreadsFor(r.threads);
  io::Progress progress("calibrate", "evaluations", 0, r.progress);
  options.on_evaluation = [&progress](const std::vector<double>&) { progress.Add(1); };
  c.fit = FitTargets(c.file, options);
  progress.Finish();
  const std::filesystem::path model_path(r.out);
  model::WriteModelFile(TargetsModel(c.file, c.fit, model_path.stem().string(), model_path.parent_path().string()), out);
  if (report) {
    // The JSON object opens with its "written_by" entry on the mark's line.
    const std::string json = TargetsCalibrationReportJson(r, c).dump(2);
    io::WriteOutputFile(*report, [&](std::ostream& o) { o << kTargetsReportMark << '\n' << json.substr(2) << '\n'; },
                        kTargetsReportMark);
  }
  return c;
}

nlohmann::json TargetsCalibrationReportJson(const TargetsCalibrationRequest& r, const TargetsCalibration& c) {
  nlohmann::json j = TargetsReportJson(c.file, c.fit);
  // What wrote it, so a file kept beside the data says how to remake it.
  j["command"] = "touchdown calibrate --targets " + r.targets + " --out " + r.out + " --report " + r.report +
                 (r.evaluate_only ? " --evaluate-only" : "");
  return j;
}

}  // namespace touchdown::targets

#pragma once
// `calibrate --targets` as one call, for the command line and the Python module alike: the targets
// file loaded, its parameters fitted (or only evaluated), the model file written to `out` (and the
// report to `report`), through io::OutputTarget, so a user's file is never replaced.
#include <string>

#include <nlohmann/json.hpp>

#include "drop_tests/drop/drop_request.h"
#include "drop_tests/util/progress.h"
#include "drop_tests/targets/targets_fit.h"

namespace touchdown::targets {

struct TargetsCalibrationRequest {
  std::string targets;        // the targets file
  std::string out;            // the model file to write
  std::string report;         // the JSON report to write; empty: none
  int threads = 0;            // scenarios side by side; 0: every core
  bool evaluate_only = false;  // no fit: every target at the parameters' start values
  drop::RequestNaming naming;  // how errors name the options (--report, or the Python module's report)
  // Of the fit's evaluations of the targets (each runs the scenarios it needs); their number is
  // not known ahead, so the total stays 0.
  io::ProgressOptions progress{io::ProgressMode::kNone};
};

struct TargetsCalibration {
  TargetsFile file;
  TargetsFitResult fit;
};

// Throws InputError for a bad request or file (naming it), before anything runs or is written.
TargetsCalibration RunTargetsCalibration(const TargetsCalibrationRequest& request);

// The report `--report` holds (without its "written_by" mark), and Python returns: the fit's
// report (TargetsReportJson) and the command that makes it again.
nlohmann::json TargetsCalibrationReportJson(const TargetsCalibrationRequest& request, const TargetsCalibration& c);

}  // namespace touchdown::targets

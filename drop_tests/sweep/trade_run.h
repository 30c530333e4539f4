#pragma once
// `touchdown trade SWEEP.yaml --out DIR` as one call, for the command and the Python module
// (touchdown.trade): checks the plan and its limits before anything runs or is written, runs (or
// resumes) the sweep into DIR/results.sqlite, then writes the trade outputs (trade.h).
#include <string>
#include <vector>

#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/trade.h"

namespace touchdown::sweep {

struct TradeRun {
  SweepRunSummary sweep;
  TradeLimits limits;
  std::vector<TradeRow> rows;  // summary.json is TradeJson(rows, limits)
};

// `model`: a model file with per-soil zeta ("" none). A sweep stopped (SweepRunOptions::stop) returns
// with its run counts only: the committed drops stay for a rerun, no trade outputs are written.
TradeRun RunTrade(const std::string& sweep_file, const std::string& model, const std::string& out,
                  const SweepRunOptions& options);

}  // namespace touchdown::sweep

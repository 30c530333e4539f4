#include "drop_tests/sweep/trade_run.h"

#include "drop_tests/formats/output_path.h"

namespace touchdown::sweep {

TradeRun RunTrade(const std::string& sweep_file, const std::string& model, const std::string& out,
                  const SweepRunOptions& options) {
  const SweepPlan plan = LoadSweepPlan(sweep_file, model);
  CheckTradePlan(plan);  // before anything runs or is written
  TradeRun run;
  run.limits = LoadTradeLimits(sweep_file);
  io::OpenOutputDirectory({out, {sweep_file, model}}, io::OutputKind::kSweep);
  run.sweep = RunSweep(plan, out, options);
  if (run.sweep.stop_signal != 0) return run;  // stopped: the drops are kept, no table of a part of them
  const ResultsDb db(ResultsDbPath(out));
  run.rows = TradeTable(db.ReadAll(/*with_traces=*/false), run.limits);
  WriteTradeOutputs(run.rows, out, run.limits);
  return run;
}

}  // namespace touchdown::sweep

#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/sweep/sweep_export.h"
#include "rft/physical_limits.h"

namespace touchdown::app {

void AddExportCommand(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto to = std::make_shared<std::string>();
  auto options = std::make_shared<sweep::ExportOptions>();
  CLI::App* cmd = app.add_subcommand("export", "Write a sweep's results (DIR/results.sqlite) in the dataset format");
  cmd->add_option("dir", *dir, "sweep output directory")->required();
  cmd->add_option("--to", *to, "dataset directory: new, empty, or an earlier dataset touchdown wrote (replaced whole when complete)")->required()->check(NonEmptyPath());
  cmd->add_flag("--full-traces", options->full_traces,
                "simulate every drop again for its full 1 kHz trace (default: stored traces; re-simulated if none)");
  cmd->add_option("--threads", options->threads, "threads for re-simulated traces (default: every core)")
      ->check(NumberIn(0, limits::kMaxThreads));
  cmd->callback([dir, to, options] {
    const io::OutputTarget out(*to, {*dir});
    io::CheckOutputDirectory(out, io::OutputKind::kDataset);
    options->progress.mode = io::ProgressMode::kAuto;
    const sweep::ExportSummary s = sweep::ExportSweep(*dir, out, *options);
    std::cout << "exported " << s.exported << (s.lander ? " lander drops" : " drops") << " to " << *to
              << (s.lander ? "/ (lander_drops.csv)" : "/ (drops.csv, traces/)");
    if (s.resimulated > 0) std::cout << "; " << s.resimulated << " traces simulated again";
    if (s.failed > 0) std::cout << "; " << s.failed << " failed drops listed in failed.csv";
    std::cout << "\n";
  });
}

}  // namespace touchdown::app

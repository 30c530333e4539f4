#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/sweep/sweep.h"

namespace touchdown::app {

void AddMergeCommand(CLI::App& app) {
  auto shards = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("merge", "Combine the results of sweep shards (--shard I/N) into one database");
  cmd->add_option("shards", *shards, "shard output directories")->required();
  cmd->add_option("--out", *out, "merged output directory (DIR/results.sqlite)")->required()->check(NonEmptyPath());
  cmd->callback([shards, out] {
    const sweep::MergeSummary s = sweep::MergeSweepResults(*out, *shards);
    std::cout << "merged " << s.shards << " shard(s): " << s.stored << " of " << s.total << " drops stored";
    if (s.missing > 0) std::cout << ", " << s.missing << " missing (run the missing shards, then merge again)";
    std::cout << ", " << s.failed << " failed\nwrote " << sweep::ResultsDbPath(*out) << "\n";
  });
}

}  // namespace touchdown::app

// touchdown import MAPPING.yaml --out DATASET_DIR: raw DAQ files of drop tests into the dataset
// format (drop_tests/dataset/daq_import.h, docs/import.md).
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/dataset/daq_import.h"
#include "drop_tests/formats/output_path.h"

namespace touchdown::app {

namespace {
struct ImportArgs {
  std::string mapping, out;
};
}  // namespace

void AddImportCommand(CLI::App& app) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "import", "Raw DAQ files of drop tests into a dataset: touchdown found, channels converted and filtered (CFC)");
  cmd->add_option("mapping", args->mapping, "mapping YAML: the DAQ's columns, units, channels and drops (docs/import.md)")
      ->required();
  cmd->add_option("--out", args->out,
                  "dataset directory: new, empty, or an earlier dataset touchdown wrote (replaced whole when complete)")
      ->required()
      ->check(NonEmptyPath());
  cmd->callback([args] {
    const dataset::ImportRun run = dataset::ImportToDirectory(args->mapping, {args->out, {args->mapping}});
    std::cout << dataset::ImportSummaryJson(run, args->out).dump(2) << std::endl;
  });
}

}  // namespace touchdown::app

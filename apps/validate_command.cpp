#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/validation/validate.h"

namespace touchdown::app {

namespace {
struct ValidateArgs {
  std::string sources, out;
};
}  // namespace

void AddValidateCommand(CLI::App& app) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "validate",
      "Validation against published granular-impact measurements: per source measured, simulated (quasi-static and "
      "dynamic RFT), error, and whether each measured trend is reproduced (docs/validation.md)");
  cmd->add_option("--sources", args->sources,
                  "directory of validation sources and dynamic_rft.yaml (default: the data's validation/)");
  cmd->add_option("--out", args->out, "output directory (validation.json, validation.md, plots/)")->check(NonEmptyPath());
  cmd->callback([args] {
    const validation::ValidationResult result = validation::ValidateSources(args->sources, args->out);
    std::cout << validation::ValidationSummary(result);
    if (!args->out.empty())
      std::cout << "wrote " << args->out << "/ (validation.json, validation.md, plots/ as PNG and SVG)\n";
  });
}

}  // namespace touchdown::app

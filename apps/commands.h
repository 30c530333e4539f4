#pragma once
// Subcommands of the touchdown executable. Each registers its options and a callback that
// runs during parse; errors propagate as exceptions to main.
#include <CLI/CLI.hpp>

namespace touchdown::app {

void AddDropCommand(CLI::App& app);      // touchdown drop --pad P --soil S --speed V ...
void AddCampaignCommand(CLI::App& app);  // touchdown campaign SCENARIO.yaml --out DIR

}  // namespace touchdown::app

#pragma once
// Subcommands of the touchdown executable. Each registers its options and a callback that
// runs during parse; errors propagate as exceptions to main.
#include <CLI/CLI.hpp>

namespace touchdown::app {

void AddDropCommand(CLI::App& app);      // touchdown drop --pad P --soil S --speed V ...
void AddCampaignCommand(CLI::App& app);  // touchdown campaign SCENARIO.yaml --out DIR
void AddForceCommand(CLI::App& app);     // touchdown force --pad P --soil S --depth D [--tilt-deg A] ...
void AddSweepCommand(CLI::App& app);      // touchdown sweep SWEEP.yaml --out DIR [--threads N] [--shard I/N]
void AddExportCommand(CLI::App& app);     // touchdown export DIR --to DATASET_DIR
void AddMergeCommand(CLI::App& app);      // touchdown merge SHARD_DIR... --out DIR
void AddCompareCommand(CLI::App& app);    // touchdown compare MEASURED_DIR [--simulated DIR | --model M] --out DIR
void AddCalibrateCommand(CLI::App& app);  // touchdown calibrate MEASURED_DIR --param zeta --out MODEL.yaml
void AddTradeCommand(CLI::App& app);      // touchdown trade SWEEP.yaml --out DIR
void AddLanderCommand(CLI::App& app);    // touchdown lander SCENARIO.yaml --out DIR
void AddSynthCommand(CLI::App& app);     // touchdown synth SPEC.yaml --out DATASET_DIR
void AddDiagnoseCommand(CLI::App& app);  // touchdown diagnose MEASURED_DIR [--model M] --out DIR
void AddStabilityCommand(CLI::App& app);  // touchdown stability STUDY.yaml --out DIR [--samples N]
void AddValidateCommand(CLI::App& app);   // touchdown validate [--sources DIR] [--out DIR]
void AddImportCommand(CLI::App& app);     // touchdown import MAPPING.yaml --out DATASET_DIR
void AddSchemaCommand(CLI::App& app);     // touchdown schema [FILE_TYPE] [--json]

}  // namespace touchdown::app

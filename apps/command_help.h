#pragma once
// What `touchdown --help` and `touchdown CMD --help` show beyond the options: worked examples
// (commands that run as written from the repository root on the bundled data), the pads,
// soils, scenarios and sweeps the catalogue knows, and a mistyped command named with the
// nearest real one.
#include <CLI/CLI.hpp>

namespace touchdown::app {

// Call after every subcommand is registered.
void AddHelpFooters(CLI::App& app);

// argv[1] is neither an option nor a subcommand: InputError "unknown command 'x' (did you mean
// 'y'?) ...". CLI11 alone reports only that a subcommand is required.
void RejectUnknownCommand(const CLI::App& app, int argc, char** argv);

}  // namespace touchdown::app

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

// Every argument must be UTF-8 text: an argument is a path, a name or a number, and touchdown
// records paths and names in its JSON outputs (summary.json, the model a calibration writes),
// which hold only UTF-8. Refusing here, before anything runs, means a file name touchdown could
// not record or read back (`calibrate --out $'m\xff.yaml'`) is never written. InputError naming
// the argument with its bad bytes escaped ("m\xff.yaml").
void RejectNonUtf8Arguments(int argc, char** argv);

}  // namespace touchdown::app

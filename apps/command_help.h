#pragma once
// What `touchdown --help` and `touchdown CMD --help` show beyond the options: worked examples
// (commands that run as written from the repository root on the bundled data), the pads,
// soils, scenarios and sweeps the catalogue knows, and a mistyped command named with the
// nearest real one.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace touchdown::app {

// Call after every subcommand is registered. Also makes every help text wrap at 100 columns.
void AddHelpFooters(CLI::App& app);

// The file `command` (campaign, lander, sweep, trade, stability) runs: a path, or the name of a
// bundled one listed in its help (io::ResolveInputDocument). Other commands' inputs as given.
std::string ResolveCommandInput(const std::string& command, const std::string& name_or_path);

// After a failed parse: "command line: --sped: unknown option of `touchdown drop` (did you mean
// '--speed'?); ..." when an option nobody defines was given, which CLI11 reports only after any
// missing required option ("--speed is required" for `drop --sped 1`); none otherwise.
std::optional<std::string> UnknownOptionMessage(const CLI::App& app);

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

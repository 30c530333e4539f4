#include "apps/command_help.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "drop_tests/io/catalog.h"
#include "drop_tests/io/nearest_name.h"
#include "rft/input_error.h"
#include "rft/input_file.h"

namespace touchdown::app {

namespace {
struct CommandExamples {
  const char* command;
  std::vector<const char*> lines;
};

// Every line runs as written from the repository root, in this order (tests/apps/cli_help_test.cpp
// runs them all).
const std::vector<CommandExamples>& Examples() {
  static const std::vector<CommandExamples> examples = {
      {"drop",
       {"touchdown drop --pad flat --soil fjs1_lp --speed 1.0",
        "touchdown drop --pad curved --soil fjs1_cp --speed 1.4 --gravity 1.62 --trace curved_cp.csv",
        "touchdown drop --pad hex --soil fjs1_lp --speed 1.0 --free --tilt-deg 5 --tilt-axis x"}},
      {"campaign", {"touchdown campaign data/scenarios/sutoh2017_single_footpad.yaml --out runs/campaign"}},
      {"force",
       {"touchdown force --pad flat --soil fjs1_lp --depth 0.01",
        "touchdown force --pad c4 --soil fjs1_cp --depth 0.02 --tilt-deg 10 --tilt-axis y --velocity 0.3 0 -1"}},
      {"sweep",
       {"touchdown sweep data/sweeps/pad_trade.yaml --out runs/pad_trade",
        "touchdown sweep data/sweeps/pad_trade.yaml --out runs/pad_trade_0 --shard 0/2   # one job of two",
        "touchdown sweep data/sweeps/pad_trade.yaml --out runs/pad_trade_1 --shard 1/2   # the other"}},
      {"export", {"touchdown export runs/pad_trade --to runs/pad_trade_dataset"}},
      {"merge", {"touchdown merge runs/pad_trade_0 runs/pad_trade_1 --out runs/merged   # the shards of `sweep`'s examples"}},
      {"compare", {"touchdown compare data/datasets/air_vs_vacuum_synthetic --out runs/compare"}},
      {"calibrate",
       {"touchdown calibrate data/datasets/air_vs_vacuum_synthetic --out runs/calibrated_model.yaml",
        "touchdown calibrate --targets data/targets/sutoh2017.yaml --out runs/sutoh2017.yaml   # the paper, default reading",
        "touchdown calibrate --targets data/targets/sutoh2017_r1.yaml --out runs/sutoh2017_r1.yaml --evaluate-only   # no fit"}},
      {"trade", {"touchdown trade data/sweeps/pad_trade.yaml --out runs/trade"}},
      {"lander",
       {"touchdown lander data/scenarios/lander_case_B.yaml --out runs/lander_B"}},
      {"synth", {"touchdown synth data/datasets/air_vs_vacuum_synthetic.synth.yaml --out runs/synthetic_dataset"}},
      {"diagnose", {"touchdown diagnose data/datasets/air_vs_vacuum_synthetic --out runs/diagnose"}},
      {"stability",
       {"touchdown stability data/studies/lunar_paper_lander.yaml --out runs/lunar_quick --samples 10   # a quick look"}},
      {"validate", {"touchdown validate --out runs/validation"}},
  };
  return examples;
}

std::string Joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

// The catalogue names a command's options take, read when help is shown (the data directory may
// be $TOUCHDOWN_DATA_DIR).
std::string KnownNames(const std::string& command) {
  std::vector<std::pair<const char*, const char*>> kinds;
  if (command == "drop" || command == "force") kinds = {{"pads", "pads"}, {"soils", "soils"}};
  if (command == "campaign" || command == "lander") kinds = {{"scenarios", "scenarios"}, {"soils", "soils"}};
  if (command == "sweep" || command == "trade") kinds = {{"sweeps", "sweeps"}, {"pads", "pads"}, {"soils", "soils"}};
  if (command == "stability") kinds = {{"studies", "studies"}};
  std::string text;
  for (const auto& [kind, label] : kinds)
    text += std::string("\n  ") + label + " (" + io::DataDirectory() + "/" + kind + "): " + Joined(io::CatalogNames(kind));
  return text.empty() ? text : "\nKnown names:" + text;
}
}  // namespace

void AddHelpFooters(CLI::App& app) {
  // A required option has no default to show (CLI11 would print the variable's initial value).
  for (CLI::App* cmd : app.get_subcommands({}))
    for (CLI::Option* option : cmd->get_options())
      if (option->get_required()) option->default_str("");
  for (const CommandExamples& e : Examples()) {
    CLI::App* cmd = app.get_subcommand(e.command);
    const std::string name = e.command;
    cmd->footer([lines = e.lines, name] {
      std::string text = "Examples (from the repository root):";
      for (const char* line : lines) text += std::string("\n  ") + line;
      return text + KnownNames(name);
    });
  }
  app.footer("Run `touchdown COMMAND --help` for a command's options and examples; docs/ has the guides.");
}

void RejectUnknownCommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  const std::string typed = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* cmd : app.get_subcommands({})) names.push_back(cmd->get_name());
  for (const std::string& n : names)
    if (n == typed) return;
  throw InputError("unknown command '" + typed + "'" + io::DidYouMean(typed, names) + "; commands: " + Joined(names));
}

namespace {
// `text` with every byte outside printable ASCII as \xNN, so the message itself is UTF-8.
std::string Escaped(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out;
}
}  // namespace

void RejectNonUtf8Arguments(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (!IsValidUtf8(argv[i]))
      throw InputError("argument '" + Escaped(argv[i]) +
                       "' is not valid UTF-8 text: touchdown records paths and names in UTF-8 outputs "
                       "(JSON), so file names and names must be UTF-8; rename it");
}

}  // namespace touchdown::app

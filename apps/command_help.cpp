#include "apps/command_help.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/util/nearest_name.h"
#include "rft/input_error.h"
#include "rft/input_file.h"

namespace touchdown::app {

namespace {
// No line of a help text is wider (the options' names take the first 30 columns).
constexpr size_t kHelpWidth = 100;

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
        "touchdown force --pad c4 --soil fjs1_cp --depth 0.02 --tilt-deg 10 --velocity 0.3 0 -1"}},
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
        "touchdown calibrate --targets data/targets/sutoh2017_r1.yaml --out runs/r1.yaml --evaluate-only   # no fit"}},
      {"trade", {"touchdown trade data/sweeps/pad_trade.yaml --out runs/trade"}},
      {"lander",
       {"touchdown lander data/scenarios/lander_case_B.yaml --out runs/lander_B"}},
      {"synth", {"touchdown synth data/datasets/air_vs_vacuum_synthetic.synth.yaml --out runs/synthetic_dataset"}},
      {"diagnose", {"touchdown diagnose data/datasets/air_vs_vacuum_synthetic --out runs/diagnose"}},
      {"stability",
       {"touchdown stability data/studies/lunar_paper_lander.yaml --out runs/lunar_quick --samples 10   # a quick look"}},
      {"validate", {"touchdown validate --out runs/validation"}},
      {"import", {"touchdown import data/datasets/rig_daq_synthetic_raw/import.yaml --out runs/rig_daq"}},
      {"schema", {"touchdown schema pad   # the keys a pad file takes", "touchdown schema --json"}},
  };
  return examples;
}

std::string Joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

// `text` broken at spaces into lines of at most `width` characters (a longer word stays whole on
// its own line), each line after the first starting with `indent`; its own line breaks are kept.
std::string Wrapped(const std::string& text, size_t width, const std::string& indent = "") {
  std::string out;
  size_t line_start = 0;   // where the current output line begins in `out`
  bool line_empty = true;  // nothing but the indent on it yet
  const auto new_line = [&] {
    out += "\n" + indent;
    line_start = out.size() - indent.size();
    line_empty = true;
  };
  for (size_t begin = 0; begin <= text.size();) {
    const size_t end = std::min(text.find_first_of(" \n", begin), text.size());
    const std::string word = text.substr(begin, end - begin);
    if (!line_empty && out.size() - line_start + 1 + word.size() > width) new_line();
    if (!line_empty) out += ' ';
    out += word;
    line_empty = line_empty && word.empty();
    if (end < text.size() && text[end] == '\n') new_line();
    begin = end + 1;
  }
  return out;
}

// CLI11 2.1 prints every description on one line, however long; this formatter wraps them so
// that no line of any help text is wider than kHelpWidth.
class WrappingFormatter : public CLI::Formatter {
 public:
  std::string make_option_desc(const CLI::Option* option) const override {
    return Wrapped(CLI::Formatter::make_option_desc(option), kHelpWidth - get_column_width());
  }
  std::string make_subcommand(const CLI::App* sub) const override {
    std::stringstream out;
    CLI::detail::format_help(out, sub->get_display_name(true),
                             Wrapped(sub->get_description(), kHelpWidth - get_column_width()), get_column_width());
    return out.str();
  }
  std::string make_description(const CLI::App* app) const override {
    return Wrapped(CLI::Formatter::make_description(app), kHelpWidth);
  }
};

// An example line as help shows it: a comment that would make it too wide goes on the line above.
std::string ExampleLine(const std::string& line) {
  const size_t comment = line.find("   #");
  if (comment == std::string::npos || 2 + line.size() <= kHelpWidth) return "\n  " + line;
  return "\n  " + line.substr(line.find('#', comment)) + "\n  " + line.substr(0, comment);
}

// The positional input of the commands that run a bundled file by name.
std::optional<io::InputDocument> InputDocumentOf(const std::string& command) {
  if (command == "campaign") return io::InputDocument::kCampaign;
  if (command == "lander") return io::InputDocument::kLander;
  if (command == "sweep") return io::InputDocument::kSweep;
  if (command == "trade") return io::InputDocument::kTrade;
  if (command == "stability") return io::InputDocument::kStudy;
  return std::nullopt;
}

// One "Known names" entry: what and where, then the names wrapped under it (so where they break
// does not depend on how long the data directory's path is).
std::string NamesLine(const std::string& label, const std::string& folder, const std::vector<std::string>& names) {
  return "\n  " + label + " (" + folder + "):\n    " + Wrapped(Joined(names), kHelpWidth - 4, "    ");
}

// The catalogue names a command takes, read when help is shown (the data directory may be
// $TOUCHDOWN_DATA_DIR): its input's shelves, then the pads and soils its options name.
std::string KnownNames(const std::string& command) {
  std::string text;
  if (const std::optional<io::InputDocument> document = InputDocumentOf(command))
    for (const io::CatalogShelf& shelf : io::ShelvesOf(*document))
      text += NamesLine(shelf.label, io::DataDirectory() + "/" + shelf.kind, io::ShelfNames(shelf));
  std::vector<const char*> kinds;
  if (command == "drop" || command == "force") kinds = {"pads", "soils"};
  if (command == "campaign" || command == "lander") kinds = {"soils"};
  if (command == "sweep" || command == "trade") kinds = {"pads", "soils"};
  for (const char* kind : kinds)
    text += NamesLine(kind, io::DataDirectory() + "/" + kind, io::CatalogNames(kind));
  return text.empty() ? text : "\nKnown names:" + text;
}
}  // namespace

void AddHelpFooters(CLI::App& app) {
  const auto formatter = std::make_shared<WrappingFormatter>();
  app.formatter(formatter);
  // A required option has no default to show (CLI11 would print the variable's initial value).
  for (CLI::App* cmd : app.get_subcommands({})) {
    cmd->formatter(formatter);
    for (CLI::Option* option : cmd->get_options())
      if (option->get_required()) option->default_str("");
  }
  for (const CommandExamples& e : Examples()) {
    CLI::App* cmd = app.get_subcommand(e.command);
    const std::string name = e.command;
    cmd->footer([lines = e.lines, name] {
      std::string text = "Examples (from the repository root):";
      for (const char* line : lines) text += ExampleLine(line);
      return text + KnownNames(name);
    });
  }
  app.footer("Run `touchdown COMMAND --help` for a command's options and examples; docs/ has the guides.");
}

std::string ResolveCommandInput(const std::string& command, const std::string& name_or_path) {
  const std::optional<io::InputDocument> document = InputDocumentOf(command);
  return document ? io::ResolveInputDocument(*document, name_or_path) : name_or_path;
}

std::optional<std::string> UnknownOptionMessage(const CLI::App& app) {
  // What CLI11 left unparsed: the top level's own leftovers and those of the command it entered.
  std::vector<std::pair<const CLI::App*, std::string>> leftovers;
  for (const std::string& arg : app.remaining()) leftovers.push_back({&app, arg});
  for (const CLI::App* cmd : app.get_subcommands())
    for (const std::string& arg : cmd->remaining()) leftovers.push_back({cmd, arg});
  for (const auto& [cmd, arg] : leftovers) {
    // An option, not a negative number left over as a value.
    if (arg.size() < 2 || arg[0] != '-' || std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.') continue;
    const std::string typed = arg.substr(0, arg.find('='));
    std::vector<std::string> names;
    for (const CLI::Option* option : cmd->get_options()) {
      for (const std::string& n : option->get_lnames()) names.push_back("--" + n);
      for (const std::string& n : option->get_snames()) names.push_back("-" + n);
    }
    const std::string where = cmd == &app ? "touchdown" : "touchdown " + cmd->get_name();
    return MakeInputError("command line", typed, "unknown option of `" + where + "`" + io::DidYouMean(typed, names) +
                                                     "; `" + where + " --help` lists its options")
        .what();
  }
  return std::nullopt;
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

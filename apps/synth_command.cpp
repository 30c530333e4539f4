// touchdown synth SPEC.yaml --out DATASET_DIR: a measured-like SYNTHETIC dataset (drop_tests/dataset/synth.h).
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/dataset/synth.h"

namespace touchdown::app {

namespace {
struct SynthArgs {
  std::string spec, out;
};
}  // namespace

void AddSynthCommand(CLI::App& app) {
  auto args = std::make_shared<SynthArgs>();
  CLI::App* cmd = app.add_subcommand(
      "synth", "Make a SYNTHETIC measured-like dataset (noise, drift, quantisation; optionally a hidden effect)");
  cmd->add_option("spec", args->spec, "synth spec YAML (see docs/model_gap.md)")->required();
  cmd->add_option("--out", args->out, "dataset directory: new, empty, or an earlier dataset touchdown wrote (replaced whole when complete)")->required()->check(NonEmptyPath());
  cmd->callback([args] {
    const dataset::SynthRun run = dataset::SynthesizeToDirectory(args->spec, {args->out, {args->spec}});
    const dataset::SynthSpec& spec = run.spec;
    std::cout << "wrote SYNTHETIC dataset " << args->out << " (" << run.drops << " drops"
              << (spec.hidden_effect ? ", hidden effect " + spec.hidden_effect->id
                                     : spec.floor ? std::string(", hidden floor_stiffening") : std::string())
              << ")" << std::endl;
  });
}

}  // namespace touchdown::app

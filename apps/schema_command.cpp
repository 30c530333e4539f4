#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/dataset/daq_mapping.h"
#include "drop_tests/dataset/synth.h"
#include "drop_tests/formats/schema_doc.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/scenario/campaign.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/sweep/sweep_plan.h"
#include "drop_tests/sweep/trade.h"
#include "drop_tests/targets/targets_file.h"
#include "drop_tests/validation/validation_source.h"
#include "rft/input_error.h"

namespace touchdown::app {

namespace {
// Every input file's blocks, in the order docs/reference.md documents them.
std::vector<io::BlockDoc> AllBlocks() {
  std::vector<io::BlockDoc> all;
  for (std::vector<io::BlockDoc> (*schema)() :
       {io::PadFileSchema, io::SoilFileSchema, model::ModelFileSchema, scenario::CampaignSchema,
        scenario::LanderScenarioSchema, scenario::LanderFileSchema, sweep::SweepPlanSchema, sweep::TradeSchema,
        stability::StudySchema, targets::TargetsFileSchema, dataset::SynthSpecSchema, dataset::DaqMappingSchema,
        validation::ValidationSourceSchema})
    for (io::BlockDoc& block : schema()) all.push_back(std::move(block));
  return all;
}
// The file types, as `touchdown schema FILE_TYPE` takes them (a block's id starts with its type).
constexpr const char* kFileTypes =
    "pad, soil, model, campaign, lander_scenario, lander, sweep, study, targets, synth, import, validation_source, "
    "validation_model";
}  // namespace

void AddSchemaCommand(CLI::App& app) {
  auto file_type = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("schema",
                                     "Print the keys an input file takes (unit, range, default), block by block, "
                                     "from the loaders' own tables");
  cmd->add_option("file_type", *file_type, std::string("one of ") + kFileTypes + " (default: every file type)");
  cmd->add_flag("--json", *json, "as JSON (id, read_by, keys with unit, range and default)");
  cmd->callback([file_type, json] {
    std::vector<io::BlockDoc> blocks;
    for (io::BlockDoc& block : AllBlocks())
      if (file_type->empty() || block.id == *file_type || block.id.rfind(*file_type + ".", 0) == 0)
        blocks.push_back(std::move(block));
    if (blocks.empty())
      throw MakeInputError("schema", "file_type", "unknown file type '" + *file_type + "' (" + kFileTypes + ")");
    if (*json)
      std::cout << io::SchemaJson(blocks).dump(1) << "\n";
    else
      std::cout << io::SchemaMarkdown(blocks);
  });
}

}  // namespace touchdown::app

// The analysis of a finished study: its database read, summarised, and written out.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/sweep/sweep.h"
#include "rft/input_error.h"

namespace touchdown::stability {

std::vector<sweep::DropRecord> ReadStudyRecords(const Study& study, const std::string& out_dir) {
  const std::string db_path = sweep::ResultsDbPath(out_dir);
  if (!std::filesystem::is_regular_file(db_path)) throw MakeInputError(db_path, "", "no study results here");
  const sweep::ResultsDb db(db_path);
  const std::map<std::string, std::string> meta = db.Meta();
  const auto digest = meta.find("plan_digest");
  if (digest == meta.end() || digest->second != sweep::PlanDigest(study.plan))
    throw MakeInputError(db_path, "plan_digest", "holds the results of another study (or another --samples)");
  const int64_t stored = db.CountBelow(study.plan.size());
  if (stored < study.plan.size())
    throw MakeInputError(db_path, "drops",
                         std::to_string(study.plan.size() - stored) + " of " + std::to_string(study.plan.size()) +
                             " landings missing (a shard's run? merge the shards, then run `touchdown stability` on "
                             "the merged directory)");
  return db.ReadAll(/*with_traces=*/false);
}

StudySummary WriteStudyAnalysis(const Study& study, const std::string& out_dir, const StudyFollowUps& follow_ups,
                                const nlohmann::json* overrides) {
  const std::vector<sweep::DropRecord>& records = follow_ups.records;
  StudySummary summary = Summarise(study, records);
  summary.recheck = follow_ups.recheck;
  summary.joint_range = follow_ups.joint_range;
  summary.soil_pairing = follow_ups.soil_pairing;
  io::ReplaceDerivedOutputs(out_dir, io::OutputKind::kSweep, "summary.json", [&](const std::string& staging) {
    WriteStudyTables(study, summary, staging);
    WriteStudyPlots(study, summary, records, staging);
    io::WriteFileAtomically((std::filesystem::path(staging) / "summary.json").string(),
                            [&](std::ostream& out) {
                              nlohmann::json j = SummaryJson(study, summary);
                              if (overrides) j.update(*overrides);
                              out << j.dump(2) << '\n';
                            });
  });
  return summary;
}

}  // namespace touchdown::stability

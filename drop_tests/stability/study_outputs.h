#pragma once
// A stability study's outputs in its directory (beside results.sqlite), written together by
// WriteStudyAnalysis (docs/stability_studies.md lists them):
//   summary.json                 landings, tip-over probability and interval, percentiles, map, worst cases,
//                                the follow-ups' reports (recheck/, joint_range_x*/: study_followups.h)
//   percentiles.csv              metric, unit, landings, p50, p95, p99, max
//   tip_over_map.csv             per map cell: ranges, landings, tip-overs, probability, 95 % interval
//   plots/tip_over_map.{png,svg} the map with the p = 0.5 boundary and the landings
//   plots/exceedance.{png,svg}   P[X > x] of max tilt and of pad penetration
//   plots/histograms.{png,svg}   max tilt, final tilt, deepest pad penetration, peak leg load
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_followups.h"
#include "drop_tests/stability/study_summary.h"

namespace touchdown::stability {

void WriteStudyTables(const Study& study, const StudySummary& summary, const std::string& dir);
void WriteStudyPlots(const Study& study, const StudySummary& summary, const std::vector<sweep::DropRecord>& records,
                     const std::string& dir);

// The study's records from DIR/results.sqlite, in index order, which must hold every landing of
// the study (InputError naming the database and how many are missing, e.g. after a shard's run:
// merge the shards first).
std::vector<sweep::DropRecord> ReadStudyRecords(const Study& study, const std::string& out_dir);

// Replaces the analysis of the records the follow-ups leave (the re-checked landings the reference
// model's) as one whole (io::ReplaceDerivedOutputs): summary.json last, so its presence means the
// analysis is complete.
// `overrides`, when given, replaces or adds summary.json's top-level keys (a rare-event method's
// probability, interval and report over the analysis of its first level's landings).
StudySummary WriteStudyAnalysis(const Study& study, const std::string& out_dir, const StudyFollowUps& follow_ups,
                                const nlohmann::json* overrides = nullptr);

}  // namespace touchdown::stability

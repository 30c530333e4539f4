#pragma once
// Shared by the study tests: what `touchdown stability` does once a study's landings are in.
#include <string>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_followups.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/sweep/sweep.h"

namespace touchdown::test {

// Reads the landings, runs the follow-ups (quietly) and writes the analysis, as the command does.
inline stability::StudySummary AnalyseStudy(const stability::Study& study, const std::string& out) {
  sweep::SweepRunOptions quiet;
  quiet.progress = sweep::ProgressMode::kNone;
  return stability::WriteStudyAnalysis(
      study, out, stability::RunStudyFollowUps(study, stability::ReadStudyRecords(study, out), out, quiet));
}

}  // namespace touchdown::test

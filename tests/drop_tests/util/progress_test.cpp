#include "drop_tests/util/progress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <thread>

namespace touchdown::io {
namespace {

TEST(Progress, AQuickJobPrintsNothingUnlessSomethingWentWrong) {
  std::ostringstream out;
  {
    Progress p("campaign", "drops", 3, {ProgressMode::kLines, 10.0, /*quiet_s=*/60.0, &out});
    p.Add(3);
    p.Finish();
  }
  EXPECT_EQ(out.str(), "");
  Progress p("sweep", "drops", 2, {ProgressMode::kLines, 10.0, 60.0, &out});
  p.Note("drop d1 failed: reason");
  EXPECT_EQ(out.str(), "sweep: drop d1 failed: reason\n");
}

TEST(Progress, LinesShowDoneTotalPercentAndTheClosingLine) {
  std::ostringstream out;
  Progress p("export", "drops", 4, {ProgressMode::kLines, /*interval_s=*/0.0, /*quiet_s=*/0.0, &out}, 1);
  p.Add(1, ", 0 failed");
  EXPECT_NE(out.str().find("export: 2/4 drops (50.0%), "), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("ETA "), std::string::npos) << out.str();
  EXPECT_NE(out.str().find(", 0 failed\n"), std::string::npos) << out.str();
  p.SetTotal(5);
  p.Add(3);
  p.Finish(", done");
  const std::string last = out.str().substr(out.str().rfind("export: "));
  EXPECT_EQ(last.find("export: 5/5 drops (100.0%), "), 0u) << last;
  EXPECT_NE(last.find("elapsed 0:00:00, done\n"), std::string::npos) << last;
  p.Finish();  // once only
  EXPECT_EQ(out.str().substr(out.str().rfind("export: ")), last);
}

TEST(Progress, NoneIsSilentAndThreadsMayAddAtOnce) {
  std::ostringstream out;
  {
    Progress p("diagnose", "fits", 4000, {ProgressMode::kNone, 0.0, 0.0, &out});
    std::thread a([&] { for (int i = 0; i < 2000; ++i) p.Add(1); });
    std::thread b([&] { for (int i = 0; i < 2000; ++i) p.Add(1); });
    a.join();
    b.join();
    p.Note("ignored");
  }
  EXPECT_EQ(out.str(), "");
  std::ostringstream lines;
  {
    Progress p("diagnose", "fits", 4000, {ProgressMode::kLines, 1e9, 0.0, &lines});
    std::thread a([&] { for (int i = 0; i < 2000; ++i) p.Add(1); });
    std::thread b([&] { for (int i = 0; i < 2000; ++i) p.Add(1); });
    a.join();
    b.join();
  }  // the destructor closes
  EXPECT_NE(lines.str().find("diagnose: 4000/4000 fits (100.0%)"), std::string::npos) << lines.str();
}

TEST(Progress, CountsAreKeptForAnotherThreadWhateverTheMode) {
  ProgressCounts counts;
  {
    Progress p("sweep", "drops", 10, {ProgressMode::kNone, 0.0, 0.0, nullptr, &counts}, 3);
    EXPECT_EQ(counts.done.load(), 3);  // a resumed job starts with what was done before
    EXPECT_EQ(counts.total.load(), 10);
    std::thread a([&] { for (int i = 0; i < 2; ++i) p.Add(1); });
    std::thread b([&] { for (int i = 0; i < 2; ++i) p.Add(1); });
    a.join();
    b.join();
    EXPECT_EQ(counts.done.load(), 7);
    p.SetTotal(12);
    EXPECT_EQ(counts.total.load(), 12);
  }
  // A next stage of the job starts the counts anew.
  Progress next("sweep", "drops", 4, {ProgressMode::kNone, 0.0, 0.0, nullptr, &counts});
  EXPECT_EQ(counts.done.load(), 0);
  EXPECT_EQ(counts.total.load(), 4);
}

TEST(FormatDuration, HoursMinutesSecondsOrUnknown) {
  EXPECT_EQ(FormatDuration(0.4), "0:00:00");
  EXPECT_EQ(FormatDuration(3725.0), "1:02:05");
  EXPECT_EQ(FormatDuration(NAN), "?");
  EXPECT_EQ(FormatDuration(-1.0), "?");
}

}  // namespace
}  // namespace touchdown::io

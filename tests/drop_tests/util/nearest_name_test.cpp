#include "drop_tests/util/nearest_name.h"

#include <gtest/gtest.h>

namespace touchdown::io {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(EditDistance("", ""), 0);
  EXPECT_EQ(EditDistance("flat", "flat"), 0);
  EXPECT_EQ(EditDistance("flatt", "flat"), 1);    // insertion
  EXPECT_EQ(EditDistance("fat", "flat"), 1);      // deletion
  EXPECT_EQ(EditDistance("fjs1-lp", "fjs1_lp"), 1);  // substitution
  EXPECT_EQ(EditDistance("stabiltiy", "stability"), 1);  // neighbours swapped
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3);  // the textbook pair
  EXPECT_EQ(EditDistance("abc", ""), 3);
  EXPECT_EQ(EditDistance("ca", "abc"), 3);  // optimal string alignment: no edit of a swapped pair
}

TEST(NearestName, SuggestsOnlyWhatIsCloseEnoughToBeATypo) {
  const std::vector<std::string> pads = {"c4", "curved", "flat", "hex"};
  EXPECT_EQ(NearestName("flatt", pads), "flat");
  EXPECT_EQ(NearestName("curve", pads), "curved");
  EXPECT_EQ(NearestName("hexagon", pads), std::nullopt);  // 3 edits from hex: another word
  EXPECT_EQ(NearestName("cone", pads), std::nullopt);
  EXPECT_EQ(NearestName("c5", pads), "c4");  // short names allow one edit
  EXPECT_EQ(DidYouMean("flatt", pads), " (did you mean 'flat'?)");
  EXPECT_EQ(DidYouMean("zzz", pads), "");
  EXPECT_EQ(NearestName("x", {}), std::nullopt);
}

}  // namespace
}  // namespace touchdown::io

#pragma once
// The round trip every file format is held to: a loaded value, written and loaded again, is the
// same value; writing that again gives the same text (a fixed point), which loads to the same value.
#include <gtest/gtest.h>

#include <string>

#include "tests/scratch_dir_test.h"

namespace touchdown::testing_scratch {

// write(value, path), load(path) -> T, expect_same(a, b) records failures for any difference.
template <class T, class Write, class Load, class ExpectSame>
void ExpectRoundTrip(const T& loaded, const std::string& first, const std::string& second, Write write, Load load,
                     ExpectSame expect_same) {
  write(loaded, first);
  const T again = load(first);
  expect_same(loaded, again);
  write(again, second);
  EXPECT_EQ(Slurp(first), Slurp(second));
  expect_same(loaded, load(second));
}

}  // namespace touchdown::testing_scratch

#pragma once
// Checks of option values, worded as touchdown's other messages.
#include <CLI/CLI.hpp>

namespace touchdown::app {

// A number in [low, high]: "must be a number from 0 to 1, got 'abc'" for text (CLI11's own Range
// says "Value abc not in range 0 to 1"), and NaN refused (every comparison with it is false, so a
// plain range lets it through).
CLI::Validator NumberIn(double low, double high);

// A path that is not empty: `--trace ''` wrote nothing and said nothing, as if the option were
// left out.
CLI::Validator NonEmptyPath();

}  // namespace touchdown::app

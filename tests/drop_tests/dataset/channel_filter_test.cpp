// The CFC filters against the reference implementation (tools/cfc_reference.py: scipy's
// Butterworth design and filtfilt) on its stored test signal, to 1e-9 absolute on a unit-scale
// signal; and the properties the standard names: a constant passes, -3 dB at 5/3 CFC, phaseless.
#include "drop_tests/dataset/channel_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace touchdown::dataset {
namespace {

struct CfcFixture {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
};

CfcFixture ReadCfcFixture(const std::string& name) {
  std::ifstream in(std::string(TOUCHDOWN_SOURCE_DIR) + "/tests/fixtures/" + name);
  EXPECT_TRUE(in.good()) << name;
  CfcFixture f;
  std::string line;
  std::getline(in, line);  // the comment naming its generator
  std::getline(in, line);
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');) f.names.push_back(cell);
  f.columns.resize(f.names.size());
  while (std::getline(in, line)) {
    std::stringstream row(line);
    size_t k = 0;
    for (std::string cell; std::getline(row, cell, ',');) f.columns[k++].push_back(std::stod(cell));
  }
  return f;
}

TEST(ChannelFilter, MatchesTheReferenceImplementation) {
  for (const char* file : {"cfc_reference_10khz.csv", "cfc_reference_2khz.csv"}) {
    SCOPED_TRACE(file);
    const CfcFixture f = ReadCfcFixture(file);
    ASSERT_GE(f.names.size(), 4u);
    const std::vector<double>& t = f.columns[0];
    const std::vector<double>& x = f.columns[1];
    const double period = (t.back() - t.front()) / double(t.size() - 1);
    for (size_t k = 2; k < f.names.size(); ++k) {
      SCOPED_TRACE(f.names[k]);
      const std::optional<ChannelFilter> filter = ParseChannelFilter(f.names[k]);
      ASSERT_TRUE(filter);
      const std::vector<double> y = ApplyChannelFilter(x, *filter, period);
      double worst = 0;
      for (size_t i = 0; i < y.size(); ++i) worst = std::max(worst, std::abs(y[i] - f.columns[k][i]));
      EXPECT_LT(worst, 1e-9);
    }
  }
}

TEST(ChannelFilter, ConstantPassesAndNoneIsIdentity) {
  const std::vector<double> x(500, 3.25);
  for (ChannelFilter filter : {ChannelFilter::kCfc60, ChannelFilter::kCfc180, ChannelFilter::kCfc600, ChannelFilter::kCfc1000}) {
    const std::vector<double> y = ApplyChannelFilter(x, filter, 1e-4);
    for (double v : y) EXPECT_NEAR(v, 3.25, 1e-12);
  }
  const std::vector<double> ramp = {1, 2, 4, 8};
  EXPECT_EQ(ApplyChannelFilter(ramp, ChannelFilter::kNone, 1e-3), ramp);
}

// |H|^4 of the two passes at 5/3 CFC is one half (-3 dB) when the sample rate is far above the
// class (the bilinear transform's warping vanishes); the standard's 2.0775 puts it there.
TEST(ChannelFilter, MinusThreeDecibelsAtFiveThirdsOfTheClass) {
  for (ChannelFilter filter : {ChannelFilter::kCfc60, ChannelFilter::kCfc180, ChannelFilter::kCfc600, ChannelFilter::kCfc1000}) {
    const double cfc = ChannelFrequencyClass(filter), period = 1.0 / (1000.0 * cfc);
    const CfcCoefficients c = CfcCoefficientsFor(cfc, period);
    const std::complex<double> z = std::polar(1.0, 2.0 * M_PI * (5.0 / 3.0) * cfc * period);
    const std::complex<double> h = (c.a0 + c.a1 / z + c.a2 / (z * z)) / (1.0 - c.b1 / z - c.b2 / (z * z));
    EXPECT_NEAR(std::pow(std::abs(h), 4), 0.5, 0.002) << ChannelFilterName(filter);
    EXPECT_NEAR(c.a0 + c.a1 + c.a2, 1.0 - c.b1 - c.b2, 1e-15);  // unit gain at 0 Hz
  }
}

// Forward then backward: a symmetric pulse stays centred where it was.
TEST(ChannelFilter, IsPhaseless) {
  std::vector<double> x(2001, 0.0);
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::exp(-std::pow((double(i) - 1000.0) / 20.0, 2));
  const std::vector<double> y = ApplyChannelFilter(x, ChannelFilter::kCfc180, 1e-4);
  double moment = 0, mass = 0;
  for (size_t i = 0; i < y.size(); ++i) moment += double(i) * y[i], mass += y[i];
  EXPECT_NEAR(moment / mass, 1000.0, 1e-6);
}

TEST(ChannelFilter, NamesAndSampleRates) {
  for (const char* name : {"none", "cfc60", "cfc180", "cfc600", "cfc1000"})
    EXPECT_EQ(ChannelFilterName(*ParseChannelFilter(name)), std::string(name));
  EXPECT_FALSE(ParseChannelFilter("CFC60"));
  EXPECT_FALSE(ParseChannelFilter("cfc100"));
  EXPECT_DOUBLE_EQ(MinSampleRateHz(ChannelFilter::kCfc600), 6000.0);
}

}  // namespace
}  // namespace touchdown::dataset

#pragma once
// The impact-test channel filter classes (CFC 60, 180, 600, 1000) of SAE J211-1 (MAR95, Appendix
// C) and ISO 6487, as `touchdown import` applies them to a DAQ channel (docs/import.md).
//
// The standard's filter is a 2-pole Butterworth low-pass, the bilinear transform of the analogue
// prototype pre-warped at wd = 2 pi CFC 2.0775, run as the difference equation
//   Y[t] = a0 X[t] + a1 X[t-1] + a2 X[t-2] + b1 Y[t-1] + b2 Y[t-2]
// with (T the sample period, wa = sin(wd T/2) / cos(wd T/2), D = 1 + sqrt(2) wa + wa^2)
//   a0 = wa^2 / D,  a1 = 2 a0,  a2 = a0,  b1 = -2 (wa^2 - 1) / D,  b2 = (-1 + sqrt(2) wa - wa^2) / D,
// once forward and once backward over the record: 4 poles, no phase shift, -3 dB at about
// 5/3 CFC (100, 300, 1000 and 1650 Hz).
//
// Start-up and end: the standard leaves the recursion's first two past values to the user and
// asks for data well beyond the region of interest (about 10 ms). Each pass here starts in the
// steady state of its first input sample (X[-1] = X[-2] = Y[-1] = Y[-2] = X[0]; the backward pass
// the same at the forward output's last sample): a constant passes unchanged, and a record that
// begins in free fall and ends at rest (every drop) starts and ends without a transient beyond
// the noise of that one sample. It is scipy.signal.filtfilt(b, a, x, padtype=None), which is how
// tools/cfc_reference.py checks it (tests/drop_tests/dataset/channel_filter_test.cpp).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rft/enum_names.h"

namespace touchdown::dataset {

enum class ChannelFilter { kNone, kCfc60, kCfc180, kCfc600, kCfc1000 };
// The names a mapping file uses (rft/enum_names.h).
inline constexpr std::array<EnumName<ChannelFilter>, 5> kChannelFilterNames{{{ChannelFilter::kCfc60, "cfc60"},
                                                                            {ChannelFilter::kCfc180, "cfc180"},
                                                                            {ChannelFilter::kCfc600, "cfc600"},
                                                                            {ChannelFilter::kCfc1000, "cfc1000"},
                                                                            {ChannelFilter::kNone, "none"}}};

const char* ChannelFilterName(ChannelFilter filter);
std::optional<ChannelFilter> ParseChannelFilter(const std::string& name);
// "cfc60, cfc180, cfc600, cfc1000 or none", for messages.
std::string ChannelFilterChoices();
// The class's number (60, 180, 600, 1000), 0 for none.
double ChannelFrequencyClass(ChannelFilter filter);
// The lowest sample rate the class is applied at: 10 CFC, six times its -3 dB frequency 5/3 CFC, as
// the standards' sampling requirement is usually stated; below it the bilinear transform's
// warping and the anti-alias margin leave the class's corridor.
double MinSampleRateHz(ChannelFilter filter);

struct CfcCoefficients {
  double a0 = 0, a1 = 0, a2 = 0, b1 = 0, b2 = 0;
};
// The standard's coefficients (above) for class `cfc` at the sample period `period_s`.
CfcCoefficients CfcCoefficientsFor(double cfc, double period_s);

// The phaseless filter (forward pass, then backward) of `x` sampled every `period_s`; kNone
// returns `x`. Assumes a uniform period and at least one sample.
std::vector<double> ApplyChannelFilter(const std::vector<double>& x, ChannelFilter filter, double period_s);

}  // namespace touchdown::dataset

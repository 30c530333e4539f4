// The sensor model (drop_tests/dataset/sensor_model.h) against closed forms. A second-order
// section y'' + 2 zeta w y' + w^2 y = w^2 F, y(0) = y'(0) = 0, driven by a force that rises
// linearly to F0 over T and then stays, answers
//   y(t) = F0 / T [y_r(t) - y_r(t - T)],   y_r(t) = t - 2 zeta / w + exp(-zeta w t) (2 zeta / w cos(w_d t)
//          + (2 zeta^2 - 1) / w_d sin(w_d t)) for t > 0 (0 before), w_d = w sqrt(1 - zeta^2),
// the response to a unit ramp. A load cell is that section at its own frequency and damping; a
// Butterworth low-pass of order 2 is it at its cutoff with zeta = 1/sqrt(2). A filter passes a
// constant unchanged (unit DC gain). (A ramp, not a step: the fine grid reads a jump at one of its
// points as half a grid step early, which is a timing below a hundredth of a sample, not an error
// of the sections.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "drop_tests/dataset/sensor_model.h"

namespace touchdown::dataset {
namespace {

constexpr double kF0 = 100.0;

constexpr double kRiseS = 1e-3;

// The rig's record of a pad whose force rises linearly to F0 over kRiseS from touchdown and then
// stays: samples every 0.1 ms to 60 ms (the linear interpolation between them is the ramp exactly).
pad::RigDropResult Ramp() {
  pad::RigDropResult r;
  for (int i = 0; i <= 600; ++i) r.trace.push_back({1e-4 * i, 0.0, 0.0, kF0 * std::min(1e-4 * i / kRiseS, 1.0)});
  r.time_to_rest_s = 0.06;
  return r;
}

double UnitRampResponse(double t, double w, double zeta) {
  if (t <= 0.0) return 0.0;
  const double wd = w * std::sqrt(1.0 - zeta * zeta);
  return t - 2.0 * zeta / w +
         std::exp(-zeta * w * t) * (2.0 * zeta / w * std::cos(wd * t) + (2.0 * zeta * zeta - 1.0) / wd * std::sin(wd * t));
}

double RampResponse(double t, double hz, double zeta) {
  const double w = 2.0 * std::numbers::pi * hz;
  return kF0 / kRiseS * (UnitRampResponse(t, w, zeta) - UnitRampResponse(t - kRiseS, w, zeta));
}

// Sample times of a 5 kHz record from 5 ms before touchdown to 50 ms after.
std::vector<double> Times() {
  std::vector<double> t;
  for (int i = -25; i <= 250; ++i) t.push_back(2e-4 * i);
  return t;
}

// The record sampled at instants through `sensor` against the section's ramp response: within
// 2e-3 of F0 (the fine grid's bilinear sections: FilterGridStep).
void ExpectRampResponse(const SensorModel& sensor, double hz, double zeta) {
  const std::vector<double> t = Times();
  const DatasetTrace tr = RecordedTrace(Ramp(), 9.81, {}, t, sensor, 2e-4);
  ASSERT_EQ(tr.size(), t.size());
  double worst = 0.0;
  for (size_t i = 0; i < t.size(); ++i) worst = std::max(worst, std::abs(tr.force_N[i] - RampResponse(t[i], hz, zeta)));
  EXPECT_LT(worst, 2e-3 * kF0) << DescribeSensor(sensor);
}

TEST(SensorModel, ALoadCellRingsAsItsSecondOrderResponse) {
  SensorModel s{pad::SensorSampling::kInstantaneous};
  s.load_cell_hz = 612.0;
  s.load_cell_damping = 0.05;
  ExpectRampResponse(s, 612.0, 0.05);
  s.load_cell_hz = 1500.0;
  s.load_cell_damping = 0.3;
  ExpectRampResponse(s, 1500.0, 0.3);
}

TEST(SensorModel, ASecondOrderButterworthIsTheSectionAtItsCutoff) {
  SensorModel s{pad::SensorSampling::kInstantaneous, 2, 400.0};
  ExpectRampResponse(s, 400.0, 1.0 / std::sqrt(2.0));
}

TEST(SensorModel, FiltersPassAConstantAndNoForceBeforeTouchdown) {
  for (const int order : {2, 4, 8}) {
    SensorModel s{pad::SensorSampling::kInstantaneous, order, 800.0, 900.0, 0.1};
    const std::vector<double> t = Times();
    const DatasetTrace tr = RecordedTrace(Ramp(), 9.81, {}, t, s, 2e-4);
    EXPECT_NEAR(tr.force_N.back(), kF0, 1e-6 * kF0) << order;  // 50 ms: every transient decayed
    for (size_t i = 0; i < t.size() && t[i] < 0.0; ++i) EXPECT_EQ(tr.force_N[i], 0.0) << order << " " << t[i];
  }
}

TEST(SensorModel, WithoutFiltersItIsTheSampleBySampleRecord) {
  const std::vector<double> t = Times();
  for (const pad::SensorSampling sampling : {pad::SensorSampling::kInstantaneous, pad::SensorSampling::kPeriodMean}) {
    const DatasetTrace tr = RecordedTrace(Ramp(), 9.81, {}, t, SensorModel{sampling}, 2e-4);
    for (size_t i = 0; i < t.size(); ++i) {
      const pad::RecordedSample r = pad::RecordedSampleOf(Ramp(), 9.81, {}, t[i], sampling, 2e-4);
      EXPECT_EQ(tr.force_N[i], r.force_N) << i;
    }
  }
}

TEST(SensorModel, SimulationRateIsTwiceTheSampleRateWithinItsBounds) {
  EXPECT_EQ(SimulationRateFor_Hz(1000.0), 4e3);
  EXPECT_EQ(SimulationRateFor_Hz(5000.0), 1e4);
  EXPECT_EQ(SimulationRateFor_Hz(50000.0), 2e4);
}

}  // namespace
}  // namespace touchdown::dataset

#pragma once
// The names of pad::SensorSampling in files and on the command line (synth's `sensor_sampling`,
// diagnose's and compare's --sensor-sampling, and the Python arguments): one list for all of them;
// and a simulated drop recorded through a sensor on a measured drop's sample times, the one way
// compare and diagnose both record a simulation.
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/dataset/dataset.h"
#include "lander/pad/effect_soil_response.h"

namespace touchdown::dataset {

const char* SensorSamplingName(pad::SensorSampling sampling);
// Every name, in the enum's order ("period_mean", "instantaneous").
std::vector<std::string> SensorSamplingNames();
// The sampling a name stands for; nullopt for any other text.
std::optional<pad::SensorSampling> ParseSensorSampling(const std::string& name);
// "period_mean or instantaneous": what a message says is allowed.
std::string SensorSamplingChoices();

// A simulated drop as the rig's sensors record it at the recorded times `t_s`: t_s, and at each the
// penetration and force of pad::RecordedSampleOf (the sensor_offset of `terms` applied; with
// kPeriodMean the mean over sample_period_s, a measured trace's SamplePeriod).
DatasetTrace RecordedTrace(const pad::RigDropResult& result, double gravity_m_s2, const rft::EffectTerms& terms,
                           const std::vector<double>& t_s, pad::SensorSampling sampling, double sample_period_s);

}  // namespace touchdown::dataset

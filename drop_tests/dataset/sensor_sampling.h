#pragma once
// The names of pad::SensorSampling in files and on the command line (synth's `sensor_sampling`,
// diagnose's --sensor-sampling, touchdown.diagnose's sensor_sampling): one list for all of them.
#include <optional>
#include <string>
#include <vector>

#include "lander/pad/effect_soil_response.h"

namespace touchdown::dataset {

const char* SensorSamplingName(pad::SensorSampling sampling);
// Every name, in the enum's order ("period_mean", "instantaneous").
std::vector<std::string> SensorSamplingNames();
// The sampling a name stands for; nullopt for any other text.
std::optional<pad::SensorSampling> ParseSensorSampling(const std::string& name);
// "period_mean or instantaneous": what a message says is allowed.
std::string SensorSamplingChoices();

}  // namespace touchdown::dataset

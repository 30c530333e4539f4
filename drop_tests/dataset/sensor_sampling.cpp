#include "drop_tests/dataset/sensor_sampling.h"

namespace touchdown::dataset {

namespace {
constexpr pad::SensorSampling kAll[] = {pad::SensorSampling::kPeriodMean, pad::SensorSampling::kInstantaneous};
}  // namespace

const char* SensorSamplingName(pad::SensorSampling sampling) {
  return sampling == pad::SensorSampling::kPeriodMean ? "period_mean" : "instantaneous";
}

std::vector<std::string> SensorSamplingNames() {
  std::vector<std::string> names;
  for (pad::SensorSampling s : kAll) names.push_back(SensorSamplingName(s));
  return names;
}

std::optional<pad::SensorSampling> ParseSensorSampling(const std::string& name) {
  for (pad::SensorSampling s : kAll)
    if (name == SensorSamplingName(s)) return s;
  return std::nullopt;
}

std::string SensorSamplingChoices() {
  std::string out;
  for (const std::string& n : SensorSamplingNames()) out += (out.empty() ? "" : " or ") + n;
  return out;
}

}  // namespace touchdown::dataset

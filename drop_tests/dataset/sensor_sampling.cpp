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

DatasetTrace RecordedTrace(const pad::RigDropResult& result, double gravity_m_s2, const rft::EffectTerms& terms,
                           const std::vector<double>& t_s, pad::SensorSampling sampling, double sample_period_s) {
  DatasetTrace out;
  out.t_s = t_s;
  out.penetration_m.reserve(t_s.size());
  out.force_N.reserve(t_s.size());
  for (const double t : t_s) {
    const pad::RecordedSample s = pad::RecordedSampleOf(result, gravity_m_s2, terms, t, sampling, sample_period_s);
    out.penetration_m.push_back(s.penetration_m);
    out.force_N.push_back(s.force_N);
  }
  return out;
}

}  // namespace touchdown::dataset

#include "drop_tests/dataset/sensor_sampling.h"

#include <array>

#include "rft/enum_names.h"

namespace touchdown::dataset {

namespace {
constexpr std::array<EnumName<pad::SensorSampling>, 2> kNames{
    {{pad::SensorSampling::kPeriodMean, "period_mean"}, {pad::SensorSampling::kInstantaneous, "instantaneous"}}};
}  // namespace

const char* SensorSamplingName(pad::SensorSampling sampling) { return NameIn(kNames, sampling); }

std::vector<std::string> SensorSamplingNames() {
  return NameList(kNames);
}

std::optional<pad::SensorSampling> ParseSensorSampling(const std::string& name) { return FindName(kNames, name); }

std::string SensorSamplingChoices() { return NameChoices(kNames); }

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

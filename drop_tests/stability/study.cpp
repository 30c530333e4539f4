#include "drop_tests/stability/study.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "drop_tests/drop/drop_request.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"

namespace touchdown::stability {

namespace {
using sweep::SweepParam;

constexpr int kMaxBins = limits::kMaxStudyMapBins;  // rft/physical_limits.h
constexpr int kMaxListed = limits::kMaxStudyListed;

// The range a parameter takes over the plan, in file units; nullopt when the plan does not vary it.
std::optional<std::pair<double, double>> PlanRange(const sweep::SweepPlan& plan, SweepParam p) {
  std::vector<double> values;
  for (const sweep::SweepAxis& axis : plan.grid)
    if (axis.param == p) values = axis.values;
  for (const sweep::SweepRandom& r : plan.random)
    if (r.param == p) values = r.choice ? r.values : std::vector<double>{r.low, r.high};
  if (values.empty()) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const double a = sweep::SweepParamFromSi(p, *lo), b = sweep::SweepParamFromSi(p, *hi);
  if (!(a < b)) return std::nullopt;
  return std::make_pair(a, b);
}

// What a YAML node holds, for a message: 'text' for a scalar, else "a list of N" or "a mapping".
std::string GivenAs(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list of " + std::to_string(n.size());
  return n.IsMap() ? "a mapping" : "nothing";
}

// Why parameter `p` cannot be a map axis: a map bins a range, so the plan must give it two values
// or more (a grid axis with one value, or a choice of one, has no range to bin).
std::string NoRangeReason(const sweep::SweepPlan& plan, SweepParam p, const std::string& name) {
  for (const sweep::SweepAxis& axis : plan.grid)
    if (axis.param == p)
      return "'" + name + "' takes the single value " + io::FormatNumber(sweep::SweepParamFromSi(p, axis.values.front())) +
             " in the grid: a map axis needs two values or more (a list, or a from/to range)";
  for (const sweep::SweepRandom& r : plan.random)
    if (r.param == p)
      return "'" + name + "' takes a single value in random: a map axis needs a range (uniform: [low, high]) or a "
             "choice of two values or more";
  return "'" + name + "' does not vary in this study: give it two values or more in grid or random";
}

MapAxis ReadMapAxis(const io::YamlFields& map, const std::string& key, int bins, const sweep::SweepPlan& plan) {
  const std::string name = map.String(key);
  const std::optional<SweepParam> p = sweep::SweepParamFromKey(name);
  if (!p || !sweep::IsLanderNumber(*p))
    map.Fail(key, "must be a number parameter of a lander sweep (e.g. slope_deg, horizontal_speed_m_s), got '" +
                      name + "'");
  const auto range = PlanRange(plan, *p);
  if (!range) map.Fail(key, NoRangeReason(plan, *p, name));
  MapAxis axis;
  axis.param = *p;
  axis.low = range->first;
  axis.high = range->second;
  axis.bins = bins;
  return axis;
}

// `contours: [p1, p2, ...]`: the probabilities the map figure draws contours at, each in (0, 1),
// increasing, at most kMaxMapContours of them (a single number is one level).
std::vector<double> ReadContours(const io::YamlFields& map) {
  if (!map.Has("contours")) return kDefaultMapContours;
  const std::vector<double> levels = map.NumberList("contours", /*allow_zero=*/false);
  if (levels.size() > static_cast<size_t>(kMaxMapContours))
    map.Fail("contours", "must list at most " + std::to_string(kMaxMapContours) + " probabilities, got " +
                             std::to_string(levels.size()));
  for (size_t i = 0; i < levels.size(); ++i) {
    const std::string path = map.Path("contours") + "[" + std::to_string(i) + "]";
    if (!(levels[i] < 1.0))
      throw MakeInputError(map.file(), path, "must be a probability below 1, got " + io::FormatNumber(levels[i]));
    if (i > 0 && !(levels[i] > levels[i - 1]))
      throw MakeInputError(map.file(), path, "must be above the level before it (" + io::FormatNumber(levels[i - 1]) +
                                                 "): the levels increase, got " + io::FormatNumber(levels[i]));
  }
  return levels;
}

// `max_drawn_landings: N`: the most landings the map figure draws one mark each for (0: none).
int64_t ReadMaxDrawnLandings(const io::YamlFields& map) {
  if (!map.Has("max_drawn_landings")) return kDefaultMaxDrawnLandings;
  const double v = map.NonNegative("max_drawn_landings");
  if (v != std::floor(v) || v > limits::kSamples.high)  // a study's landings are at most kSamples' bound
    map.Fail("max_drawn_landings", "must be a whole number from 0 to " + io::FormatNumber(limits::kSamples.high) +
                                       ", got " + io::FormatNumber(v));
  return static_cast<int64_t>(v);
}

// The `study` block's keys, and its blocks' (soil_uncertainty's are its file's, soil_pairing's
// `samples`).
const std::vector<std::string> kStudyKeys{"map", "worst_cases", "max_tip_over_cases", "recheck",
                                          "joint_range_sensitivity", "soil_uncertainty", "soil_pairing"};
const std::vector<std::string> kMapKeys{"x", "y", "bins", "contours", "max_drawn_landings"};
const std::vector<std::string> kRecheckKeys{"rtol", "tilt_margin_deg", "unsettled"};
// The follow-ups' angle margins (their own messages; the range documented from here).
constexpr limits::Range kMargin_deg{"deg", 0.0, 90.0, false};
const io::NumberKey kTiltMargin{"tilt_margin_deg", io::Sign::kAny, &kMargin_deg, nullptr,
                                RecheckSettings{}.tilt_margin_deg};
const io::NumberKey kScreenMargin{"screen_margin_deg", io::Sign::kAny, &kMargin_deg, nullptr,
                                  kDefaultJointRangeScreenDeg};
const std::vector<std::string> kJointRangeKeys{"samples", "screen_margin_deg"};

StudyMap ReadMap(const io::YamlFields& study, const sweep::SweepPlan& plan) {
  const io::YamlFields map = study.Child("map");
  map.RequireOnly(kMapKeys);
  int bins[2] = {10, 10};
  if (map.Has("bins")) {
    const YAML::Node n = map.node()["bins"];
    if (!n.IsSequence() || n.size() != 2)
      map.Fail("bins", "must be [x bins, y bins] (two whole numbers from 2 to " + std::to_string(kMaxBins) + "), got " +
                           GivenAs(n));
    for (int i = 0; i < 2; ++i) {
      double v = 0.0;
      if (!n[i].IsScalar() || !YAML::convert<double>::decode(n[i], v) || v != std::floor(v) || v < 2 || v > kMaxBins)
        throw MakeInputError(map.file(), map.Path("bins") + "[" + std::to_string(i) + "]",
                             "must be a whole number from 2 to " + std::to_string(kMaxBins) + ", got " +
                                 GivenAs(n[i]));
      bins[i] = static_cast<int>(v);
    }
  }
  StudyMap m{ReadMapAxis(map, "x", bins[0], plan), ReadMapAxis(map, "y", bins[1], plan)};
  if (m.x.param == m.y.param) map.Fail("y", "must differ from x");
  m.contours = ReadContours(map);
  m.max_drawn_landings = ReadMaxDrawnLandings(map);
  return m;
}

int ReadCount(const io::YamlFields& study, const std::string& key, int fallback) {
  if (!study.Has(key)) return fallback;
  const double v = study.NonNegative(key);
  if (v != std::floor(v) || v > kMaxListed)
    study.Fail(key, "must be a whole number from 0 to " + std::to_string(kMaxListed) + ", got " + io::FormatNumber(v));
  return static_cast<int>(v);
}
// The integrator tolerance the study's landings run at (the lander scenario's).
double ScenarioRtol(const sweep::SweepPlan& plan) {
  return plan.lander ? plan.lander->options.integrator.rtol : lander::LanderRunOptions{}.integrator.rtol;
}

// `recheck: none`, or `recheck: {rtol, tilt_margin_deg, unsettled}` (each optional): the reference
// tolerance must be tighter than the scenario's, the margin an angle from 0 to 90 deg.
RecheckSettings ReadRecheck(const io::YamlFields& study, RecheckSettings r, double scenario_rtol) {
  if (!study.Has("recheck")) return r;
  if (study.node()["recheck"].IsScalar()) {
    if (study.String("recheck") != "none")
      study.Fail("recheck", "must be none or a mapping {rtol, tilt_margin_deg, unsettled}, got '" +
                                study.String("recheck") + "'");
    r.enabled = false;
    return r;
  }
  const io::YamlFields f = study.Child("recheck");
  f.RequireOnly(kRecheckKeys);
  if (f.Has("unsettled")) r.unsettled = f.Bool("unsettled");
  if (f.Has("rtol")) {
    r.rtol = f.Number("rtol");
    if (!(r.rtol > 0.0 && r.rtol < scenario_rtol))
      f.Fail("rtol", "must be above 0 and below the study scenario's rtol " + io::FormatNumber(scenario_rtol) +
                         " (the reference is the tighter one), got " + io::FormatNumber(r.rtol));
  }
  if (f.Has(kTiltMargin.key)) {
    r.tilt_margin_deg = f.Number(kTiltMargin.key);
    if (!limits::Within(*kTiltMargin.range, r.tilt_margin_deg))
      f.Fail(kTiltMargin.key, "must be from 0 to 90 deg, got " + io::FormatNumber(r.tilt_margin_deg));
  }
  return r;
}

// A follow-up's `KEY: none` (false), or `KEY: {samples: K, ...}` (true; K, 1 to 1e9, into `samples`;
// `keys`: every key the mapping may have).
bool ReadFollowUpSamples(const io::YamlFields& study, const std::string& key, std::optional<int64_t>& samples,
                         const std::vector<std::string>& keys = {"samples"}) {
  if (study.node()[key].IsScalar()) {
    std::string names;
    for (const std::string& k : keys) names += (names.empty() ? "" : ", ") + k;
    if (study.String(key) != "none") study.Fail(key, "must be none or a mapping {" + names + "}, got '" + study.String(key) + "'");
    return false;
  }
  const io::YamlFields f = study.Child(key);
  f.RequireOnly(keys);
  if (f.Has("samples")) {
    const double v = f.Number("samples");
    limits::Require(limits::kSamples, v, f.file(), f.Path("samples"));
    if (v != std::floor(v)) f.Fail("samples", "must be a whole number, got " + io::FormatNumber(v));
    samples = static_cast<int64_t>(v);
  }
  return true;
}

// `joint_range_sensitivity: none`, or `{samples: K, screen_margin_deg: M}` (defaults 1000 and
// kDefaultJointRangeScreenDeg; `screen_margin_deg: none` runs all K).
JointRangeSettings ReadJointRange(const io::YamlFields& study) {
  JointRangeSettings j;
  const std::string key = "joint_range_sensitivity";
  if (!study.Has(key)) return j;
  std::optional<int64_t> samples;
  j.enabled = ReadFollowUpSamples(study, key, samples, kJointRangeKeys);
  j.samples = samples.value_or(j.samples);
  if (!j.enabled) return j;
  const io::YamlFields f = study.Child(key);
  if (!f.Has("screen_margin_deg")) return j;
  if (f.node()["screen_margin_deg"].IsScalar() && f.String("screen_margin_deg") == "none") {
    j.screen_margin_deg.reset();
    return j;
  }
  const double m = f.Number(kScreenMargin.key);
  if (!limits::Within(*kScreenMargin.range, m))
    f.Fail("screen_margin_deg", "must be none or from 0 to 90 deg, got " + io::FormatNumber(m));
  j.screen_margin_deg = m;
  return j;
}

// `soil_pairing: none`, or `{samples: K}` (default: every landing); only beside soil_uncertainty.
SoilPairingSettings ReadSoilPairing(const io::YamlFields& study) {
  SoilPairingSettings p;
  const std::string key = "soil_pairing";
  if (!study.Has(key)) return p;
  if (!study.Has("soil_uncertainty"))
    study.Fail(key, "pairs the drawn soils with their best values: it needs study.soil_uncertainty");
  p.enabled = ReadFollowUpSamples(study, key, p.samples);
  return p;
}
}  // namespace

std::vector<io::BlockDoc> StudySchema() {
  const std::string read_by = "drop_tests/stability/study.cpp";
  return {io::MakeBlock("study", read_by, io::PlainKeyDocs(kStudyKeys)),
          io::MakeBlock("study.map", read_by, io::PlainKeyDocs(kMapKeys)),
          io::MakeBlock("study.recheck", read_by, io::DocsWith(kRecheckKeys, {kTiltMargin})),
          io::MakeBlock("study.joint_range_sensitivity", read_by, io::DocsWith(kJointRangeKeys, {kScreenMargin})),
          io::MakeBlock("study.soil_uncertainty.soil", "drop_tests/stability/soil_uncertainty_file.cpp",
                        io::PlainKeyDocs(SoilUncertaintyEntryKeys()))};
}

Study LoadStudy(const std::string& path, const std::string& model_override, std::optional<int64_t> samples_override) {
  return LoadStudy(path, model_override, samples_override, drop::RequestNaming{"", true});
}

Study LoadStudy(const std::string& path, const std::string& model_override, std::optional<int64_t> samples_override,
                const drop::RequestNaming& naming) {
  Study study;
  study.plan = sweep::LoadSweepPlan(path, model_override);
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  if (f.String("type") != "stability")
    f.Fail("type", "must be 'stability' for `touchdown stability` (a plain sweep runs with `touchdown sweep`)");
  study.samples_in_file = study.plan.samples;
  if (samples_override) {
    if (study.plan.random.empty())
      throw MakeInputError(naming.context, naming.Field("samples"), "the study " + path + " has no random block whose samples it could set");
    limits::Require(limits::kSamples, static_cast<double>(*samples_override), naming.context, naming.Field("samples"));
    study.plan.samples = *samples_override;
    study.samples_override = samples_override;
  }
  // The reference tolerance by default: 1e-8, or a hundredth of a scenario's already as tight.
  if (!(study.recheck.rtol < ScenarioRtol(study.plan))) study.recheck.rtol = ScenarioRtol(study.plan) / 100.0;
  if (f.Has("study")) {
    const io::YamlFields s = f.Child("study");
    s.RequireOnly(kStudyKeys);
    if (s.Has("map")) study.map = ReadMap(s, study.plan);
    study.worst_cases = ReadCount(s, "worst_cases", study.worst_cases);
    study.max_tip_over_cases = ReadCount(s, "max_tip_over_cases", study.max_tip_over_cases);
    study.recheck = ReadRecheck(s, study.recheck, ScenarioRtol(study.plan));
    study.joint_range = ReadJointRange(s);
    study.soil_pairing = ReadSoilPairing(s);
    if (s.Has("soil_uncertainty")) {
      study.soil_uncertainty = ReadSoilUncertainty(s, study.plan);
      AttachSoilUncertainty(study.plan, *study.soil_uncertainty);
    }
  }
  return study;
}

std::string AxisLabel(SweepParam p) {
  switch (p) {
    case SweepParam::kImpactSpeed: return "vertical touchdown speed [m/s]";
    case SweepParam::kGravity: return "gravity [m/s^2]";
    case SweepParam::kHorizontalSpeed: return "horizontal speed [m/s]";
    case SweepParam::kRoll: return "roll at touchdown [deg]";
    case SweepParam::kPitch: return "pitch at touchdown [deg]";
    case SweepParam::kSlope: return "slope [deg]";
    case SweepParam::kDownhillAzimuth: return "downhill azimuth [deg]";
    case SweepParam::kYawToSlope: return "yaw relative to the slope [deg]";
    case SweepParam::kHorizontalAzimuth: return "horizontal velocity azimuth [deg]";
    case SweepParam::kRateX: return "angular rate about body x [deg/s]";
    case SweepParam::kRateY: return "angular rate about body y [deg/s]";
    case SweepParam::kRateZ: return "angular rate about body z [deg/s]";
    default: return sweep::SweepParamKey(p);
  }
}

}  // namespace touchdown::stability

#include "drop_tests/stability/study_summary.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/json_number.h"
#include "drop_tests/model/model_file.h"

namespace touchdown::stability {

namespace {
using sweep::DropRecord;

std::vector<MapCell> EmptyMap(const StudyMap& map) {
  std::vector<MapCell> cells;
  const double wx = (map.x.high - map.x.low) / map.x.bins, wy = (map.y.high - map.y.low) / map.y.bins;
  for (int ix = 0; ix < map.x.bins; ++ix)
    for (int iy = 0; iy < map.y.bins; ++iy) {
      MapCell c;
      c.ix = ix;
      c.iy = iy;
      c.x_low = map.x.low + ix * wx;
      c.x_high = ix + 1 == map.x.bins ? map.x.high : map.x.low + (ix + 1) * wx;
      c.y_low = map.y.low + iy * wy;
      c.y_high = iy + 1 == map.y.bins ? map.y.high : map.y.low + (iy + 1) * wy;
      cells.push_back(c);
    }
  return cells;
}

// The bin of value v on an axis: [low + k w, low + (k + 1) w), the last bin closed at high.
int Bin(const MapAxis& axis, double v) {
  const int k = static_cast<int>(std::floor((v - axis.low) / (axis.high - axis.low) * axis.bins));
  return std::clamp(k, 0, axis.bins - 1);
}

std::vector<MapCell> TipOverMap(const Study& study, const std::vector<DropRecord>& records) {
  if (!study.map) return {};
  std::vector<MapCell> cells = EmptyMap(*study.map);
  for (const DropRecord& r : records) {
    if (!r.ok) continue;
    const int ix = Bin(study.map->x, MapCoordinate(study, study.map->x, r.index));
    const int iy = Bin(study.map->y, MapCoordinate(study, study.map->y, r.index));
    MapCell& c = cells[static_cast<size_t>(ix) * study.map->y.bins + iy];
    ++c.landings;
    c.tipped += Tipped(r);
  }
  for (MapCell& c : cells) {
    c.probability = c.landings > 0 ? static_cast<double>(c.tipped) / c.landings : std::nan("");
    c.interval = ClopperPearson(c.tipped, c.landings);
  }
  return cells;
}
}  // namespace

const std::vector<StudyMetric>& StudyMetrics() {
  static const std::vector<StudyMetric> metrics = {
      {"max_tilt_deg", "deg", "largest tilt of the body from the vertical during the landing",
       [](const DropRecord& r) { return r.max_tilt_deg; }},
      {"final_tilt_deg", "deg", "tilt of the body from the vertical at rest (or at the end)",
       [](const DropRecord& r) { return r.final_tilt_deg; }},
      {"pad1_final_penetration_m", "m", "pad 1's final penetration (pads clockwise from front-left)",
       [](const DropRecord& r) { return r.pad_final_penetration_m[0]; }},
      {"pad2_final_penetration_m", "m", "pad 2's final penetration",
       [](const DropRecord& r) { return r.pad_final_penetration_m[1]; }},
      {"pad3_final_penetration_m", "m", "pad 3's final penetration",
       [](const DropRecord& r) { return r.pad_final_penetration_m[2]; }},
      {"pad4_final_penetration_m", "m", "pad 4's final penetration",
       [](const DropRecord& r) { return r.pad_final_penetration_m[3]; }},
      {"max_pad_penetration_m", "m", "the deepest pad's final penetration",
       [](const DropRecord& r) { return r.final_penetration_m; }},
      {"peak_pad_force_N", "N", "the largest soil force on any pad during the landing",
       [](const DropRecord& r) { return r.peak_force_N; }},
      {"peak_leg_force_N", "N",
       "peak axial leg load, compression (absorber legs: the absorber's force; rigid legs: the pad's soil force "
       "along the leg axis, the pad's inertia neglected), at the trace's samples",
       [](const DropRecord& r) { return r.peak_leg_force_N; }},
      {"max_body_deceleration_m_s2", "m/s^2", "largest upward acceleration of the body's centre of mass",
       [](const DropRecord& r) { return r.max_deceleration_m_s2; }},
      {"max_absorber_stroke_m", "m", "largest absorber stroke of any leg (none without absorbers)",
       [](const DropRecord& r) { return r.max_stroke_m; }},
      {"max_joint_swing_deg", "deg",
       "largest swing of any pad on its ball joint (its axis from the body's z axis); past 90 deg it turned beyond "
       "edge-on",
       [](const DropRecord& r) { return r.max_joint_swing_deg; }},
  };
  return metrics;
}

double MapCoordinate(const Study& study, const MapAxis& axis, int64_t index) {
  return sweep::SweepParamFromSi(axis.param, sweep::ParamValue(study.plan.DropAt(index), axis.param));
}

bool Tipped(const DropRecord& r) { return r.tipped_over == 1.0; }

std::optional<LegLoadLimitCount> CountOverLegLoadLimit(const Study& study, const std::vector<DropRecord>& records) {
  if (!study.plan.lander) return std::nullopt;
  // Every leg carries the lander file's one limit (legs.load_limit_N); none: infinite.
  const double limit = study.plan.lander->lander.legs[0].load_limit_N;
  if (!std::isfinite(limit)) return std::nullopt;
  LegLoadLimitCount c;
  c.load_limit_N = limit;
  int64_t landings = 0;
  for (const DropRecord& r : records) {
    if (!r.ok) continue;
    ++landings;
    const bool over = r.peak_leg_force_N > limit;
    c.over_limit += over;
    c.tipped_or_over_limit += over || Tipped(r);
  }
  c.over_limit_interval = ClopperPearson(c.over_limit, landings);
  c.tipped_or_over_limit_interval = ClopperPearson(c.tipped_or_over_limit, landings);
  return c;
}

bool StayedUp(const DropRecord& r) { return r.ok && !Tipped(r); }

bool MarginAgreesWithOutcome(const DropRecord& r) {
  if (!r.ok || std::isnan(r.min_stability_margin_m)) return true;
  return (r.min_stability_margin_m <= 0.0) == Tipped(r);
}

StudySummary Summarise(const Study& study, const std::vector<DropRecord>& records) {
  StudySummary s;
  s.planned = study.plan.size();
  std::vector<const DropRecord*> ok;  // the landings that stayed up: percentiles and closest calls
  for (const DropRecord& r : records) {
    if (!r.ok) {
      if (s.failed++ == 0) s.first_failure = r.drop_id + ": " + r.failure;
      continue;
    }
    ++s.landings;
    s.tipped += Tipped(r);
    s.margin_checked += !std::isnan(r.min_stability_margin_m);
    if (!MarginAgreesWithOutcome(r) && s.margin_disagreements++ < study.max_tip_over_cases)
      s.margin_disagreeing.push_back(r.drop_id);
    const bool past_edge_on = r.max_joint_swing_deg > kEdgeOnSwingDeg;  // NaN (an older database): no
    s.swung_past_edge_on += past_edge_on;
    s.tipped_swung_past_edge_on += past_edge_on && Tipped(r);
    if (Tipped(r) && static_cast<int>(s.tip_overs.size()) < study.max_tip_over_cases) s.tip_overs.push_back(r);
    if (Tipped(r)) continue;
    ok.push_back(&r);
    s.unsettled += std::isnan(r.time_to_rest_s);
  }
  s.tip_over_probability = s.landings > 0 ? static_cast<double>(s.tipped) / s.landings : std::nan("");
  s.interval = ClopperPearson(s.tipped, s.landings);
  s.leg_load_limit = CountOverLegLoadLimit(study, records);
  for (const StudyMetric& m : StudyMetrics()) {
    std::vector<double> v;
    for (const DropRecord* r : ok)
      if (!std::isnan(m.value(*r))) v.push_back(m.value(*r));
    s.metrics.push_back({&m, static_cast<int64_t>(v.size()), Percentile(v, 50), Percentile(v, 95), Percentile(v, 99),
                         Percentile(v, 100)});
  }
  // The worst tilts: largest first, ties in index order (stable, so the list never depends on threads).
  std::stable_sort(ok.begin(), ok.end(), [](const DropRecord* a, const DropRecord* b) {
    return a->max_tilt_deg > b->max_tilt_deg;
  });
  for (size_t i = 0; i < ok.size() && static_cast<int>(i) < study.worst_cases; ++i) s.worst_tilt.push_back(*ok[i]);
  s.map = TipOverMap(study, records);
  if (study.soil_uncertainty) s.soil_split = SplitBySoil(*study.soil_uncertainty, records);
  return s;
}

namespace {
// The signed difference a - b of two azimuths, wrapped to (-180, 180] deg.
double AzimuthDifferenceDeg(double a_deg, double b_deg) {
  double d = std::remainder(a_deg - b_deg, 360.0);
  return d == -180.0 ? 180.0 : d;
}

nlohmann::json TipOverJson(const DropRecord& r) {
  const int legs = static_cast<int>(r.pad_soil.size()), from = static_cast<int>(r.tip_over_edge);
  nlohmann::json j = {{"edge_pads", {from, from % legs + 1}},
                      {"edge_pad_soils", {r.pad_soil[from - 1], r.pad_soil[from % legs]}},
                      {"fell_towards_azimuth_deg", io::FiniteOrNull(r.tip_over_azimuth_deg)}};
  // On a slope: where it fell relative to downhill (0 downhill, +-180 uphill), and relative to its
  // horizontal velocity at touchdown (0: straight on, where the landing carried it).
  if (std::isfinite(r.downhill_azimuth_deg) && r.slope_deg > 0.0)
    j["fell_from_downhill_deg"] = AzimuthDifferenceDeg(r.tip_over_azimuth_deg, r.downhill_azimuth_deg);
  if (std::isfinite(r.horizontal_azimuth_deg) && r.horizontal_speed_m_s > 0.0)
    j["fell_from_horizontal_velocity_deg"] = AzimuthDifferenceDeg(r.tip_over_azimuth_deg, r.horizontal_azimuth_deg);
  return j;
}
}  // namespace

nlohmann::json LandingJson(const DropRecord& r) {
  nlohmann::json j = {{"drop_id", r.drop_id},
          {"drop_index", r.index},
          {"tipped_over", r.tipped_over == 1.0},
          {"max_tilt_deg", io::FiniteOrNull(r.max_tilt_deg)},
          {"final_tilt_deg", io::FiniteOrNull(r.final_tilt_deg)},
          {"min_stability_margin_m", io::FiniteOrNull(r.min_stability_margin_m)},
          {"max_pad_penetration_m", io::FiniteOrNull(r.final_penetration_m)},
          {"conditions",
           {{"impact_speed_m_s", io::FiniteOrNull(r.impact_speed_m_s)},
            {"horizontal_speed_m_s", io::FiniteOrNull(r.horizontal_speed_m_s)},
            {"horizontal_azimuth_deg", io::FiniteOrNull(r.horizontal_azimuth_deg)},
            {"roll_deg", io::FiniteOrNull(r.roll_deg)},
            {"pitch_deg", io::FiniteOrNull(r.pitch_deg)},
            {"slope_deg", io::FiniteOrNull(r.slope_deg)},
            {"downhill_azimuth_deg", io::FiniteOrNull(r.downhill_azimuth_deg)},
            {"yaw_relative_to_slope_deg", io::FiniteOrNull(r.yaw_relative_to_slope_deg)},
            {"angular_rate_deg_s",
             {io::FiniteOrNull(r.angular_rate_deg_s[0]), io::FiniteOrNull(r.angular_rate_deg_s[1]), io::FiniteOrNull(r.angular_rate_deg_s[2])}},
            {"gravity_m_s2", io::FiniteOrNull(r.gravity_m_s2)},
            {"pad", r.pad},
            {"soil", r.soil},
            {"pad_soils", r.pad_soil},
            {"ground_case", r.ground_case}}}};
  // 1-4 as written; anything else (a database from elsewhere) lists no edge rather than a wrong pad.
  if (r.tip_over_edge >= 1.0 && r.tip_over_edge <= static_cast<double>(r.pad_soil.size()) &&
      r.tip_over_edge == std::floor(r.tip_over_edge))
    j["tip_over"] = TipOverJson(r);
  return j;
}

namespace {
// A tip-over probability with its interval; with no landing there is none, so the key is left
// out (never null, which a reader would take for a number) and "reason" says why.
void AddProbability(nlohmann::json& out, int64_t landings, double probability, const BinomialInterval& interval,
                    const std::string& reason) {
  if (landings > 0 && std::isfinite(probability)) {
    out["tip_over_probability"] = probability;
    out["tip_over_probability_interval_95"] = {interval.low, interval.high};
  } else {
    out["tip_over_probability_reason"] = reason;
  }
}

// A metric's percentiles over `count` landings; with none, no percentile keys and a reason.
nlohmann::json PercentilesJson(const MetricPercentiles& m) {
  nlohmann::json out = {{"unit", m.metric->unit}, {"meaning", m.metric->meaning}, {"landings", m.count}};
  if (m.count == 0) {
    out["reason"] = "no completed landing that stayed up has this value";
    return out;
  }
  out["p50"] = io::FiniteOrNull(m.p50);
  out["p95"] = io::FiniteOrNull(m.p95);
  out["p99"] = io::FiniteOrNull(m.p99);
  out["max"] = io::FiniteOrNull(m.max);
  return out;
}

nlohmann::json MapJson(const Study& study, const StudySummary& s) {
  if (!study.map) return nullptr;
  nlohmann::json cells = nlohmann::json::array();
  for (const MapCell& c : s.map) {
    nlohmann::json cell = {{"x", {c.x_low, c.x_high}}, {"y", {c.y_low, c.y_high}}, {"landings", c.landings},
                           {"tipped_over", c.tipped}};
    AddProbability(cell, c.landings, c.probability, c.interval, "no landing fell in this cell");
    cells.push_back(cell);
  }
  const StudyMap& m = *study.map;
  return {{"x", sweep::SweepParamKey(m.x.param)}, {"y", sweep::SweepParamKey(m.y.param)},
          {"x_range", {m.x.low, m.x.high}},       {"y_range", {m.y.low, m.y.high}},
          {"bins", {m.x.bins, m.y.bins}},         {"contours", m.contours},
          {"max_drawn_landings", m.max_drawn_landings}, {"cells", cells}};
}
// Every soil the study's landings can stand on, with the model choices it carries, so that a
// lunar study records how its soils were scaled to the study's gravity.
nlohmann::json SoilModelsJson(const Study& study) {
  std::vector<rft::SoilParameters> soils = study.plan.soils;
  if (study.plan.lander) {
    const scenario::LanderGroundSpec& g = study.plan.lander->ground;
    std::vector<std::string> names{g.default_soil};
    for (const scenario::LanderPatchSpec& p : g.patches) names.push_back(p.soil);
    if (g.soil_field) names.insert(names.end(), g.soil_field->soils.begin(), g.soil_field->soils.end());
    for (const std::string& name : names) {
      const rft::SoilParameters soil = io::LoadSoil(name);
      soils.push_back(study.plan.model ? model::ApplyModel(*study.plan.model, soil) : soil);
    }
  }
  nlohmann::json out = nlohmann::json::object();
  for (const rft::SoilParameters& soil : soils)
    out[soil.name] = {{"law", rft::LawKindName(soil.rft_law_3d)},
                      {"gravity_scaling", rft::GravityScalingName(soil.gravity_scaling)},
                      {"dynamic_lambda", soil.dynamic_term ? nlohmann::json(soil.dynamic_lambda) : nlohmann::json()}};
  return out;
}

}  // namespace

nlohmann::json SummaryJson(const Study& study, const StudySummary& s) {
  nlohmann::json percentiles = nlohmann::json::object();
  for (const MetricPercentiles& m : s.metrics) percentiles[m.metric->name] = PercentilesJson(m);
  nlohmann::json worst = nlohmann::json::array(), tips = nlohmann::json::array();
  // A listed landing carries the soil parameters it drew, when the study draws them.
  const auto listed = [&study](const DropRecord& r) {
    nlohmann::json j = LandingJson(r);
    if (study.soil_uncertainty) j["soil_parameters"] = DrawnParametersJson(*study.soil_uncertainty, r.index);
    return j;
  };
  for (const DropRecord& r : s.worst_tilt) worst.push_back(listed(r));
  for (const DropRecord& r : s.tip_overs) tips.push_back(listed(r));
  nlohmann::json summary = {{"study", study.plan.name},
          {"landings", s.landings},
          {"soils", SoilModelsJson(study)},
          {"landings_planned", s.planned},
          {"landings_failed", s.failed},
          {"samples", study.plan.samples},
          {"samples_in_study_file", study.samples_in_file},
          {"samples_overridden", study.samples_override.has_value()},
          {"tipped_over", s.tipped},
          {"landings_unsettled", s.unsettled},
          {"landings_unsettled_meaning",
           "landings that neither came to rest nor tipped over within the scenario's duration (counted as not "
           "tipped over; a longer simulation.duration_s settles them)"},
          {"landings_swung_past_edge_on", s.swung_past_edge_on},
          {"tip_overs_swung_past_edge_on", s.tipped_swung_past_edge_on},
          {"swung_past_edge_on_meaning",
           "landings (and tip-overs among them) in which a pad swung more than 90 deg on its ball joint, beyond "
           "edge-on: no real joint turns so far, so their answers depend on the joints' range, which a lander "
           "without legs.cone_limit leaves free (docs/stability_studies.md, \"The pads' ball joints\")"},
          {"interval_method", "exact binomial (Clopper-Pearson), two-sided 95 %, 2.5 % in each tail"},
          {"percentiles", percentiles},
          {"percentile_definition",
           "linear interpolation between order statistics: x(h), h = (n - 1) q / 100 on the sorted values "
           "(Hyndman & Fan definition 7); max = the largest value; over the completed landings that did not tip "
           "over (a tipped lander's final attitude and depths describe no landing)"},
          {"map", MapJson(study, s)},
          {"worst_max_tilt", worst},
          {"worst_max_tilt_meaning", "the landings that stayed up with the largest max tilt (closest calls), largest first"},
          {"tip_overs", tips},
          {"tip_overs_listed", static_cast<int64_t>(s.tip_overs.size())}};
  const std::string none = s.failed > 0 ? "no landing completed: all " + std::to_string(s.failed) +
                                              " failed (first: " + s.first_failure + ")"
                                        : "no landing completed";
  AddProbability(summary, s.landings, s.tip_over_probability, s.interval, none);
  summary["tip_over_margin"] = {
      {"definition",
       "min_stability_margin_m: the least horizontal distance of the lander's centre of mass inside the support "
       "polygon of the pads' ball-joint centres over the landing (samples and events), the quantity whose crossing "
       "of zero is the tip-over event: <= 0 exactly when the lander tipped over"},
      {"landings_checked", s.margin_checked},
      {"disagreements", s.margin_disagreements},
      {"disagreeing_landings", s.margin_disagreeing}};
  if (s.leg_load_limit && s.landings > 0) {
    const LegLoadLimitCount& c = *s.leg_load_limit;
    const double n = static_cast<double>(s.landings);
    summary["leg_load_limit"] = {
        {"load_limit_N", c.load_limit_N},
        {"landings_over_limit", c.over_limit},
        {"over_limit_probability", c.over_limit / n},
        {"over_limit_probability_interval_95", {c.over_limit_interval.low, c.over_limit_interval.high}},
        {"tipped_or_over_limit_probability", c.tipped_or_over_limit / n},
        {"tipped_or_over_limit_probability_interval_95",
         {c.tipped_or_over_limit_interval.low, c.tipped_or_over_limit_interval.high}},
        {"meaning",
         "landings whose peak axial leg load (compression, the largest of any leg over the trace's samples; a peak "
         "between samples is not seen) passed the lander file's legs.load_limit_N, and those that tipped over or "
         "passed it; a check only: each landing ran on as if its legs held"}};
  }
  if (s.recheck) summary["recheck"] = RecheckJson(*s.recheck);
  if (s.joint_range) summary["joint_range_sensitivity"] = JointRangeJson(*s.joint_range);
  if (study.soil_uncertainty) {
    summary["soil_uncertainty"] = SoilSplitJson(*study.soil_uncertainty, s.soil_split);
    if (s.soil_pairing) summary["soil_uncertainty"]["paired_with_best_values"] = SoilPairingJson(*s.soil_pairing);
  }
  return summary;
}

}  // namespace touchdown::stability

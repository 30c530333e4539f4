#include "drop_tests/stability/study_followups.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/json_number.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/stability/study_summary.h"
#include "lander/multibody/static_stability.h"
#include "rft/units.h"

namespace touchdown::stability {

namespace {
using sweep::DropRecord;

// The lander as a drop of the plan builds it (the pad of every pad the plan names, else the
// scenario's), standing level at zero stroke: body and pads aligned with the world.
double TipAngleOfLander(const scenario::LanderScenario& sc) {
  const lander::LanderModel model = scenario::BuildLanderModel(sc);  // no soil needed
  const lander::StateLayout layout(model);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(layout.size);
  y.segment<4>(layout.quat_WB()) << 1.0, 0.0, 0.0, 0.0;
  for (int i = 0; i < lander::kNumLegs; ++i) y.segment<4>(layout.quat_WP(i)) << 1.0, 0.0, 0.0, 0.0;
  double smallest = INFINITY;
  for (const lander::EdgeTipping& e : lander::EdgeTippings(model, layout, y))
    smallest = std::min(smallest, e.tip_angle_rad);
  return smallest / units::kDeg;
}

// Every joint's cone half angle x factor (stiffness and damping unchanged).
void ScaleCones(scenario::LanderSpec& spec, double factor) {
  if (spec.layout.cone) spec.layout.cone->half_angle_rad *= factor;
  for (scenario::LanderLegSpec& leg : spec.legs)
    if (leg.cone) leg.cone->half_angle_rad *= factor;
}

// The records stored in `dir`'s database for the drops `indices` (ascending), by index.
std::map<int64_t, DropRecord> ReadStored(const std::string& dir, const std::vector<int64_t>& indices) {
  std::map<int64_t, DropRecord> out;
  const sweep::ResultsDb db(sweep::ResultsDbPath(dir), sweep::ResultsDb::Access::kReadOnly);
  db.ForEach(
      [&](const DropRecord& r) {
        if (std::binary_search(indices.begin(), indices.end(), r.index)) out.emplace(r.index, r);
      },
      /*with_traces=*/false);
  return out;
}

// Runs `indices` of `plan` into `dir` (a follow-up's sweep); adds its counts to `f`. False when stopped.
bool RunFollowUp(const sweep::SweepPlan& plan, const std::vector<int64_t>& indices, const std::string& dir,
                 const sweep::SweepRunOptions& options, StudyFollowUps& f) {
  sweep::SweepRunOptions o = options;
  o.shard = {};
  o.indices = indices;
  const sweep::SweepRunSummary run = sweep::RunSweep(plan, dir, o);
  f.computed += run.computed;
  f.already_done += run.already_done;
  f.stop_signal = run.stop_signal;
  return run.stop_signal == 0;
}

int64_t CountCompleted(const std::vector<DropRecord>& records) {
  return std::count_if(records.begin(), records.end(), [](const DropRecord& r) { return r.ok; });
}

JointRangeVariant Variant(double factor, double half_angle_deg, const std::vector<int64_t>& indices,
                          const std::map<int64_t, DropRecord>& records, const std::map<int64_t, DropRecord>& study) {
  JointRangeVariant v;
  v.factor = factor;
  v.half_angle_deg = half_angle_deg * factor;
  for (int64_t i : indices) {
    const auto it = records.find(i);
    if (it == records.end() || !it->second.ok) {
      ++v.failed;
      continue;
    }
    ++v.landings;
    v.tipped += Tipped(it->second);
    const DropRecord& s = study.at(i);
    v.differs_from_study += s.ok && Tipped(s) != Tipped(it->second);
  }
  v.probability = v.landings > 0 ? static_cast<double>(v.tipped) / v.landings : std::nan("");
  v.interval = ClopperPearson(v.tipped, v.landings);
  return v;
}

// The joint-range report before anything runs: the landings at the stops and whether to run.
JointRangeReport JointRangeTrigger(const Study& study, const std::vector<DropRecord>& records) {
  JointRangeReport j;
  j.enabled = study.joint_range.enabled;
  j.half_angle_deg = ConeHalfAngleDeg(study.plan);
  j.cone_limit = !std::isnan(j.half_angle_deg);
  j.landings = CountCompleted(records);
  if (j.cone_limit)
    j.at_stops = std::count_if(records.begin(), records.end(),
                               [&](const DropRecord& r) { return r.ok && ReachedStops(r, j.half_angle_deg); });
  j.at_stops_fraction = j.landings > 0 ? static_cast<double>(j.at_stops) / j.landings : 0.0;
  if (!j.cone_limit)
    j.reason = "the lander has no cone limit on its ball joints (legs.cone_limit): no range to vary";
  else if (!j.enabled)
    j.reason = "turned off (study.joint_range_sensitivity: none)";
  else if (j.at_stops_fraction <= kJointRangeTrigger)
    j.reason = "the pads reached their stops in " + io::FormatNumber(100.0 * j.at_stops_fraction) +
               " % of the landings, not more than 5 %";
  return j;
}

// ", pads at the file's N segments" when the reference model re-meshes the study's pads.
std::string ReferenceMeshNote(const Study& study) {
  if (!study.plan.lander || study.plan.lander->pad_angular_segments == 0) return "";
  return ", pads at their file's " + std::to_string(study.plan.lander->pad_file_angular_segments) +
         " rim segments instead of " + std::to_string(study.plan.lander->pad_angular_segments) +
         (study.plan.lander->pad_rim == geom::RimPolygon::kAreaPreserving ? " area-preserving" : "");
}
}  // namespace

double StandingTipAngleDeg(const sweep::SweepPlan& plan) {
  if (!plan.lander) return std::nan("");
  scenario::LanderScenario sc = *plan.lander;
  bool varies_pad = false;
  for (const sweep::SweepAxis& a : plan.grid) varies_pad = varies_pad || a.param == sweep::SweepParam::kPad;
  for (const sweep::SweepRandom& r : plan.random) varies_pad = varies_pad || r.param == sweep::SweepParam::kPad;
  varies_pad = varies_pad || plan.fixed[static_cast<int>(sweep::SweepParam::kPad)].has_value();
  if (!varies_pad || plan.pads.empty()) return TipAngleOfLander(sc);
  double smallest = INFINITY;
  for (const io::PadSpec& pad : plan.pads) {
    scenario::LanderScenario with_pad = sc;
    with_pad.lander = scenario::LanderSpecWithPad(sc.lander, pad);
    smallest = std::min(smallest, TipAngleOfLander(with_pad));
  }
  return smallest;
}

bool NeedsRecheck(const DropRecord& r, double tip_angle_deg, const RecheckSettings& s) {
  if (!r.ok) return false;
  const bool unsettled = !Tipped(r) && std::isnan(r.time_to_rest_s);  // as Summarise counts them
  return Tipped(r) || (s.unsettled && unsettled) || r.max_tilt_deg >= tip_angle_deg - s.tilt_margin_deg;
}

bool ReachedStops(const DropRecord& r, double half_angle_deg) { return r.max_joint_swing_deg > half_angle_deg; }

bool MayTipAtAnotherRange(const DropRecord& r, double tip_angle_deg, const JointRangeSettings& s) {
  if (!s.screen_margin_deg || !r.ok || Tipped(r)) return true;
  const bool unsettled = std::isnan(r.time_to_rest_s);  // as Summarise counts them (not tipped here)
  return unsettled || r.max_tilt_deg >= tip_angle_deg - *s.screen_margin_deg;
}

sweep::SweepPlan RecheckPlan(const Study& study) {
  sweep::SweepPlan plan = study.plan;
  // The reference model's pads are meshed as their file says: a study that lands coarser pads
  // (simulation.pad_angular_segments, a resolution like rtol) is re-checked at the file's.
  plan.lander = scenario::AtPadFileMesh(*plan.lander);
  plan.lander->options.integrator.rtol = study.recheck.rtol;
  // ... and its pads' spins are resolved as every other state (simulation.pad_spin_tolerance_factor
  // is the fast model's, a resolution like rtol).
  plan.lander->options.pad_spin_tolerance_factor = 1.0;
  // A scenario that sets a scalar atol keeps it in proportion to rtol (the tighter reference);
  // without one the absolute tolerances are rtol times each state's scale already.
  if (!plan.lander->options.scale_tolerances)
    plan.lander->options.integrator.atol *= study.recheck.rtol / study.plan.lander->options.integrator.rtol;
  // Appended: the study's own variant (its soil draws) holds for its re-checks too.
  plan.variant += std::string(plan.variant.empty() ? "" : ";") + "recheck: reference model, rtol " +
                  io::FormatNumber(study.recheck.rtol) +
                  (study.plan.lander->pad_angular_segments > 0 ? ", pads as their file" : "") +
                  (study.plan.lander->options.pad_spin_tolerance_factor != 1.0 ? ", pads' spins at every state's tolerance"
                                                                               : "");
  return plan;
}

sweep::SweepPlan JointRangePlan(const Study& study, double factor) {
  sweep::SweepPlan plan = study.plan;
  ScaleCones(plan.lander->lander, factor);
  plan.variant += std::string(plan.variant.empty() ? "" : ";") + "joint range: every cone half angle x" + io::FormatNumber(factor);
  return plan;
}

double ConeHalfAngleDeg(const sweep::SweepPlan& plan) {
  if (!plan.lander) return std::nan("");
  double smallest = INFINITY;
  for (const scenario::LanderLegSpec& leg : plan.lander->lander.legs)
    if (leg.cone) smallest = std::min(smallest, leg.cone->half_angle_rad);
  return std::isfinite(smallest) ? smallest / units::kDeg : std::nan("");
}

std::vector<int64_t> JointRangeIndices(const Study& study) {
  const int64_t n = study.plan.size();
  return SpreadIndices(n, std::min(study.joint_range.samples, n));
}

std::vector<int64_t> SpreadIndices(int64_t n, int64_t k) {
  std::vector<int64_t> out;
  out.reserve(static_cast<size_t>(k));
  // floor(j n / k) without overflow for n up to 1e9 x a grid: in long double, exact below 2^64.
  for (int64_t j = 0; j < k; ++j)
    out.push_back(static_cast<int64_t>(static_cast<long double>(j) * n / k));
  return out;
}

std::string RecheckDir(const std::string& out_dir) { return (std::filesystem::path(out_dir) / "recheck").string(); }

std::string JointRangeDir(const std::string& out_dir, double factor) {
  return (std::filesystem::path(out_dir) / ("joint_range_x" + io::FormatNumber(factor))).string();
}

RecheckReport ApplyRechecks(const Study& study, double tip_angle_deg, std::vector<DropRecord>& records,
                            const std::vector<DropRecord>& reference, std::vector<DropRecord>* fast) {
  RecheckReport rep;
  rep.enabled = study.recheck.enabled;
  rep.rtol = study.recheck.rtol;
  if (study.plan.lander) {
    const scenario::LanderScenario& sc = *study.plan.lander;
    rep.fast_pad_angular_segments = io::PadRimSegments(sc.lander.pad);
    rep.reference_pad_angular_segments =
        sc.pad_angular_segments > 0 ? sc.pad_file_angular_segments : rep.fast_pad_angular_segments;
  }
  rep.tip_angle_deg = tip_angle_deg;
  rep.margin_deg = study.recheck.tilt_margin_deg;
  rep.unsettled = study.recheck.unsettled;
  std::map<int64_t, size_t> position;
  for (size_t k = 0; k < records.size(); ++k) position[records[k].index] = k;
  for (const DropRecord& ref : reference) {  // index order
    DropRecord& r = records.at(position.at(ref.index));
    ++rep.rechecked;
    if (!ref.ok) {  // no reference answer: the fast one stands, and the report says so
      ++rep.reference_failed;
      rep.reference_failed_landings.push_back(r.drop_id);
      continue;
    }
    rep.largest_max_tilt_change_deg =
        std::max(rep.largest_max_tilt_change_deg, std::abs(ref.max_tilt_deg - r.max_tilt_deg));
    if (Tipped(ref) != Tipped(r)) {
      ++rep.outcome_changed;
      rep.changed_landings.push_back(r.drop_id);
    }
    if (fast) fast->push_back(r);
    r = ref;
  }
  return rep;
}

namespace {
// Re-checks `records` (a run of `study`'s plan into `out_dir`) in RecheckDir(out_dir): false when stopped.
bool Recheck(const Study& study, double tip_angle_deg, std::vector<DropRecord>& records, const std::string& out_dir,
             const sweep::SweepRunOptions& options, std::ostream* say, StudyFollowUps& f, RecheckReport& report,
             std::vector<DropRecord>* fast) {
  std::vector<DropRecord> reference;
  if (study.recheck.enabled) {
    std::vector<int64_t> todo;
    for (const DropRecord& r : records)
      if (NeedsRecheck(r, tip_angle_deg, study.recheck)) todo.push_back(r.index);
    std::sort(todo.begin(), todo.end());
    if (!todo.empty()) {
      if (say)
        *say << "stability " << study.plan.name << ": re-checking " << todo.size()
             << " landing(s) near the tip-over boundary with the reference model (rtol "
             << io::FormatNumber(study.recheck.rtol) << ReferenceMeshNote(study) << ") in " << RecheckDir(out_dir)
             << "/\n";
      if (!RunFollowUp(RecheckPlan(study), todo, RecheckDir(out_dir), options, f)) return false;
      for (auto& [index, r] : ReadStored(RecheckDir(out_dir), todo)) reference.push_back(std::move(r));
    }
  }
  report = ApplyRechecks(study, tip_angle_deg, records, reference, fast);
  return true;
}

// The soil pairing: the paired landings at the best values, re-checked, against `records` (the
// study's, re-checked). False when stopped.
bool PairSoil(const Study& study, double tip_angle_deg, const std::vector<DropRecord>& records,
              const std::string& out_dir, const sweep::SweepRunOptions& options, std::ostream* say, StudyFollowUps& f) {
  SoilPairingReport p;
  p.enabled = study.soil_pairing.enabled;
  if (!p.enabled) {
    p.reason = "turned off (study.soil_pairing: none)";
    f.soil_pairing = p;
    return true;
  }
  Study twin = study;
  twin.plan = SoilAtBestValuesPlan(study);
  const std::vector<int64_t> indices = SoilPairingIndices(study);
  const std::string dir = SoilPairingDir(out_dir);
  if (say)
    *say << "stability " << study.plan.name << ": running " << indices.size()
         << " landing(s) again with every drawn soil at its calibration's best values in " << dir << "/\n";
  if (!RunFollowUp(twin.plan, indices, dir, options, f)) return false;
  std::vector<DropRecord> at_best;
  for (auto& [index, r] : ReadStored(dir, indices)) at_best.push_back(std::move(r));
  RecheckReport recheck;
  if (!Recheck(twin, tip_angle_deg, at_best, dir, options, say, f, recheck, nullptr)) return false;
  p = PairBySoil(indices, records, at_best);
  p.rechecked = recheck.rechecked;
  p.recheck_changed = recheck.outcome_changed;
  f.soil_pairing = p;
  return true;
}
}  // namespace

StudyFollowUps RunStudyFollowUps(const Study& study, std::vector<DropRecord> records, const std::string& out_dir,
                                 const sweep::SweepRunOptions& options, std::ostream* say) {
  StudyFollowUps f;
  const double tip_angle_deg = StandingTipAngleDeg(study.plan);
  if (!Recheck(study, tip_angle_deg, records, out_dir, options, say, f, f.recheck, &f.fast)) return f;
  if (study.soil_uncertainty && !PairSoil(study, tip_angle_deg, records, out_dir, options, say, f)) return f;

  f.joint_range = JointRangeTrigger(study, records);
  JointRangeReport& j = f.joint_range;
  j.screen_margin_deg = study.joint_range.screen_margin_deg;
  j.tip_angle_deg = tip_angle_deg;
  if (j.reason.empty()) {
    const std::vector<int64_t> indices = JointRangeIndices(study);
    j.samples = static_cast<int64_t>(indices.size());
    std::map<int64_t, DropRecord> at_study;
    for (const DropRecord& r : records)
      if (std::binary_search(indices.begin(), indices.end(), r.index)) at_study.emplace(r.index, r);
    std::vector<int64_t> run;  // ascending, as `indices`
    for (const auto& [index, r] : at_study)
      if (MayTipAtAnotherRange(r, tip_angle_deg, study.joint_range)) run.push_back(index);
    j.screened_in = static_cast<int64_t>(run.size());
    std::map<double, std::map<int64_t, DropRecord>> at_factor;
    for (double factor : kJointRangeFactors) {
      const std::string dir = JointRangeDir(out_dir, factor);
      if (say) {
        *say << "stability " << study.plan.name << ": pads at their stops in " << j.at_stops << " of " << j.landings
             << " landings; running " << run.size() << " of " << indices.size() << " with the joints' range x"
             << io::FormatNumber(factor);
        if (run.size() < indices.size())
          *say << " (the other " << indices.size() - run.size() << " stood, settled, more than "
               << io::FormatNumber(*j.screen_margin_deg) << " deg below the tip-over angle: the study's outcome)";
        *say << (run.empty() ? "\n" : " in " + dir + "/\n");
      }
      if (!run.empty()) {
        if (!RunFollowUp(JointRangePlan(study, factor), run, dir, options, f)) return f;
        at_factor[factor] = ReadStored(dir, run);
      }
      // Left out by the screen: the study's record stands for the landing at this range too.
      for (const auto& [index, r] : at_study)
        if (!std::binary_search(run.begin(), run.end(), index)) at_factor[factor].emplace(index, r);
    }
    const double low = kJointRangeFactors[0], high = kJointRangeFactors[1];
    j.variants = {Variant(low, j.half_angle_deg, indices, at_factor[low], at_study),
                  Variant(1.0, j.half_angle_deg, indices, at_study, at_study),
                  Variant(high, j.half_angle_deg, indices, at_factor[high], at_study)};
    j.ran = true;
  }
  f.records = std::move(records);
  return f;
}

nlohmann::json RecheckJson(const RecheckReport& r) {
  if (!r.enabled)
    return {{"enabled", false}, {"reason", "turned off (study.recheck: none): every landing is the fast model's"}};
  return {{"enabled", true},
          {"rtol", r.rtol},
          {"pad_angular_segments", {{"fast", r.fast_pad_angular_segments}, {"reference", r.reference_pad_angular_segments}}},
          {"tip_angle_deg", io::FiniteOrNull(r.tip_angle_deg)},
          {"margin_deg", r.margin_deg},
          {"unsettled", r.unsettled},
          {"criterion",
           std::string(r.unsettled ? "landings that tipped over, ended unsettled, or whose max tilt reached "
                                   : "landings that tipped over or whose max tilt reached ") +
           "tip_angle_deg - margin_deg ran "
           "again with the reference model (the study's lander at rtol, its pads meshed as their file says: "
           "pad_angular_segments.reference rim segments, against the study's pad_angular_segments.fast; 0 for a "
           "meshed pad); every statistic here is over their reference records"},
          {"rechecked", r.rechecked},
          {"outcome_changed", r.outcome_changed},
          {"changed_landings", r.changed_landings},
          {"reference_failed", r.reference_failed},
          {"reference_failed_landings", r.reference_failed_landings},
          {"largest_max_tilt_change_deg", r.largest_max_tilt_change_deg}};
}

nlohmann::json JointRangeJson(const JointRangeReport& j) {
  nlohmann::json out = {{"cone_limit", j.cone_limit},
                        {"half_angle_deg", io::FiniteOrNull(j.half_angle_deg)},
                        {"landings_at_stops", j.at_stops},
                        {"landings_at_stops_fraction", j.at_stops_fraction},
                        {"at_stops_meaning",
                         "completed landings in which a pad swung further than the cone limit's half angle on its "
                         "ball joint (max_joint_swing_deg > half_angle_deg); above 5 % the study runs K of its "
                         "landings again at half and at 1.5 times the range"},
                        {"ran", j.ran}};
  if (!j.ran) {
    out["reason"] = j.reason;
    return out;
  }
  out["samples"] = j.samples;
  out["screen"] = {
      {"margin_deg", j.screen_margin_deg ? nlohmann::json(*j.screen_margin_deg) : nlohmann::json(nullptr)},
      {"tip_angle_deg", io::FiniteOrNull(j.tip_angle_deg)},
      {"landings_run", j.screened_in},
      {"landings_kept_from_study", j.samples - j.screened_in},
      {"meaning",
       j.screen_margin_deg
           ? "of the K landings, those that tipped over, ended unsettled or failed, or whose max tilt came within "
             "margin_deg of tip_angle_deg ran again at x0.5 and x1.5 (landings_run); the others stood, settled, "
             "further below the tip-over angle than the range moves a max tilt there, and count at every range "
             "with the study's outcome (landings_kept_from_study; docs/stability_studies.md, \"Follow-ups\", "
             "\"The screen\")"
           : "no screen (screen_margin_deg: none): all K landings ran again at x0.5 and x1.5"}};
  out["variants_meaning"] =
      "the same K landings of the study (its indices floor(j N / K), j < K) at every joint's half angle x0.5, x1 "
      "(the study's own records, after the re-checks) and x1.5, stiffness and damping unchanged; "
      "outcome_differs_from_x1 counts the landings that tip over at one range and not at the other";
  nlohmann::json variants = nlohmann::json::array();
  for (const JointRangeVariant& v : j.variants) {
    nlohmann::json e = {{"factor", v.factor},         {"half_angle_deg", v.half_angle_deg},
                        {"landings", v.landings},     {"tipped_over", v.tipped},
                        {"landings_failed", v.failed}, {"outcome_differs_from_x1", v.differs_from_study}};
    if (v.landings > 0) {
      e["tip_over_probability"] = v.probability;
      e["tip_over_probability_interval_95"] = {v.interval.low, v.interval.high};
    } else {
      e["tip_over_probability_reason"] = "no landing completed";
    }
    variants.push_back(e);
  }
  out["variants"] = variants;
  return out;
}

}  // namespace touchdown::stability

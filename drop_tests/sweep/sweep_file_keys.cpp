#include "drop_tests/sweep/sweep_file_keys.h"

#include <algorithm>
#include <filesystem>
#include <iterator>

#include "drop_tests/formats/output_path.h"

// A sweep file's keys and WriteSweepPlan, which writes them: a plan written reads back to the same
// drops (tests/drop_tests/sweep/sweep_plan_round_trip_test.cpp), its pads, sweep file and model as absolute
// paths, its soils by name or absolute path.
namespace touchdown::sweep {

namespace fs = std::filesystem;

namespace file_keys {
namespace {
std::string Absolute(const std::string& path) { return fs::absolute(path).lexically_normal().string(); }

// A soil as the plan resolved it: a catalogue name stays a name, a path becomes absolute.
std::string SoilRef(const SweepPlan& plan, int soil) {
  const std::string& ref = plan.soil_refs[soil];
  return ref.find('/') == std::string::npos && !ref.ends_with(".yaml") && !ref.ends_with(".yml") ? ref : Absolute(ref);
}

// One value of `p` as a sweep file gives it: a pad or soil, a pad_soils case, or a number.
void EmitValue(YAML::Emitter& y, const SweepPlan& plan, SweepParam p, double v) {
  const int i = static_cast<int>(v);
  if (p == SweepParam::kPad) {
    y << Absolute(plan.pads[i].source);
  } else if (p == SweepParam::kSoil) {
    y << SoilRef(plan, i);
  } else if (p == SweepParam::kPadSoils) {
    const PadSoilSet& set = plan.pad_soil_sets[i];
    if (!set.label.empty()) {
      y << set.label;
    } else {
      y << YAML::Flow << YAML::BeginSeq;
      for (int soil : set.soil) y << SoilRef(plan, soil);
      y << YAML::EndSeq;
    }
  } else {
    y << SweepParamFromSi(p, v);
  }
}

void WriteFixed(YAML::Emitter& y, const SweepPlan& plan) {
  y << YAML::BeginMap;
  for (int k = 0; k < kSweepParamCount; ++k)
    if (const SweepParam p = static_cast<SweepParam>(k); plan.fixed[k]) {
      y << YAML::Key << SweepParamKey(p) << YAML::Value;
      EmitValue(y, plan, p, *plan.fixed[k]);
    }
  y << YAML::EndMap;
}

void WriteGrid(YAML::Emitter& y, const SweepPlan& plan) {
  y << YAML::BeginMap;
  for (const SweepAxis& axis : plan.grid) {
    y << YAML::Key << SweepParamKey(axis.param) << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (double v : axis.values) EmitValue(y, plan, axis.param, v);
    y << YAML::EndSeq;
  }
  y << YAML::EndMap;
}

void WriteRandom(YAML::Emitter& y, const SweepPlan& plan) {
  y << YAML::BeginMap << YAML::Key << "samples" << YAML::Value << plan.samples << YAML::Key << "seed" << YAML::Value
    << plan.seed;
  for (const SweepRandom& r : plan.random) {
    y << YAML::Key << SweepParamKey(r.param) << YAML::Value;
    io::WriteMap(y, RandomSpecKeys(), RandomToWrite{plan, r}, YAML::Flow);
  }
  y << YAML::EndMap;
}
}  // namespace

const io::KeyTable<SweepPlan>& LanderBlockKeys() {
  using Y = YAML::Emitter;
  static const io::KeyTable<SweepPlan> keys{
      {"scenario", io::Always<SweepPlan>, [](Y& y, const SweepPlan& plan) { y << Absolute(plan.lander->source); }},
      {kPadPatchHalfWidthKey.key, io::Always<SweepPlan>,
       [](Y& y, const SweepPlan& plan) { y << plan.pad_patch_half_width_m; }, io::DocOf(kPadPatchHalfWidthKey)},
  };
  return keys;
}

const io::KeyTable<SweepPlan>& SimulationBlockKeys() {
  using Y = YAML::Emitter;
  static const io::KeyTable<SweepPlan> keys{
      {"free_drop_model", [](const SweepPlan& plan) { return plan.free_drop_model == drop::FreeDropModel::kFast; },
       [](Y& y, const SweepPlan&) { y << "fast"; }},
  };
  return keys;
}


const io::KeyTable<RandomToWrite>& RandomSpecKeys() {
  using R = RandomToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<R> keys{
      {"uniform", [](const R& w) { return !w.r.choice; },
       [](Y& y, const R& w) {
         y << YAML::BeginSeq << SweepParamFromSi(w.r.param, w.r.low) << SweepParamFromSi(w.r.param, w.r.high) << YAML::EndSeq;
       }},
      {"choice", [](const R& w) { return w.r.choice && !w.r.per_pad; },
       [](Y& y, const R& w) {
         y << YAML::BeginSeq;
         for (double v : w.r.values) EmitValue(y, w.plan, w.r.param, v);
         y << YAML::EndSeq;
       }},
      {"per_pad_choice", [](const R& w) { return w.r.per_pad; },
       [](Y& y, const R& w) {
         y << YAML::BeginSeq;
         for (double v : w.r.values) y << SoilRef(w.plan, static_cast<int>(v));
         y << YAML::EndSeq;
       }},
      {"probabilities", [](const R& w) { return !w.r.probabilities.empty(); },
       [](Y& y, const R& w) {
         y << YAML::BeginSeq;
         for (double v : w.r.probabilities) y << v;
         y << YAML::EndSeq;
       }},
  };
  return keys;
}

const io::KeyTable<SweepPlan>& SweepKeys() {
  using P = SweepPlan;
  using Y = YAML::Emitter;
  const auto single_pad = [](const P& plan) { return !plan.lander.has_value(); };
  static const io::KeyTable<P> keys{
      {"schema_version", io::Always<P>, [](Y& y, const P&) { y << 1; }},
      {"type", io::Always<P>, [](Y& y, const P&) { y << "sweep"; }},
      {"name", io::Always<P>, [](Y& y, const P& plan) { y << plan.name; }},
      {"description"},
      {"model", [](const P& plan) { return plan.model.has_value(); },
       [](Y& y, const P& plan) { y << Absolute(plan.model->source); }},
      {"lander", [](const P& plan) { return plan.lander.has_value(); },
       [](Y& y, const P& plan) {
         io::WriteMap(y, LanderBlockKeys(), plan);
       }},
      {"traces", io::Always<P>, [](Y& y, const P& plan) { y << TraceStorageName(plan.traces); }},
      {"trace_max_samples", single_pad, [](Y& y, const P& plan) { y << plan.trace_max_samples; }},
      {kRestDurationKey.key, single_pad, [](Y& y, const P& plan) { y << plan.rig.rest_duration_s; },
       io::DocOf(kRestDurationKey)},
      {"max_drop_evaluations", io::Always<P>,
       [](Y& y, const P& plan) { y << plan.rig.integrator.max_rhs_evaluations; }},
      {kMaxDropWallTimeKey.key, io::Always<P>, [](Y& y, const P& plan) { y << plan.rig.integrator.max_wall_time_s; },
       io::DocOf(kMaxDropWallTimeKey)},
      {"simulation", [](const P& plan) { return plan.free_drop_model == drop::FreeDropModel::kFast; },
       [](Y& y, const P& plan) {
         io::WriteMap(y, SimulationBlockKeys(), plan, YAML::Flow);
       }},
      {"fixed",
       [](const P& plan) {
         return std::any_of(std::begin(plan.fixed), std::end(plan.fixed), [](const auto& v) { return v.has_value(); });
       },
       WriteFixed},
      {"grid", [](const P& plan) { return !plan.grid.empty(); }, WriteGrid},
      {"random", [](const P& plan) { return !plan.random.empty(); }, WriteRandom},
      {"study"},
      {"trade"},
      {"provenance"},
  };
  return keys;
}

}  // namespace file_keys

void WriteSweepPlan(const SweepPlan& plan, const std::string& path) {
  YAML::Emitter y;
  y.SetDoublePrecision(17);  // every value reads back to the same double
  io::WriteMap(y, file_keys::SweepKeys(), plan);
  io::WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

}  // namespace touchdown::sweep

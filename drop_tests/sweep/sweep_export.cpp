#include "drop_tests/sweep/sweep_export.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "drop_tests/sweep/sweep_engine.h"
#include "drop_tests/util/work_pool.h"
#include "rft/input_error.h"
#include "rft/input_file.h"

namespace touchdown::sweep {

namespace fs = std::filesystem;

namespace {
// A column of an export: its header name and its cell of a record. A number's value comes from
// the database's column of the same name (RecordNumberNamed), so an export names and reads a
// number as the database does.
struct ExportColumn {
  std::string name;
  std::function<std::string(const DropRecord&)> cell;
};
// A not-finite number (a quantity the drop does not have) as an empty cell, or as written.
enum class NotFinite { kEmpty, kWritten };
ExportColumn NumberColumn(const std::string& name, NotFinite not_finite) {
  const RecordNumber& n = RecordNumberNamed(name);
  return {name, [&n, not_finite](const DropRecord& r) {
            const double v = n.Of(r);
            return not_finite == NotFinite::kEmpty && !std::isfinite(v) ? std::string() : io::FormatNumber(v);
          }};
}
ExportColumn StepsColumn() {
  return {"solver_steps", [](const DropRecord& r) { return std::to_string(r.solver_steps); }};
}
ExportColumn TextColumn(const std::string& name, std::function<const std::string&(const DropRecord&)> text) {
  return {name, [text = std::move(text)](const DropRecord& r) { return text(r); }};
}
std::vector<std::string> Names(const std::vector<ExportColumn>& columns) {
  std::vector<std::string> names;
  for (const ExportColumn& c : columns) names.push_back(c.name);
  return names;
}

// A single-pad sweep's columns after the dataset format's own (drops.csv's extra columns).
const std::vector<ExportColumn>& PadExtraColumns() {
  static const std::vector<ExportColumn> c = [] {
    std::vector<ExportColumn> out;
    for (const char* n : {"tilt_deg", "horizontal_speed_m_s", "zeta_N_cm3", "time_to_rest_s", "max_deceleration_m_s2",
                          "impact_energy_J", "gravity_work_J", "dissipated_energy_J", "mean_conversion_rate_W",
                          "rest_creep_m"})
      out.push_back(NumberColumn(n, NotFinite::kWritten));
    out.push_back(StepsColumn());
    for (const char* n : {"final_tilt_deg", "horizontal_travel_m"}) out.push_back(NumberColumn(n, NotFinite::kWritten));
    return out;
  }();
  return c;
}
const std::vector<std::string> kExtraColumns = Names(PadExtraColumns());

// A lander sweep's columns (lander_drops.csv): the drop, its conditions, the soils under its pads,
// its summary, and a stability study's metrics and conditions, the joints' swing, the tip-over edge.
const std::vector<ExportColumn>& LanderColumns() {
  static const std::vector<ExportColumn> c = [] {
    std::vector<ExportColumn> out = {TextColumn("drop_id", [](const DropRecord& r) -> const std::string& { return r.drop_id; }),
                                     TextColumn("pad", [](const DropRecord& r) -> const std::string& { return r.pad; }),
                                     TextColumn("soil", [](const DropRecord& r) -> const std::string& { return r.soil; }),
                                     {"atmosphere", [](const DropRecord& r) { return std::string(rft::AtmosphereName(r.atmosphere)); }}};
    for (const char* n : {"impact_speed_m_s", "pad_mass_kg", "gravity_m_s2", "horizontal_speed_m_s", "roll_deg",
                          "pitch_deg", "tilt_deg"})
      out.push_back(NumberColumn(n, NotFinite::kWritten));
    out.push_back(TextColumn("ground_case", [](const DropRecord& r) -> const std::string& { return r.ground_case; }));
    for (size_t i = 0; i < 4; ++i)
      out.push_back(TextColumn("pad" + std::to_string(i + 1) + "_soil",
                               [i](const DropRecord& r) -> const std::string& { return r.pad_soil[i]; }));
    for (const char* n : {"zeta_N_cm3", "final_penetration_m", "peak_force_N", "pad1_final_penetration_m",
                          "pad2_final_penetration_m", "pad3_final_penetration_m", "pad4_final_penetration_m",
                          "final_roll_deg", "final_pitch_deg", "final_tilt_deg", "tipped_over", "time_to_rest_s",
                          "max_deceleration_m_s2", "impact_energy_J", "gravity_work_J", "dissipated_energy_J",
                          "mean_conversion_rate_W", "horizontal_travel_m"})
      out.push_back(NumberColumn(n, NotFinite::kEmpty));
    out.push_back(StepsColumn());
    for (const RecordNumber& n : StabilityNumbers()) out.push_back(NumberColumn(n.name, NotFinite::kEmpty));
    return out;
  }();
  return c;
}

// A results database to read: there (else "no sweep results here"), and a readable file.
void RequireResultsFile(const std::string& db_path) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(db_path, ec))) throw MakeInputError(db_path, "", "no sweep results here");
  RequireReadableFile(db_path, "results database");
}

// Export reads every format up to this build's (ResultsDb reads an older one through the newer
// columns, NULL or ''); a newer or unknown one is refused, as `sweep` refuses to resume it.
void RequireReadableFormat(const std::string& db_path, const std::map<std::string, std::string>& meta) {
  const auto it = meta.find("format_version");
  const std::string version = it == meta.end() ? "" : it->second;
  for (int v = 1; v <= kResultsDbVersion; ++v)
    if (version == std::to_string(v)) return;
  throw MakeInputError(db_path, "format_version",
                       "unknown results format '" + version + "' (this touchdown reads 1 to " +
                           std::to_string(kResultsDbVersion) + "; written by another touchdown version?)");
}

// The plan the database was written from, reloaded from its sweep file and checked.
SweepPlan ReloadPlan(const std::string& db_path, const std::map<std::string, std::string>& meta) {
  const auto source = meta.find("source");
  const auto model = meta.find("model");
  if (source == meta.end() || !fs::is_regular_file(source->second))
    throw MakeInputError(db_path, "source",
                         "traces must be simulated again but the sweep file is gone; run the sweep with traces: full");
  SweepPlan plan = LoadSweepPlan(source->second, "");
  if (!plan.model && model != meta.end() && !model->second.empty()) plan = LoadSweepPlan(source->second, model->second);
  if (PlanDigest(plan) != meta.at("plan_digest"))
    throw MakeInputError(db_path, "plan_digest",
                         "the sweep file " + source->second + " (or a pad, soil or model) changed since the sweep ran");
  return plan;
}

// Whether `name` is a catalogue entry of `kind` (and, when `source` is given, that very file).
bool InCatalogue(const std::string& kind, const std::string& name, const std::string& source) {
  try {
    const std::string catalogued = io::ResolveCatalogFile(kind, name);  // throws when not a catalogue name
    return source.empty() || fs::equivalent(catalogued, source);
  } catch (const std::exception&) {
    return false;
  }
}

// The plan's pads and soils that came from files rather than the catalogue: name -> file.
void AddNonCatalogueFiles(const SweepPlan& plan, std::map<std::string, std::string>* pad_files,
                          std::map<std::string, std::string>* soil_files) {
  for (const io::PadSpec& p : plan.pads)
    if (!InCatalogue("pads", p.name, p.source)) (*pad_files)[p.name] = fs::absolute(p.source).string();
  for (size_t i = 0; i < plan.soils.size() && i < plan.soil_refs.size(); ++i) {
    const std::string source = io::ResolveCatalogFile("soils", plan.soil_refs[i]);
    if (!InCatalogue("soils", plan.soils[i].name, source))
      (*soil_files)[plan.soils[i].name] = fs::absolute(source).string();
  }
}

// A record's extra cells, in kExtraColumns order.
std::vector<std::string> ExtraCells(const DropRecord& r) {
  std::vector<std::string> cells;
  for (const ExportColumn& c : PadExtraColumns()) cells.push_back(c.cell(r));
  return cells;
}

InputError LanderRefusal(const std::string& db_path, const DropRecord& r) {
  return MakeInputError(db_path, "drop " + r.drop_id,
                        "a lander sweep has no single-pad traces to export as a dataset; `touchdown export` writes its "
                        "summaries as lander_drops.csv (pad1..pad4_final_penetration_m, final_roll_deg, "
                        "final_pitch_deg, tipped_over)");
}
// The meta table of a sweep database of a format this touchdown reads; refused otherwise.
std::map<std::string, std::string> ReadableMeta(const ResultsDb& db) {
  std::map<std::string, std::string> meta = db.Meta();
  if (meta.empty()) throw MakeInputError(db.path(), "", "not a sweep results database (no meta)");
  RequireReadableFormat(db.path(), meta);
  return meta;
}
}  // namespace


dataset::Dataset SweepToDataset(const std::string& sweep_dir, const ExportOptions& options, ExportSummary* summary_out,
                       std::vector<DropRecord>* failed_out) {
  const std::string db_path = ResultsDbPath(sweep_dir);
  RequireResultsFile(db_path);
  const ResultsDb db(db_path, ResultsDb::Access::kReadOnly);
  const std::map<std::string, std::string> meta = ReadableMeta(db);
  std::vector<DropRecord> records = db.ReadAll(/*with_traces=*/true);
  ExportSummary summary;
  for (const DropRecord& r : records)
    if (r.kind == DropKind::kLander) throw LanderRefusal(db_path, r);

  std::vector<int64_t> again;
  for (const DropRecord& r : records)
    if (r.ok && (options.full_traces || r.trace.empty())) again.push_back(r.index);
  std::optional<SweepPlan> plan;
  if (!again.empty()) {
    plan = ReloadPlan(db_path, meta);
    std::map<int64_t, size_t> position;
    for (size_t i = 0; i < records.size(); ++i) position[records[i].index] = i;
    // Full traces, recomputed on threads; the summaries must match the stored ones bit for bit.
    SweepPlan full = *plan;
    full.traces = TraceStorage::kFull;
    const SweepModels full_models(full);
    DropEngine engine(full_models, again, io::ThreadsFor(options.threads));
    while (!engine.Finished())
      for (DropRecord& r : engine.Take(1024, 1.0)) {
        DropRecord& stored = records[position.at(r.index)];
        if (!SameRecord(stored, r, /*compare_traces=*/false))
          throw std::runtime_error("drop " + r.drop_id + " does not reproduce its stored results");
        stored.trace = std::move(r.trace);
        ++summary.resimulated;
      }
  }

  // Pads and soils loaded from files (not catalogue names) are written as their absolute paths,
  // which needs the plan's files: reloaded (and checked) when a stored name is not a catalogue one.
  const auto& in_catalogue = InCatalogue;
  if (!plan)
    for (const DropRecord& r : records)
      if (r.ok && (!in_catalogue("pads", r.pad, "") || !in_catalogue("soils", r.soil, ""))) {
        plan = ReloadPlan(db_path, meta);
        break;
      }
  std::map<std::string, std::string> pad_files, soil_files;  // name -> path, for non-catalogue ones
  if (plan) AddNonCatalogueFiles(*plan, &pad_files, &soil_files);

  dataset::Dataset ds;
  ds.directory = "";
  ds.extra_columns = kExtraColumns;
  for (DropRecord& r : records) {
    if (!r.ok) {
      ++summary.failed;
      if (failed_out) failed_out->push_back(r);
      continue;
    }
    dataset::DatasetDrop d;
    d.drop_id = r.drop_id;
    d.pad = r.pad;
    d.soil = r.soil;
    // A pad or soil from a file (not a catalogue name) is written as its absolute path.
    if (const auto it = pad_files.find(r.pad); it != pad_files.end()) d.pad = it->second;
    if (const auto it = soil_files.find(r.soil); it != soil_files.end()) d.soil = it->second;
    d.atmosphere = r.atmosphere;
    d.impact_speed_m_s = r.impact_speed_m_s;
    d.pad_mass_kg = r.pad_mass_kg;
    d.gravity_m_s2 = r.gravity_m_s2;
    d.trace_file = "traces/" + r.drop_id + ".csv";
    d.final_penetration_m = r.final_penetration_m;
    d.peak_force_N = r.peak_force_N;
    d.extra = ExtraCells(r);
    d.trace.extra_columns = {"velocity_m_s"};
    d.trace.extra.resize(1);
    for (const pad::DropSample& s : r.trace) {
      d.trace.t_s.push_back(s.t_s);
      d.trace.penetration_m.push_back(s.penetration_m);
      d.trace.force_N.push_back(s.force_N);
      d.trace.extra[0].push_back(s.velocity_m_s);
    }
    ds.drops.push_back(std::move(d));
    ++summary.exported;
  }
  if (summary_out) *summary_out = summary;
  return ds;
}

const std::vector<std::string> kLanderExportColumns = Names(LanderColumns());

namespace {
// Every failed drop of the database (a second pass in index order, streamed).
void WriteFailedCsv(const ResultsDb& db, const std::string& path) {
  io::WriteFileAtomically(path, [&](std::ostream& out) {
    out << "drop_id,reason\n";
    db.ForEach(
        [&](const DropRecord& r) {
          if (r.ok) return;
          std::string reason = r.failure;
          for (char& c : reason)
            if (c == ',' || c == '\n' || c == '\r') c = ' ';
          out << r.drop_id << ',' << reason << '\n';
        },
        /*with_traces=*/false);
  });
}

// A lander sweep: its summaries as lander_drops.csv (successful drops) and failed.csv, streamed
// from the database row by row.
ExportSummary ExportLanderSweep(const ResultsDb& db, const io::OutputTarget& dataset_dir) {
  ExportSummary summary;
  summary.lander = true;
  const std::string& db_path = db.path();
  io::WriteOutputDirectory(dataset_dir, io::OutputKind::kDataset, [&](const std::string& staging) {
    io::WriteFileAtomically((fs::path(staging) / "lander_drops.csv").string(), [&](std::ostream& out) {
      for (size_t i = 0; i < kLanderExportColumns.size(); ++i) out << (i ? "," : "") << kLanderExportColumns[i];
      out << '\n';
      db.ForEach(
          [&](const DropRecord& r) {
            if (r.kind != DropKind::kLander) throw MakeInputError(db_path, "drop " + r.drop_id, "a pad drop in a lander sweep");
            if (!r.ok) {
              ++summary.failed;
              return;
            }
            for (const std::string* s : {&r.pad, &r.soil, &r.pad_soil[0], &r.pad_soil[1],
                                         &r.pad_soil[2], &r.pad_soil[3], &r.ground_case})
              if (s->find_first_of(",\n\r") != std::string::npos)
                throw MakeInputError(db_path, "drop " + r.drop_id, "a name contains a comma or line break: " + *s);
            ++summary.exported;
            const std::vector<ExportColumn>& columns = LanderColumns();
            for (size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i].cell(r);
            out << '\n';
          },
          /*with_traces=*/false);
    });
    if (summary.exported == 0) throw MakeInputError(db_path, "", "no successful drops to export");
    if (summary.failed > 0) WriteFailedCsv(db, (fs::path(staging) / "failed.csv").string());
  });
  return summary;
}

// A single-pad sweep as a dataset, streamed: the database is read a page of drops at a time,
// traces missing from it are simulated again for that page only, and each drop's row and trace
// file are written before the next page is read, so memory does not grow with the sweep. The
// files are those WriteDataset(SweepToDataset(...)) writes, byte for byte.
ExportSummary ExportPadSweep(const ResultsDb& db, const std::map<std::string, std::string>& meta,
                             const io::OutputTarget& dataset_dir, const ExportOptions& options) {
  constexpr size_t kPage = 256;
  const std::string& db_path = db.path();
  ExportSummary summary;
  std::optional<SweepPlan> plan, full_plan;  // loaded only when needed
  std::unique_ptr<SweepModels> full_models;
  std::map<std::string, std::string> pad_files, soil_files;  // non-catalogue name -> absolute path
  std::map<std::string, bool> catalogued;                    // "pads/NAME", "soils/NAME"
  io::Progress progress("export", "drops", db.Count(), options.progress);
  auto load_plan = [&] {
    if (plan) return;
    plan = ReloadPlan(db_path, meta);
    AddNonCatalogueFiles(*plan, &pad_files, &soil_files);
  };
  auto in_catalogue = [&](const std::string& kind, const std::string& name) {
    const auto [it, inserted] = catalogued.try_emplace(kind + "/" + name, false);
    if (inserted) it->second = InCatalogue(kind, name, "");
    return it->second;
  };
  io::WriteOutputDirectory(dataset_dir, io::OutputKind::kDataset, [&](const std::string& staging) {
    io::WriteFileAtomically((fs::path(staging) / "drops.csv").string(), [&](std::ostream& out) {
      for (size_t i = 0; i < dataset::kDatasetDropColumns.size(); ++i) out << (i ? "," : "") << dataset::kDatasetDropColumns[i];
      out << ",final_penetration_m,peak_force_N";
      for (const std::string& c : kExtraColumns) out << ',' << c;
      out << '\n';
      for (int64_t from = std::numeric_limits<int64_t>::min();;) {
        std::vector<DropRecord> page = db.ReadPage(from, kPage, /*with_traces=*/true);
        if (page.empty()) break;
        from = page.back().index + 1;
        std::vector<int64_t> again;
        std::map<int64_t, size_t> position;
        for (size_t i = 0; i < page.size(); ++i) {
          const DropRecord& r = page[i];
          if (r.kind == DropKind::kLander) throw LanderRefusal(db_path, r);
          if (r.ok && (options.full_traces || r.trace.empty())) {
            again.push_back(r.index);
            position[r.index] = i;
          }
        }
        if (!again.empty()) {
          // Full traces, recomputed on threads; the summaries must match the stored ones bit for bit.
          load_plan();
          if (!full_models) {
            full_plan = *plan;
            full_plan->traces = TraceStorage::kFull;
            full_models = std::make_unique<SweepModels>(*full_plan);
          }
          DropEngine engine(*full_models, again, io::ThreadsFor(options.threads));
          while (!engine.Finished())
            for (DropRecord& r : engine.Take(kPage, 1.0)) {
              DropRecord& stored = page[position.at(r.index)];
              if (!SameRecord(stored, r, /*compare_traces=*/false))
                throw std::runtime_error("drop " + r.drop_id + " does not reproduce its stored results");
              stored.trace = std::move(r.trace);
              ++summary.resimulated;
            }
        }
        progress.Add(static_cast<int64_t>(page.size()));
        for (const DropRecord& r : page) {
          if (!r.ok) {
            ++summary.failed;
            continue;
          }
          // A pad or soil from a file (not a catalogue name) is written as its absolute path.
          if (!in_catalogue("pads", r.pad) || !in_catalogue("soils", r.soil)) load_plan();
          const auto pad_file = pad_files.find(r.pad);
          const auto soil_file = soil_files.find(r.soil);
          const std::string& pad = pad_file == pad_files.end() ? r.pad : pad_file->second;
          const std::string& soil = soil_file == soil_files.end() ? r.soil : soil_file->second;
          const std::string trace_file = "traces/" + r.drop_id + ".csv";
          for (const std::string* name : {&r.drop_id, &pad, &soil})
            if (name->find_first_of(",\n\r") != std::string::npos)
              throw MakeInputError(dataset_dir.path, "drop " + r.drop_id,
                                   "a name or path contains a comma or line break: " + *name);
          out << r.drop_id << ',' << pad << ',' << soil << ',' << rft::AtmosphereName(r.atmosphere) << ',' << io::FormatNumber(r.impact_speed_m_s)
              << ',' << io::FormatNumber(r.pad_mass_kg) << ',' << io::FormatNumber(r.gravity_m_s2) << ',' << trace_file << ','
              << io::FormatNumber(r.final_penetration_m) << ',' << io::FormatNumber(r.peak_force_N);
          for (const std::string& cell : ExtraCells(r)) out << ',' << cell;
          out << '\n';
          const fs::path path = fs::path(staging) / trace_file;
          fs::create_directories(path.parent_path());
          io::WriteFileAtomically(path.string(), [&](std::ostream& t) {
            t << "t_s,penetration_m,force_N,velocity_m_s\n";
            for (const pad::DropSample& s : r.trace)
              t << io::FormatNumber(s.t_s) << ',' << io::FormatNumber(s.penetration_m) << ',' << io::FormatNumber(s.force_N) << ','
                << io::FormatNumber(s.velocity_m_s) << '\n';
          });
          ++summary.exported;
        }
      }
    });
    if (summary.exported == 0) throw MakeInputError(fs::path(db_path).parent_path().string(), "",
                                                    "no successful drops to export");
    if (summary.failed > 0) WriteFailedCsv(db, (fs::path(staging) / "failed.csv").string());
  });
  return summary;
}
}  // namespace

ExportSummary ExportSweep(const std::string& sweep_dir, const io::OutputTarget& dataset_dir, const ExportOptions& options) {
  const std::string db_path = ResultsDbPath(sweep_dir);
  RequireResultsFile(db_path);
  const ResultsDb db(db_path, ResultsDb::Access::kReadOnly);
  const std::map<std::string, std::string> meta = ReadableMeta(db);
  const std::vector<DropRecord> first = db.ReadPage(std::numeric_limits<int64_t>::min(), 1, /*with_traces=*/false);
  if (!first.empty() && first.front().kind == DropKind::kLander) return ExportLanderSweep(db, dataset_dir);
  return ExportPadSweep(db, meta, dataset_dir, options);
}

}  // namespace touchdown::sweep

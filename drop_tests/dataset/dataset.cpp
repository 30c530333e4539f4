#include "drop_tests/dataset/dataset.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/util/file_name.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::dataset {

namespace fs = std::filesystem;

double SamplePeriod(const DatasetTrace& trace) {
  if (trace.size() < 2) return 0.0;
  std::vector<double> spacing(trace.size() - 1);
  for (size_t i = 0; i + 1 < trace.size(); ++i) spacing[i] = trace.t_s[i + 1] - trace.t_s[i];
  const size_t mid = spacing.size() / 2;
  std::nth_element(spacing.begin(), spacing.begin() + mid, spacing.end());
  return spacing[mid];
}

const std::vector<std::string> kDatasetDropColumns = {"drop_id",      "pad",         "soil",         "atmosphere",
                                                      "impact_speed_m_s", "pad_mass_kg", "gravity_m_s2", "trace"};
const std::vector<std::string> kDatasetTraceColumns = {"t_s", "penetration_m", "force_N"};

namespace {
const std::vector<std::string> kOptionalColumns = {"final_penetration_m", "peak_force_N", "penetration_zero"};

bool IsPathLike(const std::string& s) {
  return s.find('/') != std::string::npos || s.ends_with(".yaml") || s.ends_with(".yml");
}

std::string Resolve(const std::string& directory, const std::string& reference) {
  if (!IsPathLike(reference) || fs::path(reference).is_absolute()) return reference;
  return (fs::path(directory) / reference).lexically_normal().string();
}

// Streamed (VisitCsv): each row goes straight into the columns as numbers, so a trace costs its
// doubles only (ten million rows: 0.24 GB, not the 2 GB of rows kept as strings).
DatasetTrace ReadTrace(const std::string& path) {
  DatasetTrace trace;
  int ct = -1, cd = -1, cf = -1;
  std::vector<int> extra_index;
  auto columns = [&](const io::CsvTable& t) {
    ct = t.Require("t_s"), cd = t.Require("penetration_m"), cf = t.Require("force_N");
    for (size_t c = 0; c < t.header.size(); ++c)
      if (static_cast<int>(c) != ct && static_cast<int>(c) != cd && static_cast<int>(c) != cf) {
        trace.extra_columns.push_back(t.header[c]);
        extra_index.push_back(static_cast<int>(c));
      }
    trace.extra.resize(extra_index.size());
  };
  const io::CsvTable table = io::VisitCsv(path, [&](const io::CsvTable& t, std::vector<std::string>& cells, int line) {
    if (ct < 0) columns(t);
    const double time = t.NumberAt(cells[ct], line, ct);
    if (!trace.t_s.empty() && !(time > trace.t_s.back()))
      t.FailAt(line, ct, "time must increase strictly (previous sample: " + io::FormatNumber(trace.t_s.back()) + ")");
    trace.t_s.push_back(time);
    trace.penetration_m.push_back(t.NumberAt(cells[cd], line, cd));
    trace.force_N.push_back(t.NumberAt(cells[cf], line, cf));
    for (size_t k = 0; k < extra_index.size(); ++k)
      trace.extra[k].push_back(t.NumberAt(cells[extra_index[k]], line, extra_index[k]));
  });
  if (ct < 0) columns(table);  // no rows: a missing column is still the first problem named
  if (trace.size() == 0) throw MakeInputError(path, "line 2", "no samples");
  trace.t_s.shrink_to_fit();
  trace.penetration_m.shrink_to_fit();
  trace.force_N.shrink_to_fit();
  for (std::vector<double>& column : trace.extra) column.shrink_to_fit();
  return trace;
}

}  // namespace

std::string DropIdProblem(const std::string& id) {
  if (std::string problem = io::FileNameProblem("drop id", id); !problem.empty()) return problem;
  if (!IsValidUtf8(id)) return "drop id is not valid UTF-8 text";
  return "";
}

namespace {
void CheckCatalog(const io::CsvTable& t, size_t row, int column, const std::string& kind, const std::string& reference) {
  try {
    io::ResolveCatalogFile(kind, reference);
  } catch (const InputError& e) {
    t.Fail(row, column, std::string("unknown ") + (kind == "pads" ? "pad" : "soil") + " (" + e.what() + ")");
  }
}
}  // namespace

double DatasetDrop::FinalPenetration() const {
  if (final_penetration_m) return *final_penetration_m;
  return trace.penetration_m.empty() ? 0.0 : trace.penetration_m.back();
}

double DatasetDrop::PeakForce() const {
  if (peak_force_N) return *peak_force_N;
  return trace.force_N.empty() ? 0.0 : *std::max_element(trace.force_N.begin(), trace.force_N.end());
}

const DatasetDrop* Dataset::Find(const std::string& drop_id) const {
  for (const DatasetDrop& d : drops)
    if (d.drop_id == drop_id) return &d;
  return nullptr;
}

std::optional<double> Dataset::ExtraNumber(const DatasetDrop& drop, const std::string& column) const {
  const auto it = std::find(extra_columns.begin(), extra_columns.end(), column);
  if (it == extra_columns.end()) return std::nullopt;
  const std::string& cell = drop.extra[it - extra_columns.begin()];
  if (cell.empty()) return std::nullopt;
  double v = 0.0;
  if (!io::ParseNumber(cell, &v))
    throw MakeInputError((fs::path(directory) / "drops.csv").string(), "drop " + drop.drop_id + ", column " + column,
                         "not a finite number: '" + cell + "'");
  return v;
}

std::string Dataset::PadReference(const DatasetDrop& drop) const { return Resolve(directory, drop.pad); }
std::string Dataset::SoilReference(const DatasetDrop& drop) const { return Resolve(directory, drop.soil); }

drop::DropRow Dataset::Row(const DatasetDrop& d) const {
  drop::DropRow row;
  row.impact_speed_m_s = d.impact_speed_m_s;
  row.mass_kg = d.pad_mass_kg;
  row.gravity_m_s2 = d.gravity_m_s2;
  row.atmosphere = d.atmosphere;
  row.tilt_rad = units::DegToRad(ExtraNumber(d, "tilt_deg").value_or(0.0));
  row.horizontal_speed_m_s = ExtraNumber(d, "horizontal_speed_m_s").value_or(0.0);
  return row;
}

Dataset ReadDataset(const std::string& directory, const DatasetReadOptions& options) {
  std::error_code ec;
  const fs::file_status status = fs::status(directory, ec);
  if (!fs::exists(status)) throw MakeInputError(directory, "", "dataset directory not found");
  if (!fs::is_directory(status)) throw MakeInputError(directory, "", "is not a directory (a dataset is a directory with drops.csv)");
  const std::string drops_csv = (fs::path(directory) / "drops.csv").string();
  const io::CsvTable t = io::ReadCsv(drops_csv);
  std::vector<int> required;
  for (const std::string& c : kDatasetDropColumns) required.push_back(t.Require(c));
  const int c_final = t.Find("final_penetration_m"), c_peak = t.Find("peak_force_N"), c_zero = t.Find("penetration_zero");
  Dataset ds;
  ds.directory = directory;
  std::vector<int> extra_index;
  for (size_t c = 0; c < t.header.size(); ++c) {
    const std::string& name = t.header[c];
    if (std::find(kDatasetDropColumns.begin(), kDatasetDropColumns.end(), name) != kDatasetDropColumns.end() ||
        std::find(kOptionalColumns.begin(), kOptionalColumns.end(), name) != kOptionalColumns.end())
      continue;
    ds.extra_columns.push_back(name);
    extra_index.push_back(static_cast<int>(c));
  }
  if (t.rows.empty()) throw MakeInputError(drops_csv, "line 2", "no drops");
  std::set<std::string> ids;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const auto& cells = t.rows[r];
    DatasetDrop d;
    auto text = [&](int column, const char* what) {
      if (cells[column].empty()) t.Fail(r, column, std::string("empty ") + what);
      return cells[column];
    };
    d.drop_id = text(required[0], "drop id");
    if (const std::string problem = DropIdProblem(d.drop_id); !problem.empty()) t.Fail(r, required[0], problem);
    if (!ids.insert(d.drop_id).second) t.Fail(r, required[0], "duplicate drop id '" + d.drop_id + "'");
    d.pad = text(required[1], "pad");
    d.soil = text(required[2], "soil");
    if (options.check_catalog) {
      CheckCatalog(t, r, required[1], "pads", Resolve(directory, d.pad));
      CheckCatalog(t, r, required[2], "soils", Resolve(directory, d.soil));
    }
    const std::string atmosphere = text(required[3], "atmosphere");
    const std::optional<rft::Atmosphere> parsed = rft::ParseAtmosphere(atmosphere);
    if (!parsed) t.Fail(r, required[3], "must be 'vacuum' or 'air', got '" + atmosphere + "'");
    d.atmosphere = *parsed;
    d.impact_speed_m_s = t.Number(r, required[4]);
    if (d.impact_speed_m_s < 0.0) t.Fail(r, required[4], "must be >= 0, got " + cells[required[4]]);
    d.pad_mass_kg = t.Number(r, required[5]);
    if (!(d.pad_mass_kg > 0.0)) t.Fail(r, required[5], "must be positive, got " + cells[required[5]]);
    d.gravity_m_s2 = t.Number(r, required[6]);
    if (!(d.gravity_m_s2 > 0.0)) t.Fail(r, required[6], "must be positive, got " + cells[required[6]]);
    d.trace_file = text(required[7], "trace path");
    if (fs::path(d.trace_file).is_absolute()) t.Fail(r, required[7], "must be relative to the dataset directory");
    const std::string trace_path = (fs::path(directory) / d.trace_file).string();
    try {
      RequireReadableFile(trace_path, "trace file");
    } catch (const InputError& e) {
      t.Fail(r, required[7], e.what());
    }
    if (c_final >= 0 && !cells[c_final].empty()) d.final_penetration_m = t.Number(r, c_final);
    if (c_peak >= 0 && !cells[c_peak].empty()) d.peak_force_N = t.Number(r, c_peak);
    if (c_zero >= 0 && !cells[c_zero].empty()) {
      const std::optional<PenetrationZero> zero = FindName(kPenetrationZeroNames, cells[c_zero]);
      if (!zero) t.Fail(r, c_zero, "must be " + NameChoices(kPenetrationZeroNames) + ", got '" + cells[c_zero] + "'");
      d.penetration_zero = *zero;
    }
    for (int c : extra_index) d.extra.push_back(cells[c]);
    if (options.load_traces) d.trace = ReadTrace(trace_path);
    ds.drops.push_back(std::move(d));
  }
  return ds;
}

void WriteDatasetFiles(const Dataset& ds, const std::string& directory) {
  bool any_final = false, any_peak = false, any_zero = false;
  std::set<std::string> ids;
  for (const DatasetDrop& d : ds.drops) {
    any_final |= d.final_penetration_m.has_value();
    any_peak |= d.peak_force_N.has_value();
    any_zero |= d.penetration_zero != PenetrationZero::kSurface;
    if (const std::string problem = DropIdProblem(d.drop_id); !problem.empty())
      throw MakeInputError(directory, "drop_id", problem);
    if (!ids.insert(d.drop_id).second) throw MakeInputError(directory, "drop_id", "duplicate drop id '" + d.drop_id + "'");
    if (d.extra.size() != ds.extra_columns.size())
      throw MakeInputError(directory, "drop " + d.drop_id, "extra cells do not match the extra columns");
    if (d.trace_file.empty() || fs::path(d.trace_file).is_absolute() ||
        fs::path(d.trace_file).lexically_normal().string().rfind("..", 0) == 0)
      throw MakeInputError(directory, "drop " + d.drop_id, "trace path must be relative and inside the dataset");
    for (const std::string& s : {d.drop_id, d.pad, d.soil, d.trace_file})
      if (s.find_first_of(",\n\r") != std::string::npos)
        throw MakeInputError(directory, "drop " + d.drop_id, "a name or path contains a comma or line break: " + s);
  }
  io::WriteFileAtomically((fs::path(directory) / "drops.csv").string(), [&](std::ostream& out) {
    for (size_t i = 0; i < kDatasetDropColumns.size(); ++i) out << (i ? "," : "") << kDatasetDropColumns[i];
    if (any_final) out << ",final_penetration_m";
    if (any_peak) out << ",peak_force_N";
    if (any_zero) out << ",penetration_zero";
    for (const std::string& c : ds.extra_columns) out << ',' << c;
    out << '\n';
    for (const DatasetDrop& d : ds.drops) {
      out << d.drop_id << ',' << d.pad << ',' << d.soil << ',' << rft::AtmosphereName(d.atmosphere) << ','
          << io::FormatNumber(d.impact_speed_m_s) << ',' << io::FormatNumber(d.pad_mass_kg) << ','
          << io::FormatNumber(d.gravity_m_s2) << ',' << d.trace_file;
      if (any_final) out << ',' << (d.final_penetration_m ? io::FormatNumber(*d.final_penetration_m) : "");
      if (any_peak) out << ',' << (d.peak_force_N ? io::FormatNumber(*d.peak_force_N) : "");
      if (any_zero) out << ',' << NameIn(kPenetrationZeroNames, d.penetration_zero);
      for (const std::string& cell : d.extra) out << ',' << cell;
      out << '\n';
    }
  });
  for (const DatasetDrop& d : ds.drops) {
    const fs::path path = fs::path(directory) / d.trace_file;
    fs::create_directories(path.parent_path());
    const DatasetTrace& tr = d.trace;
    io::WriteFileAtomically(path.string(), [&](std::ostream& out) {
      out << "t_s,penetration_m,force_N";
      for (const std::string& c : tr.extra_columns) out << ',' << c;
      out << '\n';
      for (size_t i = 0; i < tr.size(); ++i) {
        out << io::FormatNumber(tr.t_s[i]) << ',' << io::FormatNumber(tr.penetration_m[i]) << ','
            << io::FormatNumber(tr.force_N[i]);
        for (const auto& column : tr.extra) out << ',' << io::FormatNumber(column[i]);
        out << '\n';
      }
    });
  }
}

void WriteDataset(const Dataset& dataset, const io::OutputTarget& target) {
  io::WriteOutputDirectory(target, io::OutputKind::kDataset,
                       [&](const std::string& staging) { WriteDatasetFiles(dataset, staging); });
}

}  // namespace touchdown::dataset

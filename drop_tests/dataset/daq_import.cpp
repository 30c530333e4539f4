#include "drop_tests/dataset/daq_import.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "drop_tests/dataset/channel_filter.h"
#include "drop_tests/dataset/daq_csv.h"
#include "drop_tests/dataset/daq_penetration.h"
#include "drop_tests/formats/dataset_csv.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/units.h"

namespace touchdown::dataset {

namespace fs = std::filesystem;

namespace {

// A DAQ samples at a fixed rate; a spacing off by more than this share of the mean is a missing,
// repeated or reordered sample (the time columns seen print 0.1 us, 1e-3 of a 10 kHz period).
constexpr double kUniformSpacingTolerance = 0.01;

// The channel in SI units: gain (raw - offset).
std::vector<double> Converted(const std::vector<double>& raw, const DaqChannel& c) {
  std::vector<double> out(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) out[i] = c.gain * (raw[i] - c.offset);
  return out;
}

// The sample times in seconds, checked increasing and uniform.
std::vector<double> SampleTimes(const DaqMapping& m, const DaqColumns& columns) {
  const size_t n = columns.lines.size();
  std::vector<double> t(n);
  if (m.time_column.empty()) {
    for (size_t i = 0; i < n; ++i) t[i] = double(i) / m.sample_rate_hz;
    return t;
  }
  io::CsvTable table;  // for the dataset reader's wording of a cell's place
  table.file = columns.file;
  table.header = columns.header;
  const int column = static_cast<int>(std::find(columns.header.begin(), columns.header.end(), m.time_column) - columns.header.begin());
  for (size_t i = 0; i < n; ++i) {
    t[i] = columns.values[0][i] * m.time_unit_s;
    if (i > 0 && !(t[i] > t[i - 1]))
      table.FailAt(columns.lines[i], column, "time must increase strictly (previous sample: " + io::FormatNumber(columns.values[0][i - 1]) + ")");
  }
  if (n < 2) return t;
  const double mean = (t.back() - t.front()) / double(n - 1);
  for (size_t i = 1; i < n; ++i)
    if (std::abs(t[i] - t[i - 1] - mean) > kUniformSpacingTolerance * mean)
      table.FailAt(columns.lines[i], column,
                   "sample spacing " + io::FormatNumber((t[i] - t[i - 1]) / m.time_unit_s) + " against the record's mean " +
                       io::FormatNumber(mean / m.time_unit_s) +
                       ": import needs a uniform sample rate (a missing, repeated or reordered sample?)");
  return t;
}

std::vector<double> Filtered(const std::vector<double>& x, const DaqChannel& c, double period, const DaqMapping& m,
                             const DaqDropEntry& d) {
  if (c.filter == ChannelFilter::kNone) return x;
  if (1.0 / period < MinSampleRateHz(c.filter) * (1.0 - 1e-9))
    throw MakeInputError(m.source, c.field + ".filter",
                         std::string(ChannelFilterName(c.filter)) + " needs a sample rate of " +
                             io::FormatNumber(MinSampleRateHz(c.filter)) + " Hz at least (10 CFC), and " + d.path +
                             " is sampled at " + io::FormatNumber(std::round(1.0 / period * 1e3) / 1e3) +
                             " Hz: choose a lower class or none");
  return ApplyChannelFilter(x, c.filter, period);
}

double PretriggerMean(const std::vector<double>& x, size_t n) {
  double sum = 0;
  for (size_t i = 0; i < n; ++i) sum += x[i];
  return sum / double(n);
}

ImportedDrop ImportDrop(const DaqMapping& m, const DaqDropEntry& d, DatasetDrop* out) {
  std::vector<std::string> names;
  if (!m.time_column.empty()) names.push_back(m.time_column);
  names.push_back(m.force.column);
  names.push_back(m.motion.column);
  const DaqColumns columns = ReadDaqColumns(d.path, m.text, names);
  const size_t first_channel = m.time_column.empty() ? 0 : 1;
  const std::vector<double> t = SampleTimes(m, columns);
  ImportedDrop r;
  r.drop_id = d.drop_id;
  r.raw_path = d.path;
  r.samples = t.size();
  const double period = t.size() > 1 ? (t.back() - t.front()) / double(t.size() - 1) : 1.0;
  r.sample_rate_hz = 1.0 / period;

  std::vector<double> force = Filtered(Converted(columns.values[first_channel], m.force), m.force, period, m, d);
  std::vector<double> motion = Filtered(Converted(columns.values[first_channel + 1], m.motion), m.motion, period, m, d);

  OnsetOptions options;
  options.threshold_N = m.threshold_N;
  // A phaseless CFC filter reaches ahead of a jump by about 1 / F_H (F_H = 5/3 CFC, its -3 dB
  // frequency); the pre-trigger's zero and noise stay clear of it.
  if (m.force.filter != ChannelFilter::kNone) options.guard_s = 1.0 / (5.0 / 3.0 * ChannelFrequencyClass(m.force.filter));
  r.onset = DetectTouchdown(t, force, options, d.path);
  const size_t pre = r.onset.pretrigger_end;
  if (m.force.zero == ChannelZero::kPreTrigger) r.force_zero_N = r.onset.baseline_N;
  for (double& f : force) f -= r.force_zero_N;

  double motion_zero = 0.0;
  if (m.motion.zero == ChannelZero::kPreTrigger) motion_zero = PretriggerMean(motion, pre);
  if (m.motion.zero == ChannelZero::kFreeFall) motion_zero = PretriggerMean(motion, pre) - d.gravity_m_s2;
  for (double& x : motion) x -= motion_zero;
  std::vector<double> penetration;
  if (m.motion_kind == MotionChannel::kDisplacement) {
    DisplacementPenetration p = PenetrationFromDisplacement(t, motion, r.onset.t0_s, pre, d.path);
    r.displacement_at_touchdown_m = p.at_touchdown_m;
    r.measured_impact_speed_m_s = p.speed_m_s;
    penetration = std::move(p.penetration_m);
  } else {
    AccelerationPenetration p =
        PenetrationFromAcceleration(t, motion, r.onset.t0_s, d.impact_speed_m_s, pre, d.path);
    r.acceleration_bias_m_s2 = p.bias_m_s2;
    r.rest_velocity_m_s = p.rest_velocity_m_s;
    r.pretrigger_acceleration_m_s2 = p.pretrigger_acceleration_m_s2;
    penetration = std::move(p.penetration_m);
  }

  out->drop_id = d.drop_id;
  out->pad = d.pad;
  out->soil = d.soil;
  out->atmosphere = d.atmosphere;
  out->impact_speed_m_s = d.impact_speed_m_s;
  out->pad_mass_kg = d.pad_mass_kg;
  out->gravity_m_s2 = d.gravity_m_s2;
  out->trace_file = "traces/" + d.drop_id + ".csv";
  out->trace.t_s.resize(t.size());
  for (size_t i = 0; i < t.size(); ++i) out->trace.t_s[i] = t[i] - r.onset.t0_s;
  out->trace.penetration_m = std::move(penetration);
  // Both ways zero it at the detected touchdown: the displacement at the free-fall fit's value
  // there, the acceleration's double integral from there. A late detection moves that zero along
  // the free fall (dataset.h), which diagnose's per-drop time takes up with it.
  out->penetration_zero = PenetrationZero::kTouchdown;
  out->trace.force_N = std::move(force);
  out->extra = d.extra;
  const auto number = [](double v) { return io::FormatNumber(v); };
  for (const std::string& cell :
       {d.file, number(r.onset.t0_s), number(r.onset.uncertainty_s), number(r.onset.jump_N), number(r.onset.exponent),
        number(r.onset.t0_s - t.front()), number(r.force_zero_N), number(r.onset.noise_N),
        std::string(ChannelFilterName(m.force.filter)), std::string(MotionChannelName(m.motion_kind)),
        std::string(ChannelFilterName(m.motion.filter))})
    out->extra.push_back(cell);
  if (m.motion_kind == MotionChannel::kDisplacement) {
    out->extra.push_back(number(r.displacement_at_touchdown_m));
    out->extra.push_back(number(r.measured_impact_speed_m_s));
  } else {
    out->extra.push_back(number(r.acceleration_bias_m_s2));
    out->extra.push_back(number(r.rest_velocity_m_s));
    out->extra.push_back(number(r.pretrigger_acceleration_m_s2));
  }
  return r;
}

std::string Milliseconds(double seconds) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(3) << seconds * units::kMsPerS;
  return s.str();
}

void WriteImportReadme(const ImportRun& run, std::ostream& out) {
  const DaqMapping& m = run.mapping;
  const std::string mapping = fs::absolute(m.source).lexically_normal().string();
  out << "# Dataset: " << m.name << "\n\n"
      << "Imported by `touchdown import` from raw DAQ files, as the mapping `" << mapping
      << "` names them (a copy of it is `import.yaml` here; its `file:` paths are relative to the original's "
         "folder). See docs/import.md for each step.\n\n";
  if (!m.description.empty()) out << m.description << "\n\n";
  auto channel = [](const DaqChannel& c) {
    return "column `" + c.column + "`, gain " + io::FormatNumber(c.gain) + " per raw unit, offset " +
           io::FormatNumber(c.offset) + ", filter " + ChannelFilterName(c.filter) + ", zero " + ChannelZeroName(c.zero);
  };
  out << "- drops: " << run.dataset.drops.size() << "\n"
      << "- time: "
      << (m.time_column.empty() ? "row index / " + io::FormatNumber(m.sample_rate_hz) + " Hz" : "column `" + m.time_column + "`")
      << "; t = 0 at the touchdown found on the force (touchdown_time_in_file_s in drops.csv, in the raw file's clock)\n"
      << "- force [N, up]: " << channel(m.force) << "\n"
      << "- " << MotionChannelName(m.motion_kind)
      << (m.motion_kind == MotionChannel::kDisplacement ? " [m, down]: " : " [m/s^2, down]: ") << channel(m.motion) << "\n"
      << "- touchdown trigger: "
      << (m.threshold_N > 0 ? io::FormatNumber(m.threshold_N) + " N above the pre-trigger" : std::string("5 sigma of the pre-trigger noise"))
      << ", refined by the onset fit\n\n"
      << "| drop_id | raw file | samples | rate [Hz] | touchdown in file [s] | uncertainty [ms] | pre-trigger [ms] | force noise [N] |\n"
      << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (size_t i = 0; i < run.drops.size(); ++i) {
    const ImportedDrop& r = run.drops[i];
    out << "| " << r.drop_id << " | " << fs::absolute(r.raw_path).lexically_normal().string() << " | " << r.samples << " | "
        << io::FormatNumber(std::round(r.sample_rate_hz * 1e3) / 1e3) << " | " << io::FormatNumber(r.onset.t0_s) << " | "
        << Milliseconds(r.onset.uncertainty_s) << " | "
        << Milliseconds(run.dataset.drops[i].trace.t_s.empty() ? 0.0 : -run.dataset.drops[i].trace.t_s.front()) << " | "
        << io::FormatNumber(std::round(r.onset.noise_N * 1e4) / 1e4) << " |\n";
  }
}

}  // namespace

ImportRun ImportRaw(const std::string& mapping_path) {
  ImportRun run;
  run.mapping = LoadDaqMapping(mapping_path);
  const DaqMapping& m = run.mapping;
  run.dataset.extra_columns = m.extra_columns;
  for (const std::string& c : kImportColumns) run.dataset.extra_columns.push_back(c);
  for (const std::string& c : m.motion_kind == MotionChannel::kDisplacement ? kImportDisplacementColumns : kImportAccelerationColumns)
    run.dataset.extra_columns.push_back(c);
  double samples = 0;
  for (const DaqDropEntry& d : m.drops) {
    DatasetDrop drop;
    run.drops.push_back(ImportDrop(m, d, &drop));
    samples += double(run.drops.back().samples);
    if (samples > kMaxImportSamples)
      throw MakeInputError(m.source, d.field + ".file",
                           "the raw files up to this one hold " + io::FormatNumber(samples) + " samples, more than the " +
                               io::FormatNumber(kMaxImportSamples) + " one import keeps in memory: split the mapping");
    run.dataset.drops.push_back(std::move(drop));
  }
  return run;
}

void WriteImportedDataset(const ImportRun& run, const io::OutputTarget& out) {
  const std::string mapping_text = ReadInputFile(run.mapping.source, "mapping file");
  io::WriteOutputDirectory(out, io::OutputKind::kDataset, [&](const std::string& staging) {
    WriteDatasetFiles(run.dataset, staging);
    io::WriteFileAtomically((fs::path(staging) / "README.md").string(), [&](std::ostream& o) { WriteImportReadme(run, o); });
    io::WriteFileAtomically((fs::path(staging) / "import.yaml").string(), [&](std::ostream& o) { o << mapping_text; });
  });
}

ImportRun ImportToDirectory(const std::string& mapping_path, const io::OutputTarget& out) {
  io::CheckOutputDirectory(out, io::OutputKind::kDataset);
  ImportRun run = ImportRaw(mapping_path);
  io::OutputTarget target = out;
  target.inputs.push_back(mapping_path);
  for (const DaqDropEntry& d : run.mapping.drops) target.inputs.push_back(d.path);
  WriteImportedDataset(run, target);
  return run;
}

nlohmann::json ImportSummaryJson(const ImportRun& run, const std::string& out) {
  nlohmann::json drops = nlohmann::json::array();
  for (size_t i = 0; i < run.drops.size(); ++i) {
    const ImportedDrop& r = run.drops[i];
    const DatasetDrop& d = run.dataset.drops[i];
    drops.push_back({{"drop_id", r.drop_id},
                     {"samples", r.samples},
                     {"touchdown_time_in_file_s", r.onset.t0_s},
                     {"touchdown_uncertainty_s", r.onset.uncertainty_s},
                     {"pretrigger_force_noise_N", r.onset.noise_N},
                     {"final_penetration_m", d.FinalPenetration()},
                     {"peak_force_N", d.PeakForce()}});
  }
  return {{"name", run.mapping.name},
          {"out", out},
          {"drops", run.dataset.drops.size()},
          {"penetration_from", MotionChannelName(run.mapping.motion_kind)},
          {"per_drop", drops}};
}

}  // namespace touchdown::dataset

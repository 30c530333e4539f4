#include "drop_tests/dataset/daq_mapping.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"

namespace touchdown::dataset {

namespace fs = std::filesystem;

const std::vector<std::string> kDaqDropKeys = {"file",         "drop_id",          "pad",
                                               "soil",         "atmosphere",       "impact_speed_m_s",
                                               "pad_mass_kg",  "gravity_m_s2"};
const std::vector<std::string> kImportColumns = {
    "raw_file",     "touchdown_time_in_file_s", "touchdown_uncertainty_s", "onset_jump_N",     "onset_exponent",
    "pretrigger_s", "force_zero_N",             "pretrigger_force_noise_N", "force_filter",     "penetration_from",
    "penetration_filter"};
const std::vector<std::string> kImportDisplacementColumns = {"displacement_at_touchdown_m", "measured_impact_speed_m_s"};
const std::vector<std::string> kImportAccelerationColumns = {"acceleration_bias_m_s2", "rest_velocity_m_s",
                                                              "pretrigger_acceleration_m_s2"};

const char* ChannelZeroName(ChannelZero zero) { return NameIn(kChannelZeroNames, zero); }

const char* MotionChannelName(MotionChannel kind) { return NameIn(kMotionChannelNames, kind); }

namespace {
// An import mapping's keys, block by block (docs/import.md; docs/reference.md).
// The numbers a mapping gives on their own: checked at load, documented from the same entries.
const io::NumberKey kDaqSampleRate{"sample_rate_hz", io::Sign::kPositive, nullptr, "one of `column`, `sample_rate_hz`"};
const io::NumberKey kDaqThreshold{"threshold_N", io::Sign::kPositive, nullptr, "automatic (5 sigma of the pre-trigger's noise)"};
const io::NumberKey kDaqDropSpeed{"impact_speed_m_s", io::Sign::kAny, &limits::kSpeed_m_s};
const io::NumberKey kDaqDropMass{"pad_mass_kg", io::Sign::kAny, &limits::kMass_kg};
const io::NumberKey kDaqDropGravity{"gravity_m_s2", io::Sign::kAny, &limits::kGravity_m_s2};
const std::vector<std::string> kMappingKeys{"schema_version", "type", "name", "description", "daq", "channels",
                                            "touchdown", "drops"};
const std::vector<std::string> kDaqKeys{"delimiter", "comment", "decimal", "time"};
const std::vector<std::string> kTimeKeys{"column", "unit", "sample_rate_hz"};
const std::vector<std::string> kChannelsKeys{"force", "displacement", "acceleration"};
const std::vector<std::string> kChannelKeys{"column", "gain", "offset", "filter", "zero"};
const std::vector<std::string> kTouchdownKeys{"channel", "threshold_N"};

constexpr double kMaxDaqSampleRate_Hz = 1e7;

char OneCharacter(const io::YamlFields& f, const std::string& key, const std::string& fallback) {
  const std::string text = f.StringOr(key, fallback);
  if (text.size() != 1) f.Fail(key, "must be one character, got '" + text + "'");
  return text[0];
}

DaqChannel LoadChannel(const io::YamlFields& channels, const std::string& key, ChannelZero default_zero) {
  const io::YamlFields f = channels.Child(key);
  f.RequireOnly(kChannelKeys);
  DaqChannel c;
  c.field = f.prefix();
  c.column = f.String("column");
  c.gain = f.Number("gain");
  if (c.gain == 0.0) f.Fail("gain", "must not be 0 (it converts raw units into SI units; negative flips the sign)");
  c.offset = f.Has("offset") ? f.Number("offset") : 0.0;
  const std::string filter = f.StringOr("filter", "none");
  const std::optional<ChannelFilter> parsed = ParseChannelFilter(filter);
  if (!parsed) f.Fail("filter", "must be " + ChannelFilterChoices() + ", got '" + filter + "'");
  c.filter = *parsed;
  c.zero = default_zero;
  if (f.Has("zero")) {
    const std::string zero = f.String("zero");
    if (zero == "none") c.zero = ChannelZero::kNone;
    else if (zero == "pre_trigger") c.zero = ChannelZero::kPreTrigger;
    else if (zero == "free_fall" && key == "acceleration") c.zero = ChannelZero::kFreeFall;
    else
      f.Fail("zero", "must be pre_trigger or none" + std::string(key == "acceleration" ? " or free_fall" : "") + ", got '" +
                         zero + "'" +
                         (zero == "free_fall" ? " (free_fall sets an acceleration's pre-trigger mean to +g)" : ""));
  }
  return c;
}

void LoadTime(const io::YamlFields& daq, DaqMapping& m) {
  const io::YamlFields f = daq.Child("time");
  f.RequireOnly(kTimeKeys);
  if (f.Has("column") == f.Has("sample_rate_hz"))
    throw MakeInputError(f.file(), f.prefix(), "give either {column: NAME, unit: s|ms|us} or {sample_rate_hz: RATE}");
  if (f.Has("sample_rate_hz")) {
    if (f.Has("unit")) f.Fail("unit", "goes with a time column, not with sample_rate_hz");
    m.sample_rate_hz = io::ReadNumber(f, kDaqSampleRate);
    if (m.sample_rate_hz > kMaxDaqSampleRate_Hz)
      f.Fail("sample_rate_hz", "must be at most 1e7 Hz, got " + io::FormatNumber(m.sample_rate_hz));
    return;
  }
  m.time_column = f.String("column");
  const std::string unit = f.String("unit");
  const std::map<std::string, double> units = {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}};
  const auto found = units.find(unit);
  if (found == units.end()) f.Fail("unit", "must be s, ms or us, got '" + unit + "'");
  m.time_unit_s = found->second;
}

void LoadDaq(const io::YamlFields& root, DaqMapping& m) {
  const io::YamlFields f = root.Child("daq");
  f.RequireOnly(kDaqKeys);
  m.text.delimiter = OneCharacter(f, "delimiter", ",");
  m.text.decimal = OneCharacter(f, "decimal", ".");
  m.text.comment = f.StringOr("comment", "#");
  const char d = m.text.delimiter;
  if (std::isalnum(static_cast<unsigned char>(d)) || d == '"' || d == '.' || d == '+' || d == '-' || d == '\r' || d == '\n')
    f.Fail("delimiter", std::string("cannot be '") + d + "': it can be part of a number or a quoted cell");
  if (m.text.decimal != '.' && m.text.decimal != ',')
    f.Fail("decimal", std::string("must be '.' or ',', got '") + m.text.decimal + "'");
  if (m.text.decimal == d) f.Fail("decimal", "cannot be the delimiter too");
  LoadTime(f, m);
}

bool IsReservedColumn(const std::string& key) {
  for (const auto* list : {&kDatasetDropColumns, &kImportColumns, &kImportDisplacementColumns, &kImportAccelerationColumns})
    if (std::find(list->begin(), list->end(), key) != list->end()) return true;
  return key == "final_penetration_m" || key == "peak_force_N";
}

// A catalogue name as written, or a pad or soil file beside the mapping as its absolute path (a
// dataset reads relative paths against its own folder, which is elsewhere).
std::string CatalogReference(const io::YamlFields& f, const std::string& key, const std::string& kind) {
  const std::string reference = f.String(key);
  std::string resolved;
  try {
    resolved = io::ResolveCatalogFileNear(f.file(), kind, reference);
    RequireReadableFile(resolved, kind == "pads" ? "pad file" : "soil file");
  } catch (const InputError& e) {
    f.Fail(key, std::string("unknown ") + (kind == "pads" ? "pad" : "soil") + " '" + reference + "' (" + e.what() + ")");
  }
  const bool is_path = reference.find('/') != std::string::npos || reference.ends_with(".yaml") || reference.ends_with(".yml");
  const std::string cell = is_path ? fs::absolute(resolved).lexically_normal().string() : reference;
  if (cell.find_first_of(",\n\r") != std::string::npos)
    f.Fail(key, "'" + cell + "' holds a comma or a line break, which drops.csv cannot hold");
  return cell;
}

DaqDropEntry LoadDropEntry(const io::YamlFields& f, DaqMapping& m) {
  DaqDropEntry d;
  d.field = f.prefix();
  d.file = f.String("file");
  d.path = (fs::path(m.source).parent_path() / d.file).lexically_normal().string();
  if (fs::path(d.file).is_absolute()) d.path = fs::path(d.file).lexically_normal().string();
  try {
    RequireReadableFile(d.path, "raw file");
  } catch (const InputError& e) {
    f.Fail("file", e.what());
  }
  d.drop_id = f.String("drop_id");
  if (const std::string problem = DropIdProblem(d.drop_id); !problem.empty()) f.Fail("drop_id", problem);
  if (d.drop_id.find_first_of(",\n\r") != std::string::npos)
    f.Fail("drop_id", "'" + d.drop_id + "' holds a comma or a line break, which drops.csv cannot hold");
  d.pad = CatalogReference(f, "pad", "pads");
  d.soil = CatalogReference(f, "soil", "soils");
  const std::string atmosphere = f.String("atmosphere");
  const std::optional<rft::Atmosphere> parsed = rft::ParseAtmosphere(atmosphere);
  if (!parsed) f.Fail("atmosphere", "must be vacuum or air, got '" + atmosphere + "'");
  d.atmosphere = *parsed;
  d.impact_speed_m_s = io::ReadNumber(f, kDaqDropSpeed);
  d.pad_mass_kg = io::ReadNumber(f, kDaqDropMass);
  d.gravity_m_s2 = io::ReadNumber(f, kDaqDropGravity);
  // Further keys: columns of drops.csv, in the order they first appear over the drops.
  std::vector<std::pair<std::string, std::string>> extra;
  for (const auto& item : f.node()) {
    const std::string key = item.first.Scalar();
    if (std::find(kDaqDropKeys.begin(), kDaqDropKeys.end(), key) != kDaqDropKeys.end()) continue;
    if (IsReservedColumn(key))
      f.Fail(key, "is a column touchdown writes itself; give the drop's own value another name");
    if (key.empty() || key.find_first_of(",\n\r\"") != std::string::npos)
      f.Fail(key, "a further key becomes a column of drops.csv: no comma, quote or line break in its name");
    if (!item.second.IsScalar()) f.Fail(key, "a further key becomes a cell of drops.csv: give one value, not a list or mapping");
    const std::string cell = item.second.Scalar();
    if (cell.find_first_of(",\n\r") != std::string::npos)
      f.Fail(key, "'" + cell + "' holds a comma or a line break, which drops.csv cannot hold");
    if (std::find(m.extra_columns.begin(), m.extra_columns.end(), key) == m.extra_columns.end()) m.extra_columns.push_back(key);
    extra.emplace_back(key, cell);
  }
  d.extra.assign(m.extra_columns.size(), "");
  for (const auto& [key, cell] : extra)
    d.extra[std::find(m.extra_columns.begin(), m.extra_columns.end(), key) - m.extra_columns.begin()] = cell;
  return d;
}

}  // namespace

std::vector<io::BlockDoc> DaqMappingSchema() {
  const std::string read_by = "drop_tests/dataset/daq_mapping.cpp";
  return {io::MakeBlock("import", read_by, io::PlainKeyDocs(kMappingKeys)),
          io::MakeBlock("import.daq", read_by, io::PlainKeyDocs(kDaqKeys)),
          io::MakeBlock("import.daq.time", read_by, io::DocsWith(kTimeKeys, {kDaqSampleRate})),
          io::MakeBlock("import.channels", read_by, io::PlainKeyDocs(kChannelsKeys)),
          io::MakeBlock("import.channels.channel", read_by, io::PlainKeyDocs(kChannelKeys)),
          io::MakeBlock("import.touchdown", read_by, io::DocsWith(kTouchdownKeys, {kDaqThreshold})),
          io::MakeBlock("import.drops", read_by, io::DocsWith(kDaqDropKeys, {kDaqDropSpeed, kDaqDropMass, kDaqDropGravity}))};
}

DaqMapping LoadDaqMapping(const std::string& path) {
  const io::YamlFields root = io::YamlFields::LoadFile(path);
  root.RequireOnly(kMappingKeys);
  root.RequireSchemaVersion(1);
  if (const std::string type = root.String("type"); type != "import")
    root.Fail("type", "must be 'import' for a mapping of raw drop files, got '" + type + "'");
  DaqMapping m;
  m.source = path;
  m.name = root.Name("name");
  m.description = root.StringOr("description", "");
  LoadDaq(root, m);

  const io::YamlFields channels = root.Child("channels");
  channels.RequireOnly(kChannelsKeys);
  m.force = LoadChannel(channels, "force", ChannelZero::kPreTrigger);
  if (channels.Has("displacement") == channels.Has("acceleration"))
    throw MakeInputError(path, "channels", "give one of displacement or acceleration (the penetration comes from one of them)");
  m.motion_kind = channels.Has("displacement") ? MotionChannel::kDisplacement : MotionChannel::kAcceleration;
  m.motion = LoadChannel(channels, MotionChannelName(m.motion_kind), ChannelZero::kNone);
  if (m.time_column == m.force.column || m.time_column == m.motion.column || m.force.column == m.motion.column)
    throw MakeInputError(path, "channels",
                         "time, force and " + std::string(MotionChannelName(m.motion_kind)) + " must be three different columns");

  if (root.Has("touchdown")) {
    const io::YamlFields f = root.Child("touchdown");
    f.RequireOnly(kTouchdownKeys);
    if (const std::string channel = f.StringOr("channel", "force"); channel != "force")
      f.Fail("channel", "must be force (touchdown is found on the force), got '" + channel + "'");
    if (f.Has(kDaqThreshold.key)) m.threshold_N = io::ReadNumber(f, kDaqThreshold);
  }

  std::map<std::string, std::string> ids, files;
  for (const io::YamlFields& f : root.List("drops")) {
    DaqDropEntry d = LoadDropEntry(f, m);
    if (const auto [it, fresh] = ids.emplace(d.drop_id, d.field); !fresh)
      f.Fail("drop_id", "'" + d.drop_id + "' is " + it->second + "'s id too");
    if (const auto [it, fresh] = files.emplace(fs::absolute(d.path).lexically_normal().string(), d.field); !fresh)
      f.Fail("file", "'" + d.file + "' is " + it->second + "'s raw file too");
    m.drops.push_back(std::move(d));
  }
  for (DaqDropEntry& d : m.drops) d.extra.resize(m.extra_columns.size());  // keys first seen in a later drop
  return m;
}

}  // namespace touchdown::dataset

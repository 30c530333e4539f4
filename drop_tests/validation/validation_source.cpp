#include "drop_tests/validation/validation_source.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/validation/katsuragi_durian.h"
#include "drop_tests/validation/shallow_impact_depth.h"
#include "lander/pad/release.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::validation {

namespace fs = std::filesystem;

const char* QuantityName(Quantity q) { return NameIn(kQuantityNames, q); }
const char* QuantityUnit(Quantity q) { return q == Quantity::kFinalDepth ? "mm" : "ms"; }
double QuantityToReport(Quantity) { return 1e3; }
const char* VariableName(Variable v) { return NameIn(kVariableNames, v); }
const char* ProvenanceName(Provenance p) { return NameIn(kProvenanceNames, p); }

namespace {
// A validation source's keys, block by block, and a validation model file's (docs/validation.md;
// docs/reference.md).
const std::vector<std::string> kSourceKeys{"schema_version", "type", "id", "citation", "read_at", "projectile",
                                           "medium", "gravity_m_s2", "low_gravity", "measured_law", "points",
                                           "trends", "static_bearing", "provenance"};
const std::vector<std::string> kProjectileKeys{"pad", "description"};
const std::vector<std::string> kMediumKeys{"soil", "description", "zeta_route", "calibrated_on"};
const std::vector<std::string> kKatsuragiDurianKeys{"kind", "d1_mm", "d1_uncertainty_mm", "k_over_m_per_s2",
                                                    "k_over_m_uncertainty_per_s2", "how", "where"};
const std::vector<std::string> kShallowImpactKeys{"kind", "prefactor", "friction_coefficient", "how", "where"};
const std::vector<std::string> kPointKeys{"id", "impact_speed_m_s", "drop_height_mm", "quantity", "depth_mm",
                                          "stop_time_ms", "uncertainty_mm", "uncertainty_ms", "from_law", "how",
                                          "where"};
const std::vector<std::string> kTrendKeys{"id", "quantity", "vary", "values", "at_impact_speed_m_s",
                                          "at_gravity_m_s2", "exponent", "tolerance", "tolerance_source",
                                          "tolerance_note", "direction", "how", "where"};
const std::vector<std::string> kBearingKeys{"id", "pressure_N_cm2", "depth_mm", "diameter_mm", "how", "where"};
const std::vector<std::string> kValidationModelKeys{"schema_version", "type", "inertial_drag_lambda", "source",
                                                    "provenance"};

// Every number a source gives is range-checked at load, as a scenario's is (rft/physical_limits.h
// where a bound exists there), in the file's own units: a measured depth of 1e9 mm would otherwise
// be simulated, and a law's 1e308 reach its Lambert W.
constexpr limits::Range kLength_mm{"mm", 0.0, limits::kDepth_m.high * units::kMmPerM, true};       // depths, d1, diameters
constexpr limits::Range kUncertainty_mm{"mm", 0.0, limits::kDepth_m.high * units::kMmPerM, false};
constexpr limits::Range kDropHeight_mm{"mm", 0.0, limits::kDropHeight_m.high * units::kMmPerM, false};
constexpr limits::Range kStopTime_ms{"ms", 0.0, 1e5, true};                               // 100 s
constexpr limits::Range kUncertainty_ms{"ms", 0.0, 1e5, false};
constexpr limits::Range kPressure_N_cm2{"N/cm^2", 0.0, 1e6, true};                        // 10 GPa
// Katsuragi & Durian's k/m: 1040 s^-2 for their sphere; 1e8 is a 1e4 times stiffer bed under a
// 1e4 times lighter sphere.
constexpr limits::Range kKOverM_per_s2{"1/s^2", 0.0, 1e8, true};
constexpr limits::Range kKOverMUncertainty_per_s2{"1/s^2", 0.0, 1e8, false};
constexpr limits::Range kCoefficient{"(dimensionless)", 0.0, 1e3, true};  // a prefactor, a friction coefficient
constexpr limits::Range kExponent{"(dimensionless)", -100.0, 100.0, false};

// A source's numbers: each within its range (file units), read and documented from one entry.
const io::NumberKey kSourceGravity{"gravity_m_s2", io::Sign::kAny, &limits::kGravity_m_s2};
const io::NumberKey kD1{"d1_mm", io::Sign::kAny, &kLength_mm};
const io::NumberKey kD1Uncertainty{"d1_uncertainty_mm", io::Sign::kAny, &kUncertainty_mm};
const io::NumberKey kKOverM{"k_over_m_per_s2", io::Sign::kAny, &kKOverM_per_s2};
const io::NumberKey kKOverMUncertainty{"k_over_m_uncertainty_per_s2", io::Sign::kAny, &kKOverMUncertainty_per_s2};
const io::NumberKey kPrefactor{"prefactor", io::Sign::kAny, &kCoefficient};
const io::NumberKey kFrictionCoefficient{"friction_coefficient", io::Sign::kAny, &kCoefficient};
const io::NumberKey kPointSpeed{"impact_speed_m_s", io::Sign::kAny, &limits::kSpeed_m_s,
                                "one of `impact_speed_m_s`, `drop_height_mm`"};
const io::NumberKey kPointDropHeight{"drop_height_mm", io::Sign::kAny, &kDropHeight_mm,
                                     "one of `impact_speed_m_s`, `drop_height_mm`"};
const io::NumberKey kPointDepth{"depth_mm", io::Sign::kAny, &kLength_mm, "with `final_depth`"};
const io::NumberKey kPointStopTime{"stop_time_ms", io::Sign::kAny, &kStopTime_ms, "with `stop_time`"};
const io::NumberKey kPointDepthUncertainty{"uncertainty_mm", io::Sign::kAny, &kUncertainty_mm, "none"};
const io::NumberKey kPointTimeUncertainty{"uncertainty_ms", io::Sign::kAny, &kUncertainty_ms, "none"};
const io::NumberKey kTrendExponent{"exponent", io::Sign::kAny, &kExponent, "one of `exponent`, `direction`"};
const io::NumberKey kTrendTolerance{"tolerance", io::Sign::kAny, &kCoefficient, "with `exponent`"};
const io::NumberKey kTrendGravity{"at_gravity_m_s2", io::Sign::kAny, &limits::kGravity_m_s2, "the source's"};
const io::NumberKey kTrendSpeed{"at_impact_speed_m_s", io::Sign::kAny, &limits::kSpeed_m_s,
                                "*required* (unless the trend varies the speed)"};
// A measured range's ends, each within its range.
const io::NumberKey kBearingPressure{"pressure_N_cm2", io::Sign::kAny, &kPressure_N_cm2};
const io::NumberKey kBearingDepth{"depth_mm", io::Sign::kAny, &kLength_mm};
const io::NumberKey kBearingDiameter{"diameter_mm", io::Sign::kAny, &limits::kPadSize_mm};

double InRange(const io::YamlFields& f, const io::NumberKey& key) { return io::ReadNumber(f, key); }

Quantity ReadQuantity(const io::YamlFields& f) {
  const std::string q = f.String("quantity");
  if (q == "final_depth") return Quantity::kFinalDepth;
  if (q == "stop_time") return Quantity::kStopTime;
  f.Fail("quantity", "must be final_depth or stop_time, got '" + q + "'");
}

Provenance ReadProvenance(const io::YamlFields& f) {
  const std::string how = f.String("how");
  if (how == "quoted") return Provenance::kQuoted;
  if (how == "read_off_figure") return Provenance::kReadOffFigure;
  if (how == "derived_from_measured_law") return Provenance::kDerivedFromMeasuredLaw;
  f.Fail("how", "must be quoted, read_off_figure or derived_from_measured_law, got '" + how + "'");
}

// A pad or soil path as the file gives it: relative to the file's directory.
std::string Beside(const io::YamlFields& f, const std::string& key) {
  const fs::path given = f.String(key);
  const fs::path resolved = given.is_absolute() ? given : fs::path(f.file()).parent_path() / given;
  if (!fs::exists(resolved)) f.Fail(key, "no such file '" + resolved.string() + "'");
  return resolved.string();
}

template <typename Load>
auto LoadNamed(const io::YamlFields& f, const std::string& key, Load load) {
  const std::string path = Beside(f, key);
  try {
    return load(path);
  } catch (const InputError& e) {
    f.Fail(key, e.what());
  }
}

KatsuragiDurianLaw ReadKatsuragiDurianLaw(const io::YamlFields& f) {
  f.RequireOnly(kKatsuragiDurianKeys);
  KatsuragiDurianLaw law;
  law.d1_m = InRange(f, kD1) * units::kMm;
  law.d1_uncertainty_m = InRange(f, kD1Uncertainty) * units::kMm;
  law.k_over_m_s2 = InRange(f, kKOverM);
  law.k_over_m_uncertainty_s2 = InRange(f, kKOverMUncertainty);
  if (law.d1_uncertainty_m >= law.d1_m) f.Fail("d1_uncertainty_mm", "must be below d1_mm");
  if (law.k_over_m_uncertainty_s2 >= law.k_over_m_s2) f.Fail("k_over_m_uncertainty_per_s2", "must be below k_over_m_per_s2");
  law.how = ReadProvenance(f);
  law.where = f.String("where");
  return law;
}

// The law needs a sphere: its density and diameter come from the pad (a spherical_cap of the
// sphere's own radius, the sphere's lower hemisphere).
ShallowImpactLaw ReadShallowImpactLaw(const io::YamlFields& f, const ValidationSource& s) {
  f.RequireOnly(kShallowImpactKeys);
  if (s.pad.file.shape != io::PadShape::kSphericalCap || s.pad.file.sphere_radius_mm != s.pad.file.radius_mm)
    f.Fail("kind", "shallow_impact needs a sphere: a spherical_cap pad whose radius is its sphere_radius");
  if (!(s.soil.bulk_density_kg_m3 > 0.0)) f.Fail("kind", "shallow_impact needs the soil's bulk_density_kg_m3 (rho_g)");
  ShallowImpactLaw law;
  law.prefactor = InRange(f, kPrefactor);
  law.friction_coefficient = InRange(f, kFrictionCoefficient);
  law.how = ReadProvenance(f);
  law.where = f.String("where");
  return law;
}

void ReadLaw(const io::YamlFields& f, ValidationSource& s) {
  const std::string kind = f.String("kind");
  if (kind == "katsuragi_durian") s.law = ReadKatsuragiDurianLaw(f);
  else if (kind == "shallow_impact") s.shallow_impact_law = ReadShallowImpactLaw(f, s);
  else f.Fail("kind", "must be katsuragi_durian or shallow_impact, got '" + kind + "'");
}

// The depth of a `from_law` point and its half-range (zero where the law states no uncertainty).
DepthWithUncertainty LawDepth(const ValidationSource& s, const MeasuredPoint& p) {
  if (s.law)
    return KatsuragiDurianStopDepthRange({s.law->d1_m, s.law->k_over_m_s2, s.gravity_m_s2}, s.law->d1_uncertainty_m,
                                         s.law->k_over_m_uncertainty_s2, p.impact_speed_m_s);
  const double radius_m = s.pad.file.sphere_radius_mm * units::kMm;
  const ShallowImpactParameters law{s.shallow_impact_law->prefactor, s.shallow_impact_law->friction_coefficient,
                                    s.pad.mass_kg / (4.0 / 3.0 * std::numbers::pi * radius_m * radius_m * radius_m),
                                    s.soil.bulk_density_kg_m3, 2.0 * radius_m};
  return {ShallowImpactDepth(law, p.drop_height_m.value_or(0.0)), 0.0};
}

// The impact speed of a point or trend: given, or from a drop height in free fall at gravity g.
double ReadImpactSpeed(const io::YamlFields& f, double gravity_m_s2, std::optional<double>& drop_height_m) {
  if (f.Has("impact_speed_m_s") == f.Has("drop_height_mm"))
    f.Fail("impact_speed_m_s", "give exactly one of impact_speed_m_s and drop_height_mm");
  if (f.Has(kPointSpeed.key)) return InRange(f, kPointSpeed);
  drop_height_m = InRange(f, kPointDropHeight) * units::kMm;
  return pad::TouchdownSpeed(0.0, gravity_m_s2, *drop_height_m);
}

MeasuredPoint ReadPoint(const io::YamlFields& f, const ValidationSource& s) {
  f.RequireOnly(kPointKeys);
  MeasuredPoint p;
  p.id = f.Name("id");
  p.impact_speed_m_s = ReadImpactSpeed(f, s.gravity_m_s2, p.drop_height_m);
  p.quantity = ReadQuantity(f);
  const bool from_law = f.Has("from_law") && f.Bool("from_law");
  const bool depth = p.quantity == Quantity::kFinalDepth;
  const io::NumberKey& value = depth ? kPointDepth : kPointStopTime;
  const io::NumberKey& uncertainty = depth ? kPointDepthUncertainty : kPointTimeUncertainty;
  if (from_law) {
    if (!s.law && !s.shallow_impact_law) f.Fail("from_law", "the source has no measured_law");
    if (s.shallow_impact_law && !p.drop_height_m)
      f.Fail("impact_speed_m_s", "the shallow_impact law is for drops from rest: give drop_height_mm");
    if (p.quantity != Quantity::kFinalDepth) f.Fail("from_law", "the law gives final_depth only");
    if (f.Has(value.key)) f.Fail(value.key, "give a value or from_law: true, not both");
    // The law's depth at this point is a number the run will simulate towards: it must exist and
    // lie within the depths any value may (a law whose bed barely resists gives none, or 1e9 m).
    DepthWithUncertainty d;
    try {
      d = LawDepth(s, p);
    } catch (const std::invalid_argument& e) {
      f.Fail("from_law", std::string("the measured law gives no final depth at this point (") + e.what() + ")");
    }
    if (!limits::Within(kLength_mm, d.depth_m * units::kMmPerM) || !limits::Within(kUncertainty_mm, d.half_range_m * units::kMmPerM))
      f.Fail("from_law", "the measured law's final depth here " + limits::Describe(kLength_mm, d.depth_m * units::kMmPerM));
    p.value = d.depth_m;
    p.uncertainty = d.half_range_m;
  } else {
    p.value = InRange(f, value) * (depth ? units::kMm : units::kMs);
    if (f.Has(uncertainty.key)) p.uncertainty = InRange(f, uncertainty) * (depth ? units::kMm : units::kMs);
  }
  p.how = ReadProvenance(f);
  if (from_law != (p.how == Provenance::kDerivedFromMeasuredLaw))
    f.Fail("how", "derived_from_measured_law goes with from_law: true, and only with it");
  p.where = f.String("where");
  return p;
}

Variable ReadVariable(const io::YamlFields& f) {
  const std::string v = f.String("vary");
  if (v == "impact_speed_m_s") return Variable::kImpactSpeed;
  if (v == "gravity_m_s2") return Variable::kGravity;
  if (v == "drop_height_m") return Variable::kTotalDropDistance;
  if (v == "projectile_density_kg_m3") return Variable::kProjectileDensity;
  f.Fail("vary", "must be impact_speed_m_s, gravity_m_s2, drop_height_m or projectile_density_kg_m3, got '" + v + "'");
}

void ReadTrendLaw(const io::YamlFields& f, MeasuredTrend& t) {
  if (f.Has("exponent") == f.Has("direction")) f.Fail("exponent", "give exactly one of exponent and direction");
  if (f.Has("direction")) {
    const std::string d = f.String("direction");
    if (d == "increasing") t.direction = Direction::kIncreasing;
    else if (d == "decreasing") t.direction = Direction::kDecreasing;
    else f.Fail("direction", "must be increasing or decreasing, got '" + d + "'");
    return;
  }
  t.exponent = InRange(f, kTrendExponent);
  t.tolerance = InRange(f, kTrendTolerance);
  const std::string from = f.String("tolerance_source");
  if (from != "stated" && from != "assumed") f.Fail("tolerance_source", "must be stated or assumed, got '" + from + "'");
  t.tolerance_assumed = from == "assumed";
  if (t.tolerance_assumed) t.tolerance_note = f.String("tolerance_note");
}

MeasuredTrend ReadTrend(const io::YamlFields& f, const ValidationSource& s) {
  f.RequireOnly(kTrendKeys);
  MeasuredTrend t;
  t.id = f.Name("id");
  t.quantity = ReadQuantity(f);
  t.vary = ReadVariable(f);
  t.values = f.NumberList("values", /*allow_zero=*/false);
  if (t.values.size() < 2 || !std::is_sorted(t.values.begin(), t.values.end()) ||
      t.values.front() == t.values.back())
    f.Fail("values", "must be two or more increasing values spanning the measured range");
  const limits::Range& values_range = t.vary == Variable::kImpactSpeed        ? limits::kSpeed_m_s
                                      : t.vary == Variable::kGravity          ? limits::kGravity_m_s2
                                      : t.vary == Variable::kTotalDropDistance ? limits::kDropHeight_m
                                                                               : limits::kDensity_kg_m3;
  for (const double v : t.values)
    if (!limits::Within(values_range, v)) f.Fail("values", limits::Describe(values_range, v));
  t.at_gravity_m_s2 = f.Has(kTrendGravity.key) ? InRange(f, kTrendGravity) : s.gravity_m_s2;
  const bool varies_speed = t.vary == Variable::kImpactSpeed || t.vary == Variable::kTotalDropDistance;
  if (varies_speed) {
    if (f.Has("at_impact_speed_m_s")) f.Fail("at_impact_speed_m_s", "the trend varies the impact speed");
  } else {
    t.at_impact_speed_m_s = InRange(f, kTrendSpeed);
  }
  if (t.vary == Variable::kGravity && f.Has("at_gravity_m_s2")) f.Fail("at_gravity_m_s2", "the trend varies gravity");
  if (t.vary == Variable::kProjectileDensity && s.pad.file.shape != io::PadShape::kSphericalCap)
    f.Fail("vary", "projectile_density_kg_m3 needs a sphere (a spherical_cap pad)");
  ReadTrendLaw(f, t);
  t.how = ReadProvenance(f);
  t.where = f.String("where");
  return t;
}

// A measured range: one value, or [low, high] with low < high, each within `range` (the file's
// units); SI by `to_si`.
Range ReadRange(const io::YamlFields& f, const io::NumberKey& number, double to_si) {
  const std::string key = number.key;
  const limits::Range& range = *number.range;
  const std::vector<double> v = f.NumberList(key, /*allow_zero=*/false);
  if (v.empty() || v.size() > 2 || (v.size() == 2 && !(v[0] < v[1])))
    f.Fail(key, "must be [value] or [low, high] with low < high");
  for (const double x : v)
    if (!limits::Within(range, x)) f.Fail(key, limits::Describe(range, x));
  return {v.front() * to_si, v.back() * to_si};
}

// The bearing area is the source's flat pad made at each bearing diameter (io::FlatPadWithRadius).
MeasuredBearing ReadBearing(const io::YamlFields& f, const ValidationSource& s) {
  f.RequireOnly(kBearingKeys);
  if (s.pad.file.shape != io::PadShape::kFlat) f.Fail("id", "a static bearing needs a flat pad (profile shape: flat)");
  MeasuredBearing b;
  b.id = f.Name("id");
  b.pressure_Pa = ReadRange(f, kBearingPressure, 1e4);
  b.depth_m = ReadRange(f, kBearingDepth, units::kMm);
  b.diameter_m = ReadRange(f, kBearingDiameter, units::kMm);
  b.how = ReadProvenance(f);
  if (b.how == Provenance::kDerivedFromMeasuredLaw) f.Fail("how", "a static bearing is quoted or read off a figure");
  b.where = f.String("where");
  return b;
}

// A file loaded once per cache (by its path, as resolved beside the source).
template <typename T, typename Load>
T Cached(std::map<std::string, T>* cache, const std::string& path, Load load) {
  if (!cache) return load(path);
  const auto it = cache->find(path);
  if (it != cache->end()) return it->second;
  return cache->emplace(path, load(path)).first->second;
}

void ReadMedium(const io::YamlFields& m, ValidationSource& s, SourceFileCache* cache) {
  m.RequireOnly(kMediumKeys);
  s.soil = LoadNamed(m, "soil", [cache](const std::string& p) {
    return Cached(cache ? &cache->soils : nullptr, p, [](const std::string& q) { return io::LoadSoil(q); });
  });
  s.medium = m.String("description");
  const std::string route = m.String("zeta_route");
  if (route == "derived") {
    if (m.Has("calibrated_on")) m.Fail("calibrated_on", "only with zeta_route: calibrated_on");
  } else if (route == "calibrated_on") {
    s.zeta_route = ZetaRoute::kCalibratedOn;
    s.calibrated_on = m.String("calibrated_on");
  } else {
    m.Fail("zeta_route", "must be derived or calibrated_on, got '" + route + "'");
  }
}

void CheckIds(const io::YamlFields& f, const ValidationSource& s) {
  std::set<std::string> ids;
  for (const MeasuredPoint& p : s.points)
    if (!ids.insert(p.id).second) f.Fail("points", "repeated id '" + p.id + "'");
  for (const MeasuredTrend& t : s.trends)
    if (!ids.insert(t.id).second) f.Fail("trends", "repeated id '" + t.id + "'");
  for (const MeasuredBearing& b : s.bearings)
    if (!ids.insert(b.id).second) f.Fail("static_bearing", "repeated id '" + b.id + "'");
  if (s.points.empty() && s.trends.empty() && s.bearings.empty())
    f.Fail("points", "a source needs measured points, trends or a static_bearing");
  if (s.zeta_route == ZetaRoute::kCalibratedOn) {
    const auto it = std::find_if(s.points.begin(), s.points.end(),
                                 [&](const MeasuredPoint& p) { return p.id == s.calibrated_on; });
    if (it == s.points.end() || it->quantity != Quantity::kFinalDepth)
      f.Fail("medium.calibrated_on", "'" + s.calibrated_on + "' is not a final_depth point of this source");
  }
}

}  // namespace

std::vector<io::BlockDoc> ValidationSourceSchema() {
  const std::string read_by = "drop_tests/validation/validation_source.cpp";
  return {io::MakeBlock("validation_source", read_by, io::DocsWith(kSourceKeys, {kSourceGravity})),
          io::MakeBlock("validation_source.projectile", read_by, io::PlainKeyDocs(kProjectileKeys)),
          io::MakeBlock("validation_source.medium", read_by, io::PlainKeyDocs(kMediumKeys)),
          io::MakeBlock("validation_source.measured_law.katsuragi_durian", read_by,
                        io::DocsWith(kKatsuragiDurianKeys, {kD1, kD1Uncertainty, kKOverM, kKOverMUncertainty})),
          io::MakeBlock("validation_source.measured_law.shallow_impact", read_by,
                        io::DocsWith(kShallowImpactKeys, {kPrefactor, kFrictionCoefficient})),
          io::MakeBlock("validation_source.points", read_by,
                        io::DocsWith(kPointKeys, {kPointSpeed, kPointDropHeight, kPointDepth, kPointStopTime,
                                                   kPointDepthUncertainty, kPointTimeUncertainty})),
          io::MakeBlock("validation_source.trends", read_by,
                        io::DocsWith(kTrendKeys, {kTrendExponent, kTrendTolerance, kTrendGravity, kTrendSpeed})),
          io::MakeBlock("validation_source.static_bearing", read_by,
                        io::DocsWith(kBearingKeys, {kBearingPressure, kBearingDepth, kBearingDiameter})),
          io::MakeBlock("validation_model", read_by, io::PlainKeyDocs(kValidationModelKeys))};
}

ValidationSource LoadValidationSource(const std::string& path, SourceFileCache* cache) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(kSourceKeys);
  if (f.String("type") != "validation_source") f.Fail("type", "must be validation_source, got '" + f.String("type") + "'");
  ValidationSource s;
  s.file = path;
  s.id = f.String("id");
  if (s.id != fs::path(path).stem().string()) f.Fail("id", "must be the file's name without .yaml, got '" + s.id + "'");
  s.citation = f.String("citation");
  s.read_at = f.String("read_at");
  const io::YamlFields projectile = f.Child("projectile");
  projectile.RequireOnly(kProjectileKeys);
  s.pad = LoadNamed(projectile, "pad", [cache](const std::string& p) {
    return Cached(cache ? &cache->pads : nullptr, p, [](const std::string& q) { return io::LoadPad(q); });
  });
  if (!s.pad.is_axisymmetric()) projectile.Fail("pad", "must be an axisymmetric pad (the rig drop)");
  s.projectile = projectile.String("description");
  ReadMedium(f.Child("medium"), s, cache);
  s.gravity_m_s2 = InRange(f, kSourceGravity);
  if (f.Has("low_gravity")) s.low_gravity = f.Bool("low_gravity");
  if (f.Has("measured_law")) ReadLaw(f.Child("measured_law"), s);
  if (f.Has("points"))
    for (const io::YamlFields& p : f.List("points")) s.points.push_back(ReadPoint(p, s));
  if (f.Has("trends"))
    for (const io::YamlFields& t : f.List("trends")) s.trends.push_back(ReadTrend(t, s));
  if (f.Has("static_bearing"))
    for (const io::YamlFields& b : f.List("static_bearing")) s.bearings.push_back(ReadBearing(b, s));
  CheckIds(f, s);
  return s;
}

DynamicRftModel LoadDynamicRftModel(const std::string& path) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(kValidationModelKeys);
  if (f.String("type") != "validation_model") f.Fail("type", "must be validation_model, got '" + f.String("type") + "'");
  DynamicRftModel m;
  m.lambda = f.Positive("inertial_drag_lambda");
  if (m.lambda > 1e3) f.Fail("inertial_drag_lambda", "must be at most 1000 (an O(1) coefficient)");
  m.source = f.String("source");
  m.file = path;
  return m;
}

ValidationSet LoadValidationSet(const std::string& directory) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) throw MakeInputError(directory, "", "not a directory of validation sources");
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(directory, ec))
    if (e.path().extension() == ".yaml" && e.path().filename() != "dynamic_rft.yaml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ValidationSet set;
  SourceFileCache cache;
  for (const std::string& file : files) set.sources.push_back(LoadValidationSource(file, &cache));
  if (set.sources.empty()) throw MakeInputError(directory, "", "holds no validation source (*.yaml)");
  const fs::path model = fs::path(directory) / "dynamic_rft.yaml";
  if (!fs::exists(model)) throw MakeInputError(model.string(), "", "missing (the dynamic variant's lambda)");
  set.dynamic = LoadDynamicRftModel(model.string());
  return set;
}

}  // namespace touchdown::validation

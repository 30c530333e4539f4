#pragma once
// A published granular-impact measurement as touchdown validates against it
// (data/validation/<source_id>.yaml, `type: validation_source`): the citation, the projectile as a
// catalogued pad, the medium as a soil with zeta's route (derived from density and friction angle,
// or calibrated on ONE designated measured case), gravity, the measured points, the measured
// trends (power-law exponents or directions) and static bearings. Every number carries where it
// was read and whether it was quoted, read off a figure, or derived from a measured law the source
// fitted.
// docs/validation.md describes the format and the sources.
#include <array>
#include <optional>
#include <map>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "rft/enum_names.h"
#include "rft/gravity_constants.h"
#include "rft/soil.h"

namespace touchdown::validation {

// What a point or a trend measures.
enum class Quantity { kFinalDepth, kStopTime };
inline constexpr std::array<EnumName<Quantity>, 2> kQuantityNames{
    {{Quantity::kFinalDepth, "final_depth"}, {Quantity::kStopTime, "stop_time"}}};
const char* QuantityName(Quantity q);
const char* QuantityUnit(Quantity q);   // the unit the reports print: "mm", "ms"
double QuantityToReport(Quantity q);    // SI -> report unit factor (1e3 for both)

// What a trend varies. kTotalDropDistance: the drop height h (values) in free fall, the trend
// taken against the total drop distance H = h + d (Uehara et al.'s variable, d the final depth).
// kProjectileDensity: the sphere's density at its fixed size (a spherical_cap pad: the sphere of
// the pad's radius), i.e. its mass.
enum class Variable { kImpactSpeed, kGravity, kTotalDropDistance, kProjectileDensity };
inline constexpr std::array<EnumName<Variable>, 4> kVariableNames{{{Variable::kImpactSpeed, "impact_speed_m_s"},
                                                                   {Variable::kGravity, "gravity_m_s2"},
                                                                   {Variable::kTotalDropDistance, "drop_height_m"},
                                                                   {Variable::kProjectileDensity, "projectile_density_kg_m3"}}};
const char* VariableName(Variable v);

// How a number came out of its source.
enum class Provenance { kQuoted, kReadOffFigure, kDerivedFromMeasuredLaw };
inline constexpr std::array<EnumName<Provenance>, 3> kProvenanceNames{
    {{Provenance::kQuoted, "quoted"},
     {Provenance::kReadOffFigure, "read_off_figure"},
     {Provenance::kDerivedFromMeasuredLaw, "derived_from_measured_law"}}};
const char* ProvenanceName(Provenance p);

// Katsuragi & Durian's force law fitted to their measured trajectories:
// m dv/dt = m g - m v^2 / d1 - k z (z down). Its stop depth is a measured point's value when the
// point says `from_law: true` (katsuragi_durian.h).
struct KatsuragiDurianLaw {
  double d1_m = 0.0, d1_uncertainty_m = 0.0;
  double k_over_m_s2 = 0.0, k_over_m_uncertainty_s2 = 0.0;  // k / m [1/s^2]
  std::string where;
  Provenance how = Provenance::kQuoted;
};

// Uehara et al. / Ambroso et al.'s fitted penetration depth of spheres dropped from rest,
// d = (c / mu) (rho_b / rho_g)^(1/2) D^(2/3) (h + d)^(1/3) (shallow_impact_depth.h): the
// prefactor c and the medium's mu as the file gives them; rho_b and D from the source's sphere
// pad, rho_g the soil's bulk density. A point's value when it says `from_law: true`.
struct ShallowImpactLaw {
  double prefactor = 0.0;
  double friction_coefficient = 0.0;
  std::string where;
  Provenance how = Provenance::kQuoted;
};

struct MeasuredPoint {
  std::string id;
  double impact_speed_m_s = 0.0;  // given, or sqrt(2 g h) from drop_height_m
  std::optional<double> drop_height_m;
  Quantity quantity = Quantity::kFinalDepth;
  double value = 0.0;        // SI (m, s)
  double uncertainty = 0.0;  // SI, half-width; 0 when the source states none
  Provenance how = Provenance::kQuoted;
  std::string where;
};

// A static bearing measurement (`static_bearing`): the pressure under a flat bearing area pushed
// slowly into the soil, static_bearing_pressure = vertical force / bearing area, over a range of
// penetration depths and bearing diameters. Each is a range [low, high] (low = high for a single
// value); the source's pad (`shape: flat`) is made at each bearing diameter.
struct Range {
  double low = 0.0, high = 0.0;  // SI
};
struct MeasuredBearing {
  std::string id;
  Range pressure_Pa, depth_m, diameter_m;
  Provenance how = Provenance::kQuoted;
  std::string where;
};

// A measured trend: quantity ~ variable^exponent over `values` (the measured range), the other
// conditions fixed at `at_*`. `exponent` with its tolerance, or only a direction.
enum class Direction { kExponent, kIncreasing, kDecreasing };
struct MeasuredTrend {
  std::string id;
  Quantity quantity = Quantity::kFinalDepth;
  Variable vary = Variable::kImpactSpeed;
  std::vector<double> values;  // SI
  double at_impact_speed_m_s = 0.0;
  double at_gravity_m_s2 = rft::kEarthGravity_m_s2;
  Direction direction = Direction::kExponent;
  double exponent = 0.0;
  double tolerance = 0.0;          // |simulated - exponent| <= tolerance reproduces it
  bool tolerance_assumed = false;  // the source states none: ours, with `tolerance_note`
  std::string tolerance_note;
  Provenance how = Provenance::kQuoted;
  std::string where;
};

enum class ZetaRoute { kDerived, kCalibratedOn };

struct ValidationSource {
  std::string id;    // the file's stem, also its `id:`
  std::string file;  // the YAML file
  std::string citation;  // authors, year, title, journal, DOI as one line
  std::string read_at;   // where the text was read (pages, abstracts)
  io::PadSpec pad;
  std::string projectile;  // one line: what the source used
  rft::SoilParameters soil;
  std::string medium;      // one line
  ZetaRoute zeta_route = ZetaRoute::kDerived;
  std::string calibrated_on;  // a point id when zeta_route is kCalibratedOn
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
  bool low_gravity = false;   // run with zeta scaled with g and with zeta fixed
  // The measured law the `from_law` points come from: at most one (`measured_law.kind`).
  std::optional<KatsuragiDurianLaw> law;
  std::optional<ShallowImpactLaw> shallow_impact_law;
  std::vector<MeasuredPoint> points;
  std::vector<MeasuredTrend> trends;
  std::vector<MeasuredBearing> bearings;  // `static_bearing`
};

// Loads and checks one source; pad and soil paths are relative to the file. InputError naming
// file, field and value on anything wrong.
// The pads and soils sources name, each loaded once per set (a set of many sources naming the same
// sphere loaded its mesh thousands of times: 10,000 sources took four minutes to reach a malformed
// last one).
struct SourceFileCache {
  std::map<std::string, io::PadSpec> pads;
  std::map<std::string, rft::SoilParameters> soils;
};
ValidationSource LoadValidationSource(const std::string& path, SourceFileCache* cache = nullptr);
// The reference of a validation source's and a validation model file's keys (schema_doc.h;
// `touchdown schema`, docs/reference.md).
std::vector<io::BlockDoc> ValidationSourceSchema();

// The dynamic-RFT coefficient the `dynamic` variant uses (data/validation/dynamic_rft.yaml,
// `type: validation_model`), with its source.
struct DynamicRftModel {
  double lambda = 0.0;
  std::string source;
  std::string file;
};
DynamicRftModel LoadDynamicRftModel(const std::string& path);

// Every `*.yaml` of `directory` but dynamic_rft.yaml is a source (`type: validation_source`),
// loaded in file-name order, and dynamic_rft.yaml is the model. InputError when the directory holds
// no source or no model, or any file is not what it must be.
struct ValidationSet {
  std::vector<ValidationSource> sources;
  DynamicRftModel dynamic;
};
ValidationSet LoadValidationSet(const std::string& directory);

}  // namespace touchdown::validation

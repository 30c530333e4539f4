// validate's outputs: validation.json, validation.md, the console summary and the plots.
#include <cmath>
#include <iomanip>
#include <initializer_list>
#include <sstream>

#include <nlohmann/json.hpp>

#include "drop_tests/formats/json_number.h"
#include "drop_tests/validation/validate.h"
#include "rft/units.h"

namespace touchdown::validation {

namespace {

std::string Fixed(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}
std::string Percent(double relative) { return std::isfinite(relative) ? Fixed(100.0 * relative, 1) + " %" : "-"; }

std::string MeasuredTrendText(const MeasuredTrend& t) {
  if (t.direction == Direction::kIncreasing) return "increasing";
  if (t.direction == Direction::kDecreasing) return "decreasing";
  return Fixed(t.exponent, 2) + " +- " + Fixed(t.tolerance, 2) + (t.tolerance_assumed ? " (tolerance assumed)" : "");
}

std::string ZetaRouteText(const ValidationSource& s) {
  return s.zeta_route == ZetaRoute::kDerived ? "derived (the soil file's route)"
                                             : "calibrated on point '" + s.calibrated_on + "'";
}

nlohmann::json PointJson(const SourceResult& r, const PointResult& p) {
  const double f = QuantityToReport(p.point->quantity);
  nlohmann::json j{{"id", p.point->id},
                   {"quantity", QuantityName(p.point->quantity)},
                   {"unit", QuantityUnit(p.point->quantity)},
                   {"impact_speed_m_s", p.point->impact_speed_m_s},
                   {"measured", p.point->value * f},
                   {"measured_uncertainty", p.point->uncertainty * f},
                   {"how", ProvenanceName(p.point->how)},
                   {"where", p.point->where},
                   {"fitted", r.source->zeta_route == ZetaRoute::kCalibratedOn && p.point->id == r.source->calibrated_on}};
  if (p.point->drop_height_m) j["drop_height_mm"] = *p.point->drop_height_m * units::kMmPerM;
  for (size_t k = 0; k < r.variants.size(); ++k)
    j["simulated"][r.variants[k].Name()] = {{"value", io::FiniteOrNull(p.simulated[k] * f)},
                                            {"relative_error", io::FiniteOrNull(p.relative_error[k])}};
  return j;
}

nlohmann::json TrendJson(const SourceResult& r, const TrendResult& t) {
  const MeasuredTrend& m = *t.trend;
  nlohmann::json j{{"id", m.id},
                   {"quantity", QuantityName(m.quantity)},
                   {"vary", VariableName(m.vary)},
                   {"values", m.values},
                   {"how", ProvenanceName(m.how)},
                   {"where", m.where}};
  if (m.direction == Direction::kExponent) {
    j["measured_exponent"] = m.exponent;
    j["tolerance"] = m.tolerance;
    j["tolerance_source"] = m.tolerance_assumed ? "assumed" : "stated";
  } else {
    j["measured_direction"] = m.direction == Direction::kIncreasing ? "increasing" : "decreasing";
  }
  for (size_t k = 0; k < r.variants.size(); ++k)
    j["simulated"][r.variants[k].Name()] = {{"exponent", io::FiniteOrNull(t.exponent[k])},
                                            {"reproduced", static_cast<bool>(t.reproduced[k])},
                                            {"x_SI", t.x[k]},
                                            {"values_SI", t.simulated[k]}};
  return j;
}

nlohmann::json RangeJson(const Range& r, double f) { return {r.low * f, r.high * f}; }

nlohmann::json BearingJson(const SourceResult& r, const BearingResult& b) {
  const MeasuredBearing& m = *b.bearing;
  constexpr double kN_cm2 = 1e-4;
  nlohmann::json j{{"id", m.id},
                   {"quantity", "static_bearing_pressure"},
                   {"unit", "N/cm^2"},
                   {"measured", RangeJson(m.pressure_Pa, kN_cm2)},
                   {"depth_mm", RangeJson(m.depth_m, 1e3)},
                   {"diameter_mm", RangeJson(m.diameter_m, 1e3)},
                   {"how", ProvenanceName(m.how)},
                   {"where", m.where}};
  for (size_t k = 0; k < r.variants.size(); ++k) {
    nlohmann::json corners = nlohmann::json::array();
    for (const double p : b.corners_Pa[k]) corners.push_back(p * kN_cm2);
    j["simulated"][r.variants[k].Name()] = {{"range", RangeJson(b.simulated_Pa[k], kN_cm2)},
                                            {"corners", corners},
                                            {"agreement", RangeAgreementName(b.comparison[k].agreement)},
                                            {"relative_distance", b.comparison[k].relative_distance}};
  }
  return j;
}

nlohmann::json SourceJson(const SourceResult& r) {
  const ValidationSource& s = *r.source;
  nlohmann::json j{{"id", s.id},
                   {"citation", s.citation},
                   {"projectile", s.projectile},
                   {"pad", s.pad.name},
                   {"medium", s.medium},
                   {"soil", s.soil.name},
                   {"zeta_route", s.zeta_route == ZetaRoute::kDerived ? "derived" : "calibrated_on"},
                   {"gravity_m_s2", s.gravity_m_s2},
                   {"low_gravity", s.low_gravity},
                   {"best_variant", r.variants[static_cast<size_t>(r.best_variant)].Name()}};
  if (s.zeta_route == ZetaRoute::kCalibratedOn) j["calibrated_on"] = s.calibrated_on;
  for (size_t k = 0; k < r.variants.size(); ++k)
    j["variants"][r.variants[k].Name()] = {{"zeta_N_cm3", units::ZetaToN_cm3(r.zeta_N_m3[k])},
                                           {"mean_abs_relative_error", io::FiniteOrNull(r.mean_abs_error[k])},
                                           {"trends_reproduced", r.trends_reproduced[k]},
                                           {"trends", r.trends.size()}};
  if (!r.bearings.empty())
    for (size_t k = 0; k < r.variants.size(); ++k) {
      j["variants"][r.variants[k].Name()]["static_bearings_met"] = r.bearings_met[k];
      j["variants"][r.variants[k].Name()]["static_bearings"] = r.bearings.size();
    }
  j["points"] = nlohmann::json::array();
  for (const PointResult& p : r.points) j["points"].push_back(PointJson(r, p));
  j["trends"] = nlohmann::json::array();
  for (const TrendResult& t : r.trends) j["trends"].push_back(TrendJson(r, t));
  // Only a source with static bearings carries the key (the others' JSON stays as it was).
  for (const BearingResult& b : r.bearings) j["static_bearing"].push_back(BearingJson(r, b));
  return j;
}

// A results table's header row and rule: the fixed columns, then each variant's name (and an error
// column beside it when `with_error`).
void TableHeader(std::ostringstream& md, std::initializer_list<const char*> fixed, const SourceResult& r,
                 bool with_error) {
  md << "|";
  for (const char* f : fixed) md << " " << f << " |";
  for (const Variant& v : r.variants) md << " " << v.Name() << (with_error ? " | error |" : " |");
  md << "\n|";
  for (size_t i = 0; i < fixed.size(); ++i) md << "---|";
  for (size_t k = 0; k < r.variants.size(); ++k) md << (with_error ? "---|---|" : "---|");
  md << "\n";
}

void PointsTable(std::ostringstream& md, const SourceResult& r) {
  if (r.points.empty()) return;
  TableHeader(md, {"point", "v0 [m/s]", "measured", "how"}, r, true);
  for (const PointResult& p : r.points) {
    const double f = QuantityToReport(p.point->quantity);
    const bool fitted = r.source->zeta_route == ZetaRoute::kCalibratedOn && p.point->id == r.source->calibrated_on;
    md << "| " << p.point->id << (fitted ? " (fitted)" : "") << " | " << Fixed(p.point->impact_speed_m_s, 2) << " | "
       << Fixed(p.point->value * f, 1)
       // A value whose source states no uncertainty is printed without one, not as +- 0.
       << (p.point->uncertainty > 0.0 ? " +- " + Fixed(p.point->uncertainty * f, 1) : std::string()) << " "
       << QuantityUnit(p.point->quantity) << " " << QuantityName(p.point->quantity) << " | "
       << ProvenanceName(p.point->how) << " |";
    for (size_t k = 0; k < r.variants.size(); ++k)
      md << " " << Fixed(p.simulated[k] * f, 1) << " | " << Percent(p.relative_error[k]) << " |";
    md << "\n";
  }
  md << "\n";
}

void TrendsTable(std::ostringstream& md, const SourceResult& r) {
  if (r.trends.empty()) return;
  TableHeader(md, {"trend", "law", "measured exponent", "how"}, r, false);
  for (const TrendResult& t : r.trends) {
    const MeasuredTrend& m = *t.trend;
    md << "| " << m.id << " | " << QuantityName(m.quantity) << " ~ " << VariableName(m.vary) << "^p over ["
       << m.values.front() << ", " << m.values.back() << "] | " << MeasuredTrendText(m) << " | "
       << ProvenanceName(m.how) << " |";
    for (size_t k = 0; k < r.variants.size(); ++k)
      md << " " << Fixed(t.exponent[k], 3) << (t.reproduced[k] ? " (reproduced)" : " (not reproduced)") << " |";
    md << "\n";
  }
  md << "\n";
}

std::string BearingCell(const BearingResult& b, size_t k) {
  const RangeComparison& c = b.comparison[k];
  return Fixed(b.simulated_Pa[k].low * units::kN_cm2_per_Pa, 2) + "-" + Fixed(b.simulated_Pa[k].high * units::kN_cm2_per_Pa, 2) + " (" +
         RangeAgreementName(c.agreement) +
         (c.agreement == RangeAgreement::kOutside ? ", " + Percent(c.relative_distance) : std::string()) + ")";
}

void BearingsTable(std::ostringstream& md, const SourceResult& r) {
  if (r.bearings.empty()) return;
  TableHeader(md, {"static bearing", "depth [mm]", "diameter [mm]", "measured [N/cm^2]", "how"}, r, false);
  const auto range = [](const Range& x, double f, int digits) {
    return x.low == x.high ? Fixed(x.low * f, digits) : Fixed(x.low * f, digits) + "-" + Fixed(x.high * f, digits);
  };
  for (const BearingResult& b : r.bearings) {
    const MeasuredBearing& m = *b.bearing;
    md << "| " << m.id << " | " << range(m.depth_m, 1e3, 0) << " | " << range(m.diameter_m, 1e3, 0) << " | "
       << range(m.pressure_Pa, 1e-4, 1) << " | " << ProvenanceName(m.how) << " |";
    for (size_t k = 0; k < r.variants.size(); ++k) md << " " << BearingCell(b, k) << " |";
    md << "\n";
  }
  md << "\n";
}

std::string PlotBase(const SourceResult& r, const std::string& panel) { return "plots/" + r.source->id + "_" + panel; }

std::vector<std::string> PanelsOf(const SourceResult& r) {
  std::vector<std::string> panels;
  for (const Curve& c : r.curves) panels.push_back(QuantityName(c.quantity));
  for (const TrendResult& t : r.trends) panels.push_back(t.trend->id);
  return panels;
}

}  // namespace

nlohmann::json ValidationJson(const ValidationResult& result) {
  nlohmann::json j{{"schema_version", 1},
                   {"dynamic_rft",
                    {{"inertial_drag_lambda", result.set->dynamic.lambda}, {"source", result.set->dynamic.source}}}};
  j["sources"] = nlohmann::json::array();
  for (const SourceResult& r : result.sources) j["sources"].push_back(SourceJson(r));
  return j;
}

std::string ValidationMarkdown(const ValidationResult& result) {
  std::ostringstream md;
  md << "Dynamic variant: inertial_drag with lambda = " << result.set->dynamic.lambda << " ("
     << result.set->dynamic.source << ").\n\n";
  for (const SourceResult& r : result.sources) {
    const ValidationSource& s = *r.source;
    md << "### " << s.id << "\n\n" << s.citation << "\n\n- projectile: " << s.projectile << " (pad `" << s.pad.name
       << "`, " << Fixed(s.pad.mass_kg * units::kGPerKg, 1) << " g)\n- medium: " << s.medium << " (soil `" << s.soil.name
       << "`)\n- gravity: " << s.gravity_m_s2 << " m/s^2" << (s.low_gravity ? " (low-gravity source)" : "")
       << "\n- zeta: " << ZetaRouteText(s) << ";";
    for (size_t k = 0; k < r.variants.size(); ++k)
      md << " " << r.variants[k].Name() << " " << Fixed(units::ZetaToN_cm3(r.zeta_N_m3[k]), 3) << " N/cm^3"
         << (k + 1 < r.variants.size() ? "," : "");
    md << " (at " << s.soil.reference_gravity_m_s2 << " m/s^2)\n\n";
    PointsTable(md, r);
    TrendsTable(md, r);
    BearingsTable(md, r);
    md << "Per variant: ";
    for (size_t k = 0; k < r.variants.size(); ++k) {
      md << r.variants[k].Name() << " mean |error| " << Percent(r.mean_abs_error[k]) << ", trends "
         << r.trends_reproduced[k] << "/" << r.trends.size();
      if (!r.bearings.empty()) md << ", static bearings met " << r.bearings_met[k] << "/" << r.bearings.size();
      md << (k + 1 < r.variants.size() ? "; " : ".");
    }
    md << " Closer to this source: **" << r.variants[static_cast<size_t>(r.best_variant)].Name() << "**.\n\n";
    for (const std::string& panel : PanelsOf(r)) md << "![" << s.id << " " << panel << "](" << PlotBase(r, panel) << ".png)\n";
    md << "\n";
  }
  return md.str();
}

std::string ValidationSummary(const ValidationResult& result) {
  std::ostringstream out;
  for (const SourceResult& r : result.sources) {
    out << r.source->id << "\n";
    for (const PointResult& p : r.points) {
      const double f = QuantityToReport(p.point->quantity);
      out << "  " << std::left << std::setw(14) << p.point->id << std::right << " measured " << std::setw(8)
          << Fixed(p.point->value * f, 2) << " " << QuantityUnit(p.point->quantity);
      for (size_t k = 0; k < r.variants.size(); ++k)
        out << "  " << r.variants[k].Name() << " " << Fixed(p.simulated[k] * f, 2) << " ("
            << Percent(p.relative_error[k]) << ")";
      out << "\n";
    }
    for (const TrendResult& t : r.trends) {
      out << "  " << std::left << std::setw(14) << t.trend->id << std::right << " measured " << MeasuredTrendText(*t.trend);
      for (size_t k = 0; k < r.variants.size(); ++k)
        out << "  " << r.variants[k].Name() << " " << Fixed(t.exponent[k], 3) << (t.reproduced[k] ? " ok" : " no");
      out << "\n";
    }
    for (const BearingResult& b : r.bearings) {
      out << "  " << std::left << std::setw(14) << b.bearing->id << std::right << " measured "
          << Fixed(b.bearing->pressure_Pa.low * units::kN_cm2_per_Pa, 2) << "-" << Fixed(b.bearing->pressure_Pa.high * units::kN_cm2_per_Pa, 2)
          << " N/cm^2";
      for (size_t k = 0; k < r.variants.size(); ++k) out << "  " << r.variants[k].Name() << " " << BearingCell(b, k);
      out << "\n";
    }
    out << "  closer: " << r.variants[static_cast<size_t>(r.best_variant)].Name() << "\n";
  }
  return out.str();
}

}  // namespace touchdown::validation

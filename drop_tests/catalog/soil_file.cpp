#include "drop_tests/catalog/catalog.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

// A soil file (data/soils; docs/reference.md): loaded, checked and written.
namespace touchdown::io {

namespace fs = std::filesystem;

namespace {
using units::kDeg;
using units::kMm;

// Zeta: a number in its range, or 'agarwal2023' (derived, then held to the same range).
const NumberKey kSoilZeta{"zeta_N_cm3", Sign::kPositive, &limits::kZeta_N_cm3, "*required* (optional with `law: bekker`)"};

// A soil file's number fields (zeta, with its 'agarwal2023' alternative, is read on its own).
const FieldTable<rft::SoilParameters>& SoilNumberFields() {
  using S = rft::SoilParameters;
  static const FieldTable<S> fields{
      {"reference_gravity_m_s2", &S::reference_gravity_m_s2, 1.0, Sign::kPositive, true, true, &limits::kGravity_m_s2},
      {"bulk_density_kg_m3", &S::bulk_density_kg_m3, 1.0, Sign::kPositive, true, true, &limits::kDensity_kg_m3},
      {"internal_friction_angle_deg", &S::internal_friction_angle_rad, kDeg, Sign::kPositive, true, true},
      {"mu_surf", &S::surface_friction_coefficient, 1.0, Sign::kNonNegative, true, true},
      {"dynamic_lambda", &S::dynamic_lambda, 1.0, Sign::kNonNegative, true, true},
      {"dynamic_density_kg_m3", &S::dynamic_density_kg_m3, 1.0, Sign::kPositive, true, true, &limits::kDensity_kg_m3,
       "`bulk_density_kg_m3`"},
  };
  return fields;
}

// The `bekker:` block of a soil file (rft/bekker_parameters.h): kN, kPa, deg and mm in the file;
// the pressure-sinkage parameters first, from their one table.
const FieldTable<rft::BekkerParameters>& BekkerFields() {
  using B = rft::BekkerParameters;
  static const FieldTable<B> fields = [] {
    FieldTable<B> f;
    for (const BekkerFileField& e : BekkerPressureSinkageFields())
      f.push_back({e.key, e.member, e.file_to_si, e.range->low_open ? Sign::kPositive : Sign::kNonNegative, false, false,
                   e.range});
    f.insert(f.end(),
             {{"cohesion_kPa", &B::cohesion_Pa, units::kKilo, Sign::kNonNegative, false, false, &limits::kCohesion_kPa},
              {"friction_angle_deg", &B::friction_angle_rad, kDeg, Sign::kNonNegative, false, false},
              {"shear_modulus_K_mm", &B::shear_modulus_K_m, kMm, Sign::kPositive, false, false, &limits::kShearModulusK_mm}});
    return f;
  }();
  return fields;
}

const KeyTable<rft::BekkerParameters>& BekkerKeys() {
  static const KeyTable<rft::BekkerParameters> keys = [] {
    KeyTable<rft::BekkerParameters> k;
    AppendNumberKeys(k, BekkerFields());
    k.push_back({"provenance"});
    return k;
  }();
  return keys;
}

// A soil file's keys, in the order WriteSoil writes them.
const KeyTable<rft::SoilParameters>& SoilKeys() {
  using S = rft::SoilParameters;
  using Y = YAML::Emitter;
  const auto bekker_law = [](const S& s) { return s.rft_law_3d == rft::LawKind::kBekker; };
  static const KeyTable<S> keys = [&] {
    KeyTable<S> k{
        {"schema_version", Always<S>, [](Y& y, const S&) { y << 1; }},
        {"name", Always<S>, [](Y& y, const S& s) { y << s.name; }},
        {"description"},
        {"atmosphere", Always<S>, [](Y& y, const S& s) { y << rft::AtmosphereName(s.atmosphere); }},
        {"gravity_scaling", [](const S& s) { return s.gravity_scaling != rft::GravityScaling::kLithostatic; },
         [](Y& y, const S& s) { y << rft::GravityScalingName(s.gravity_scaling); }},
        // A Bekker soil without zeta leaves it out (0 would not read back); RFT soils always state it.
        {kSoilZeta.key, [=](const S& s) { return !bekker_law(s) || s.zeta_N_m3 > 0.0; },
         [](Y& y, const S& s) { y << units::ZetaToN_cm3(s.zeta_N_m3); }, DocOf(kSoilZeta)},
    };
    AppendNumberKeys(k, SoilNumberFields());
    k.push_back({"law", [](const S& s) { return s.rft_law_3d != rft::LawKind::kLi2013; },
                 [](Y& y, const S& s) { y << std::string(rft::LawKindName(s.rft_law_3d)); }});
    k.push_back({"bekker",
                 [=](const S& s) { return bekker_law(s) || s.bekker.k_c_N_m_n1 + s.bekker.k_phi_N_m_n2 > 0.0; },
                 [](Y& y, const S& s) {
                   WriteMap(y, BekkerKeys(), s.bekker);
                 }});
    k.push_back({"dynamic_term", [](const S& s) { return s.dynamic_term; }, [](Y& y, const S&) { y << true; }});
    k.push_back({"provenance"});
    return k;
  }();
  return keys;
}

rft::BekkerParameters ReadBekkerBlock(const YamlFields& f) {
  const YamlFields b = f.Child("bekker");
  b.RequireOnly(Keys(BekkerKeys()));
  rft::BekkerParameters out;
  ReadFields(b, BekkerFields(), out);
  if (out.n > limits::kBekkerN.high) b.Fail("n", "must be at most 5 (Bekker exponents are about 0.5 to 1.5)");
  if (out.friction_angle_rad >= limits::kFrictionAngleBelow_deg * kDeg)
    b.Fail("friction_angle_deg", "must be below " + std::to_string(limits::kFrictionAngleBelow_deg));
  if (!(out.k_c_N_m_n1 + out.k_phi_N_m_n2 > 0.0)) b.Fail("k_phi_kN_m_n2", "k_c and k_phi cannot both be 0");
  return out;
}
}  // namespace

rft::SoilParameters LoadSoil(const std::string& name_or_path) {
  const std::string path = ResolveCatalogFile("soils", name_or_path);
  const YamlFields f = YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(Keys(SoilKeys()));
  rft::SoilParameters soil;
  soil.name = f.Name("name", fs::path(path).stem().string());
  if (!IsValidUtf8(soil.name)) f.Fail("name", "the soil name (from the file name) is not valid UTF-8 text");
  const std::string atmosphere = f.StringOr("atmosphere", "vacuum");
  const std::optional<rft::Atmosphere> parsed = rft::ParseAtmosphere(atmosphere);
  if (!parsed) f.Fail("atmosphere", "must be 'vacuum' or 'air', got '" + atmosphere + "'");
  soil.atmosphere = *parsed;
  if (f.Has("gravity_scaling")) {
    const std::string scaling = f.String("gravity_scaling");
    const std::optional<rft::GravityScaling> s = rft::ParseGravityScaling(scaling);
    if (!s) f.Fail("gravity_scaling", "must be 'lithostatic' or 'none', got '" + scaling + "'");
    soil.gravity_scaling = *s;
  }
  ReadFields(f, SoilNumberFields(), soil);
  if (soil.internal_friction_angle_rad >= limits::kFrictionAngleBelow_deg * kDeg)
    f.Fail("internal_friction_angle_deg", "must be below " + std::to_string(limits::kFrictionAngleBelow_deg));
  // The 3D laws' soil fields (rft/soil.h): Agarwal 2023's intruder-surface friction, and the
  // dynamic term lambda rho_c (v.n)^2 of the 3D contact (free drops, force, lander).
  if (soil.surface_friction_coefficient > 10.0) f.Fail("mu_surf", "must be at most 10 (a friction coefficient)");
  // `law: bekker` (rft/bekker_law.h): the bekker block is the soil's law and zeta is optional; a
  // bekker block beside an RFT law is kept for `--law bekker`.
  if (f.Has("law")) {
    try {
      soil.rft_law_3d = rft::ParseLawKind(f.String("law"), "", "");
    } catch (const InputError& e) {
      f.Fail("law", e.what());
    }
  }
  const bool bekker = soil.rft_law_3d == rft::LawKind::kBekker;
  if (bekker && !f.Has("bekker")) f.Fail("bekker", "missing (law: bekker needs its bekker block)");
  if (f.Has("bekker")) soil.bekker = ReadBekkerBlock(f);
  if (bekker && !f.Has("zeta_N_cm3")) {
    // no RFT scaling: the soil runs on Bekker's law only
  } else if (!f.Has("zeta_N_cm3")) {
    f.Fail("zeta_N_cm3", "missing (a number, or 'agarwal2023' to derive it)");
  } else if (f.node()["zeta_N_cm3"].IsScalar() && f.node()["zeta_N_cm3"].Scalar() == "agarwal2023") {
    if (soil.bulk_density_kg_m3 == 0.0 || soil.internal_friction_angle_rad == 0.0)
      f.Fail("zeta_N_cm3", "'agarwal2023' needs bulk_density_kg_m3 and internal_friction_angle_deg");
    soil.zeta_N_m3 = rft::AgarwalScalingXi(soil.bulk_density_kg_m3, soil.reference_gravity_m_s2,
                                           std::tan(soil.internal_friction_angle_rad));
    // The derived value meets the range a given one must (the scaling's cubic in tan(phi) grows
    // without bound as phi nears 90 deg: 18,917 N/cm^3 at 85 deg, 2.5e15 at 89.999).
    const double derived_N_cm3 = units::ZetaToN_cm3(soil.zeta_N_m3);
    if (!limits::Within(limits::kZeta_N_cm3, derived_N_cm3)) {
      char inputs[160];
      std::snprintf(inputs, sizeof inputs, " (derived by agarwal2023 from bulk_density_kg_m3 %g, internal_friction_angle_deg %g)",
                    soil.bulk_density_kg_m3, units::RadToDeg(soil.internal_friction_angle_rad));
      f.Fail("zeta_N_cm3", limits::Describe(limits::kZeta_N_cm3, derived_N_cm3) + inputs);
    }
  } else {
    const double zeta_N_cm3 = f.Positive(kSoilZeta.key);
    limits::Require(*kSoilZeta.range, zeta_N_cm3, f.file(), kSoilZeta.key);
    soil.zeta_N_m3 = units::ZetaFromN_cm3(zeta_N_cm3);
  }
  if (f.Has("dynamic_term")) soil.dynamic_term = f.Bool("dynamic_term");
  if (soil.dynamic_term && soil.bulk_density_kg_m3 == 0.0)
    f.Fail("dynamic_term", "needs the soil's bulk_density_kg_m3");
  return soil;
}

void WriteSoil(const rft::SoilParameters& soil, const std::string& path) {
  WriteFileAtomically(path, [&](std::ostream& out) { WriteSoil(soil, out); });
}

void WriteSoil(const rft::SoilParameters& soil, std::ostream& out) {
  YAML::Emitter y;
  WriteMap(y, SoilKeys(), soil);
  out << y.c_str() << '\n';
}

const std::array<BekkerFileField, 3>& BekkerPressureSinkageFields() {
  using B = rft::BekkerParameters;
  static const std::array<BekkerFileField, 3> fields{{
      {"n", 1.0, &limits::kBekkerN, &B::n},
      {"k_c_kN_m_n1", units::kKilo, &limits::kBekkerKc_kN_m_n1, &B::k_c_N_m_n1},
      {"k_phi_kN_m_n2", units::kKilo, &limits::kBekkerKphi_kN_m_n2, &B::k_phi_N_m_n2},
  }};
  return fields;
}

std::vector<BlockDoc> SoilFileSchema() {
  const std::string read_by = "drop_tests/catalog/soil_file.cpp";
  return {MakeBlock("soil", read_by, DocsOf(SoilKeys())), MakeBlock("soil.bekker", read_by, DocsOf(BekkerKeys()))};
}

}  // namespace touchdown::io

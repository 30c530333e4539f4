#include "drop_tests/catalog/catalog.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <system_error>

#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "drop_tests/util/nearest_name.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/yaml_fields.h"
#include "footpad_geom/mesh_io.h"
#include "footpad_geom/pad_body_builder.h"
#include "footpad_geom/revolve.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::io {

namespace fs = std::filesystem;

namespace {
using units::kDeg;
using units::kMm;
// Resolution caps (rft/physical_limits.h).
using limits::kMaxAngularSegments;
using limits::kMaxProfileSegments;

// A soil file's number fields (zeta, with its 'agarwal2023' alternative, is read on its own).
const FieldTable<rft::SoilParameters>& SoilNumberFields() {
  using S = rft::SoilParameters;
  static const FieldTable<S> fields{
      {"reference_gravity_m_s2", &S::reference_gravity_m_s2, 1.0, Sign::kPositive, true, true, &limits::kGravity_m_s2},
      {"bulk_density_kg_m3", &S::bulk_density_kg_m3, 1.0, Sign::kPositive, true, true, &limits::kDensity_kg_m3},
      {"internal_friction_angle_deg", &S::internal_friction_angle_rad, kDeg, Sign::kPositive, true, true},
      {"mu_surf", &S::surface_friction_coefficient, 1.0, Sign::kNonNegative, true, true},
      {"dynamic_lambda", &S::dynamic_lambda, 1.0, Sign::kNonNegative, true, true},
      {"dynamic_density_kg_m3", &S::dynamic_density_kg_m3, 1.0, Sign::kPositive, true, true, &limits::kDensity_kg_m3},
  };
  return fields;
}

// The `bekker:` block of a soil file (rft/bekker_parameters.h): kN, kPa, deg and mm in the file.
const FieldTable<rft::BekkerParameters>& BekkerFields() {
  using B = rft::BekkerParameters;
  static const FieldTable<B> fields{
      {"n", &B::n, 1.0, Sign::kPositive, false, false},
      {"k_c_kN_m_n1", &B::k_c_N_m_n1, 1e3, Sign::kNonNegative, false, false, &limits::kBekkerKc_kN_m_n1},
      {"k_phi_kN_m_n2", &B::k_phi_N_m_n2, 1e3, Sign::kNonNegative, false, false, &limits::kBekkerKphi_kN_m_n2},
      {"cohesion_kPa", &B::cohesion_Pa, 1e3, Sign::kNonNegative, false, false, &limits::kCohesion_kPa},
      {"friction_angle_deg", &B::friction_angle_rad, kDeg, Sign::kNonNegative, false, false},
      {"shear_modulus_K_mm", &B::shear_modulus_K_m, kMm, Sign::kPositive, false, false, &limits::kShearModulusK_mm},
  };
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
        {"zeta_N_cm3", [=](const S& s) { return !bekker_law(s) || s.zeta_N_m3 > 0.0; },
         [](Y& y, const S& s) { y << units::ZetaToN_cm3(s.zeta_N_m3); }},
    };
    AppendNumberKeys(k, SoilNumberFields());
    k.push_back({"law", [](const S& s) { return s.rft_law_3d != rft::LawKind::kLi2013; },
                 [](Y& y, const S& s) { y << std::string(rft::LawKindName(s.rft_law_3d)); }});
    k.push_back({"bekker",
                 [=](const S& s) { return bekker_law(s) || s.bekker.k_c_N_m_n1 + s.bekker.k_phi_N_m_n2 > 0.0; },
                 [](Y& y, const S& s) {
                   y << YAML::BeginMap;
                   WriteKeys(y, BekkerKeys(), s.bekker);
                   y << YAML::EndMap;
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

std::vector<geom::ProfilePoint> ReadProfileTable(const YamlFields& f, PadFileFields& file) {
  std::vector<geom::ProfilePoint> points;
  const YAML::Node list = f.node()["points_mm"];
  if (!list.IsSequence() || list.size() < 2) f.Fail("points_mm", "must be a list of at least two [x, u] pairs");
  if (list.size() > static_cast<size_t>(kMaxProfileSegments) + 1)
    f.Fail("points_mm", "must have at most " + std::to_string(kMaxProfileSegments + 1) + " points, got " +
                            std::to_string(list.size()));
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string path = "points_mm[" + std::to_string(i) + "]";
    double x = 0, u = 0;
    if (!list[i].IsSequence() || list[i].size() != 2 || !YAML::convert<double>::decode(list[i][0], x) ||
        !YAML::convert<double>::decode(list[i][1], u) || !std::isfinite(x) || !std::isfinite(u))
      f.Fail(path, "must be a pair of finite numbers [x_mm, u_mm]");
    points.push_back({x * kMm, u * kMm});
    file.points_mm.push_back({x, u});
  }
  return points;
}

// The geometry factories name the field but not the file: add the file and profile path.
template <typename Build>
geom::AxisymmetricProfile Guarded(const YamlFields& f, Build build) {
  try {
    return build();
  } catch (const InputError& e) {
    throw MakeInputError(f.file(), f.prefix(), e.what());
  }
}

// Each profile shape's number fields, as the file gives them (mm, degrees; kept in PadFileFields),
// read by LoadPad and written by WritePad. nullptr for an unknown shape.
const FieldTable<PadFileFields>* ProfileFields(const std::string& shape) {
  using P = PadFileFields;
  const auto with = [](std::initializer_list<NumberField<P>> own) {
    FieldTable<P> fields{{"radius_mm", &P::radius_mm, 1.0, Sign::kPositive, false},
                         {"thickness_mm", &P::thickness_mm, 1.0, Sign::kPositive, false}};
    fields.insert(fields.end(), own);
    return fields;
  };
  static const std::map<std::string, FieldTable<P>> tables{
      {"flat", with({})},
      {"chamfer", with({{"chamfer_mm", &P::chamfer_mm, 1.0, Sign::kPositive, false}})},
      // u = a0 (exp(a1 x) - 1): give a0 directly, or the rim height u(r) that fixes it.
      {"exponential", with({{"a0_mm", &P::a0_mm, 1.0, Sign::kPositive, true, true},
                            {"rim_height_mm", &P::rim_height_mm, 1.0, Sign::kPositive, true, true},
                            {"a1_per_mm", &P::a1_per_mm, 1.0, Sign::kPositive, false}})},
      {"spherical_cap", with({{"sphere_radius_mm", &P::sphere_radius_mm, 1.0, Sign::kPositive, false}})},
      {"cone", with({{"half_angle_deg", &P::half_angle_deg, 1.0, Sign::kPositive, false}})},
      {"table", with({})},
  };
  const auto it = tables.find(shape);
  return it == tables.end() ? nullptr : &it->second;
}

bool HasSegments(const std::string& shape) { return shape == "exponential" || shape == "spherical_cap"; }

// A profile block's keys for its shape, in the order WritePad writes them.
KeyTable<PadFileFields> ProfileKeys(const std::string& shape) {
  using P = PadFileFields;
  using Y = YAML::Emitter;
  KeyTable<P> k{{"shape", Always<P>, [](Y& y, const P& p) { y << p.shape; }}};
  AppendNumberKeys(k, *ProfileFields(shape));
  if (HasSegments(shape))
    k.push_back({"segments", [](const P& p) { return p.segments > 0; }, [](Y& y, const P& p) { y << p.segments; }});
  if (shape == "table")
    k.push_back({"points_mm", Always<P>, [](Y& y, const P& p) {
                   y << YAML::BeginSeq;
                   for (const std::array<double, 2>& q : p.points_mm)
                     y << YAML::Flow << YAML::BeginSeq << q[0] << q[1] << YAML::EndSeq;
                   y << YAML::EndSeq;
                 }});
  return k;
}

geom::AxisymmetricProfile ReadProfile(const YamlFields& f, PadFileFields& file) {
  file.shape = f.String("shape");
  const FieldTable<PadFileFields>* fields = ProfileFields(file.shape);
  if (!fields)
    f.Fail("shape", "unknown shape '" + file.shape + "' (flat, chamfer, exponential, spherical_cap, cone, table)");
  f.RequireOnly(Keys(ProfileKeys(file.shape)));
  limits::Require(limits::kPadSize_mm, f.Positive("radius_mm"), f.file(), f.Path("radius_mm"));
  limits::Require(limits::kPadSize_mm, f.Positive("thickness_mm"), f.file(), f.Path("thickness_mm"));
  ReadFields(f, *fields, file);
  const double r = file.radius_mm * kMm;
  const double h = file.thickness_mm * kMm;
  if (f.Has("segments")) file.segments = f.PositiveInt("segments");
  const int segments = file.segments > 0 ? file.segments : 400;
  if (segments > kMaxProfileSegments)
    f.Fail("segments", "must be at most " + std::to_string(kMaxProfileSegments) + ", got " + std::to_string(segments));
  if (file.shape == "flat") return Guarded(f, [&] { return geom::MakeFlatProfile(r, h); });
  if (file.shape == "chamfer") {
    const double c = file.chamfer_mm * kMm;
    return Guarded(f, [&] { return geom::MakeChamferProfile(r, h, c); });
  }
  if (file.shape == "exponential") {
    const double a1 = file.a1_per_mm / kMm;
    if (f.Has("a0_mm") == f.Has("rim_height_mm")) f.Fail("a0_mm", "give exactly one of a0_mm and rim_height_mm");
    const double a0 = f.Has("a0_mm") ? file.a0_mm * kMm : file.rim_height_mm * kMm / std::expm1(a1 * r);
    return Guarded(f, [&] { return geom::MakeExponentialProfile(r, h, a0, a1, segments); });
  }
  if (file.shape == "spherical_cap") {
    const double R = file.sphere_radius_mm * kMm;
    return Guarded(f, [&] { return geom::MakeSphericalCapProfile(r, h, R, segments); });
  }
  if (file.shape == "cone") {
    const double half_angle = file.half_angle_deg * kDeg;
    return Guarded(f, [&] { return geom::MakeConeProfile(r, h, half_angle); });
  }
  std::vector<geom::ProfilePoint> points = ReadProfileTable(f, file);  // shape: table
  if (std::abs(points.back().x_m - r) > 1e-12) f.Fail("points_mm", "last point must be at the rim, x = radius_mm");
  return Guarded(f, [&] { return geom::MakeTabulatedProfile(std::move(points), h); });
}

// A point in mm, kept as the file gives it in `given`, returned in m.
Eigen::Vector3d ReadPointMm(const YamlFields& f, const std::string& key, std::optional<std::array<double, 3>>& given) {
  const YAML::Node list = f.node()[key];
  Eigen::Vector3d p;
  if (!list.IsSequence() || list.size() != 3) f.Fail(key, "must be a list of three numbers [x, y, z] in mm");
  for (int i = 0; i < 3; ++i)
    if (!YAML::convert<double>::decode(list[i], p(i)) || !std::isfinite(p(i)))
      f.Fail(key, "must be a list of three finite numbers [x, y, z] in mm");
  given = std::array<double, 3>{p.x(), p.y(), p.z()};
  return p * kMm;
}

double Mass(const YamlFields& f, const std::string& key) { return ReadNumber(f, key, Sign::kPositive, &limits::kMass_kg); }

// The optional explicit inertia and centre of mass, shared by both pad kinds.
void ReadMassDistribution(const YamlFields& f, geom::PadMassModel& mass, PadFileFields& file) {
  if (f.Has("inertia_kg_m2")) {
    const Eigen::Matrix3d m = ReadInertia(f.Child("inertia_kg_m2"));
    mass.inertia_com_kg_m2 = m;
    file.inertia_kg_m2 = std::array<double, 6>{m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2)};
  }
  if (f.Has("center_of_mass_mm")) {
    if (!f.Has("inertia_kg_m2")) f.Fail("center_of_mass_mm", "needs inertia_kg_m2 (about that centre) as well");
    mass.center_of_mass_m = ReadPointMm(f, "center_of_mass_mm", file.center_of_mass_mm);
  }
}

// Builds the body; the builder names the field, the YAML file is added here.
template <typename Build>
geom::PadBody GuardedBody(const YamlFields& f, Build build) {
  try {
    return build();
  } catch (const InputError& e) {
    const std::string what = e.what();
    throw MakeInputError(what.starts_with(f.file()) ? "" : f.file(), "", what);
  }
}

void LoadAxisymmetricPad(const YamlFields& f, PadSpec& pad) {
  pad.file.mass_kg = Mass(f, "mass_kg");
  pad.mass_kg = pad.file.mass_kg;
  pad.profile = ReadProfile(f.Child("profile"), pad.file);
  geom::ValidateProfile(pad.profile, f.file());
  if (f.Has("angular_segments")) pad.file.angular_segments = f.PositiveInt("angular_segments");
  const int segments = PadRimSegments(pad);
  if (segments < limits::kMinAngularSegments)
    f.Fail("angular_segments", "must be at least " + std::to_string(limits::kMinAngularSegments) + ", got " +
                                   std::to_string(segments));
  if (segments > kMaxAngularSegments)
    f.Fail("angular_segments", "must be at most " + std::to_string(kMaxAngularSegments) + ", got " +
                                   std::to_string(segments));
  const Eigen::Vector3d reference =
      f.Has("reference_point_mm") ? ReadPointMm(f, "reference_point_mm", pad.file.reference_point_mm)
                                  : Eigen::Vector3d(0.0, 0.0, pad.profile.thickness_m());
  geom::PadMassModel mass;
  mass.mass_kg = pad.mass_kg;
  ReadMassDistribution(f, mass, pad.file);
  pad.body = GuardedBody(f, [&] {
    return geom::MakePadBody(geom::RevolveProfileToMesh(pad.profile, segments, pad.rim), mass, reference, f.file());
  });
}

// A pad to write, and where (a mesh is written relative to the pad file).
struct PadToWrite {
  const PadSpec& pad;
  fs::path path;
};

// The `mesh` block's keys, in the order WritePad writes them.
const KeyTable<PadToWrite>& MeshKeys() {
  using W = PadToWrite;
  using Y = YAML::Emitter;
  static const KeyTable<W> keys{
      {"file", Always<W>,
       [](Y& y, const W& w) {
         // The mesh relative to the written file (as LoadPad reads it), wherever either lives.
         const fs::path mesh = fs::absolute(w.pad.mesh_file).lexically_normal();
         const fs::path rel = mesh.lexically_relative(fs::absolute(w.path).parent_path().lexically_normal());
         y << (rel.empty() ? mesh : rel).generic_string();
       }},
      {"unit", Always<W>, [](Y& y, const W& w) { y << w.pad.file.mesh_unit; }},
      {"remesh_edge_mm", [](const W& w) { return w.pad.file.remesh_edge_mm > 0.0; },
       [](Y& y, const W& w) { y << w.pad.file.remesh_edge_mm; }},
  };
  return keys;
}

// An inertia block's keys (ixx, iyy, izz, ixy, ixz, iyz), as a pad file and a lander file give it.
const KeyTable<std::array<double, 6>>& InertiaKeys() {
  using I = std::array<double, 6>;
  const auto entry = [](const char* key, int k) -> FileKey<I> {
    return {key, Always<I>, [k](YAML::Emitter& y, const I& i) { y << i[k]; }};
  };
  static const KeyTable<I> keys{entry("ixx", 0), entry("iyy", 1), entry("izz", 2),
                                entry("ixy", 3), entry("ixz", 4), entry("iyz", 5)};
  return keys;
}

void WritePoint(YAML::Emitter& y, const std::array<double, 3>& v) {
  y << YAML::Flow << YAML::BeginSeq << v[0] << v[1] << v[2] << YAML::EndSeq;
}

// A pad file's keys (both kinds), in the order WritePad writes them.
const KeyTable<PadToWrite>& PadKeys() {
  using W = PadToWrite;
  using Y = YAML::Emitter;
  const auto axisymmetric = [](const W& w) { return w.pad.kind == PadKind::kAxisymmetric; };
  static const KeyTable<W> keys{
      {"schema_version", Always<W>, [](Y& y, const W&) { y << 1; }},
      {"name", Always<W>, [](Y& y, const W& w) { y << w.pad.name; }},
      {"kind", Always<W>, [](Y& y, const W& w) { y << (w.pad.kind == PadKind::kMesh ? "mesh" : "axisymmetric"); }},
      {"description", [](const W& w) { return !w.pad.file.description.empty(); },
       [](Y& y, const W& w) { y << w.pad.file.description; }},
      {"mass_kg", [](const W& w) { return w.pad.file.mass_kg > 0.0; }, [](Y& y, const W& w) { y << w.pad.file.mass_kg; }},
      {"density_kg_m3", [](const W& w) { return w.pad.file.density_kg_m3 > 0.0; },
       [](Y& y, const W& w) { y << w.pad.file.density_kg_m3; }},
      {"profile", axisymmetric,
       [](Y& y, const W& w) {
         y << YAML::BeginMap;
         WriteKeys(y, ProfileKeys(w.pad.file.shape), w.pad.file);
         y << YAML::EndMap;
       }},
      {"mesh", [=](const W& w) { return !axisymmetric(w); },
       [](Y& y, const W& w) {
         y << YAML::BeginMap;
         WriteKeys(y, MeshKeys(), w);
         y << YAML::EndMap;
       }},
      {"angular_segments", [=](const W& w) { return axisymmetric(w) && w.pad.file.angular_segments > 0; },
       [](Y& y, const W& w) { y << w.pad.file.angular_segments; }},
      {"reference_point_mm", [](const W& w) { return w.pad.file.reference_point_mm.has_value(); },
       [](Y& y, const W& w) { WritePoint(y, *w.pad.file.reference_point_mm); }},
      {"inertia_kg_m2", [](const W& w) { return w.pad.file.inertia_kg_m2.has_value(); },
       [](Y& y, const W& w) {
         y << YAML::Flow << YAML::BeginMap;
         WriteKeys(y, InertiaKeys(), *w.pad.file.inertia_kg_m2);
         y << YAML::EndMap;
       }},
      {"center_of_mass_mm", [](const W& w) { return w.pad.file.center_of_mass_mm.has_value(); },
       [](Y& y, const W& w) { WritePoint(y, *w.pad.file.center_of_mass_mm); }},
      {"provenance"},
  };
  return keys;
}

void LoadMeshPad(const YamlFields& f, PadSpec& pad) {
  const YamlFields m = f.Child("mesh");
  m.RequireOnly(Keys(MeshKeys()));
  fs::path file = m.String("file");
  if (file.is_relative()) file = fs::path(f.file()).parent_path() / file;  // relative to the YAML file
  pad.mesh_file = file.lexically_normal().string();
  geom::MeshLoadOptions options;
  pad.file.mesh_unit = m.String("unit");
  options.unit = geom::ParseLengthUnit(pad.file.mesh_unit, f.file(), m.Path("unit"));
  if (m.Has("remesh_edge_mm")) {
    pad.file.remesh_edge_mm = m.Positive("remesh_edge_mm");
    options.remesh_edge_m = pad.file.remesh_edge_mm * kMm;
  }
  geom::TriangleMesh mesh;
  try {
    mesh = geom::LoadTriangleMesh(pad.mesh_file, options).mesh;
  } catch (const InputError& e) {
    throw MakeInputError(f.file(), m.Path("file"), e.what());
  }

  geom::PadMassModel mass;
  if (f.Has("mass_kg") == f.Has("density_kg_m3")) f.Fail("mass_kg", "give exactly one of mass_kg and density_kg_m3");
  if (f.Has("mass_kg")) mass.mass_kg = pad.file.mass_kg = Mass(f, "mass_kg");
  if (f.Has("density_kg_m3"))
    mass.density_kg_m3 = pad.file.density_kg_m3 = ReadNumber(f, "density_kg_m3", Sign::kPositive, &limits::kDensity_kg_m3);
  ReadMassDistribution(f, mass, pad.file);
  Eigen::Vector3d reference;
  if (f.Has("reference_point_mm")) {
    reference = ReadPointMm(f, "reference_point_mm", pad.file.reference_point_mm);
  } else {
    Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
    for (const Eigen::Vector3d& v : mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    reference = Eigen::Vector3d(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), hi.z());
  }
  pad.body = GuardedBody(f, [&] { return geom::MakePadBody(mesh, mass, reference, f.file()); });
  pad.mass_kg = pad.body.mass_kg;
  if (mass.density_kg_m3)
    limits::Require(limits::kMass_kg, pad.mass_kg, f.file(), f.Path("density_kg_m3") + " (the pad's mass it gives)");
}
}  // namespace

Eigen::Matrix3d ReadInertia(const YamlFields& i) {
  i.RequireOnly(Keys(InertiaKeys()));
  const auto moment = [&](const char* key) { return ReadNumber(i, key, Sign::kPositive, &limits::kInertia_kg_m2); };
  const auto product = [&](const char* key) { return i.Has(key) ? i.Number(key) : 0.0; };
  Eigen::Matrix3d m;
  m << moment("ixx"), product("ixy"), product("ixz"),  //
      product("ixy"), moment("iyy"), product("iyz"),   //
      product("ixz"), product("iyz"), moment("izz");
  geom::ValidateInertia(m, i.file(), i.prefix());
  return m;
}

namespace {
// The data installed with the running executable (`cmake --install`: <prefix>/bin/touchdown and
// <prefix>/share/touchdown), if there is such a folder. /proc/self/exe names the executable file
// itself, whatever link or relative path started it. None in the build tree (build/apps/touchdown
// has no share/ beside it), nor for a program elsewhere that links the libraries.
std::optional<std::string> DataBesideExecutable() {
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  const fs::path data = (executable.parent_path() / TOUCHDOWN_DATA_DIR_FROM_BIN).lexically_normal();
  if (!fs::is_directory(data, ec)) return std::nullopt;
  return data.string();
}
}  // namespace

// $TOUCHDOWN_DATA_DIR, else an installed copy's own data, else the source tree's data/ this
// build was made from (docs/install.md).
std::string DataDirectory() {
  if (const char* env = std::getenv("TOUCHDOWN_DATA_DIR"); env && *env) return env;
  return DataBesideExecutable().value_or(TOUCHDOWN_DATA_DIR);
}

std::string ResolveCatalogFile(const std::string& kind, const std::string& name_or_path) {
  if (name_or_path.empty()) throw MakeInputError("", kind, "empty name");
  const bool is_path = name_or_path.find('/') != std::string::npos ||
                       name_or_path.ends_with(".yaml") || name_or_path.ends_with(".yml");
  const std::string path = is_path ? name_or_path : DataDirectory() + "/" + kind + "/" + name_or_path + ".yaml";
  if (is_path) {
    RequireReadableFile(path);  // says what is wrong: missing, a directory, a loop, no permission
    return path;
  }
  if (!fs::is_regular_file(path)) {
    // No shelf at all means no data directory, not a misspelt name: say where it was looked for.
    const std::string shelf = DataDirectory() + "/" + kind;
    if (!fs::is_directory(shelf))
      throw MakeInputError(shelf, kind,
                           "no such data directory, so no bundled name such as '" + name_or_path +
                               "' (set TOUCHDOWN_DATA_DIR to touchdown's data/ folder, or give a file path)");
    const std::vector<std::string> names = CatalogNames(kind);
    std::string known;
    for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
    throw MakeInputError("", kind, "unknown name '" + name_or_path + "'" + DidYouMean(name_or_path, names) +
                                       " (known: " + known + ")");
  }
  return path;
}

std::string ResolveCatalogFileNear(const std::string& referring_file, const std::string& kind,
                                   const std::string& name_or_path) {
  const bool is_path = name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".yaml") ||
                       name_or_path.ends_with(".yml");
  if (is_path && fs::path(name_or_path).is_relative()) {
    const fs::path beside = fs::path(referring_file).parent_path() / name_or_path;
    if (fs::is_regular_file(beside)) return beside.lexically_normal().string();
  }
  return ResolveCatalogFile(kind, name_or_path);
}

std::vector<std::string> CatalogNames(const std::string& kind) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(DataDirectory() + "/" + kind, ec))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

namespace {
// A YAML file's top-level `type:`; "" when it cannot be read as a map. A campaign file may leave
// it out (LoadCampaignScenario's default; every other input type requires it).
std::string DocumentType(const fs::path& file) {
  try {
    const YAML::Node node = YAML::LoadFile(file.string());
    if (!node.IsMap()) return "";
    return node["type"] ? node["type"].as<std::string>() : "campaign";
  } catch (const std::exception&) {
    return "";  // not a document of any shelf; its loader says why when it is named by path
  }
}
}  // namespace

std::vector<CatalogShelf> ShelvesOf(InputDocument document) {
  const CatalogShelf campaigns{"scenarios", "campaign", "campaign scenarios"};
  const CatalogShelf landers{"scenarios", "lander", "lander scenarios"};
  const CatalogShelf sweeps{"sweeps", "sweep", "sweeps"};
  const CatalogShelf studies{"studies", "stability", "studies"};
  switch (document) {
    case InputDocument::kCampaign: return {campaigns};
    case InputDocument::kLander: return {landers};
    case InputDocument::kSweep: return {sweeps, studies};
    case InputDocument::kTrade: return {sweeps};
    case InputDocument::kStudy: return {studies};
  }
  return {};
}

std::vector<std::string> ShelfNames(const CatalogShelf& shelf) {
  std::vector<std::string> names;
  for (const std::string& name : CatalogNames(shelf.kind))
    if (DocumentType(fs::path(DataDirectory()) / shelf.kind / (name + ".yaml")) == shelf.type) names.push_back(name);
  return names;
}

std::string ResolveInputDocument(InputDocument document, const std::string& name_or_path) {
  const bool is_path = name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".yaml") ||
                       name_or_path.ends_with(".yml");
  std::error_code ec;
  if (is_path || name_or_path.empty() || fs::exists(fs::symlink_status(name_or_path, ec))) return name_or_path;
  std::vector<std::string> all;
  std::string known;
  for (const CatalogShelf& shelf : ShelvesOf(document)) {
    const std::vector<std::string> names = ShelfNames(shelf);
    if (std::find(names.begin(), names.end(), name_or_path) != names.end())
      return DataDirectory() + "/" + shelf.kind + "/" + name_or_path + ".yaml";
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    known += (known.empty() ? "" : "; ") + shelf.label + " in " + DataDirectory() + "/" + shelf.kind + ": " + list;
    all.insert(all.end(), names.begin(), names.end());
  }
  throw MakeInputError(name_or_path, "", "no such file, nor a bundled name" + DidYouMean(name_or_path, all) + " (" +
                                             known + ")");
}

PadSpec LoadPad(const std::string& name_or_path) {
  return LoadPad(YamlFields::LoadFile(ResolveCatalogFile("pads", name_or_path)));
}

int PadRimSegments(const PadSpec& pad) {
  if (!pad.is_axisymmetric()) return 0;
  return pad.file.angular_segments > 0 ? pad.file.angular_segments : geom::kDefaultAngularSegments;
}

PadSpec FlatPadWithRadius(const PadSpec& pad, double radius_mm, geom::RimPolygon rim) {
  if (pad.file.shape != "flat")
    throw MakeInputError(pad.source, "profile.shape", "pad '" + pad.name + "' is not a flat revolved profile");
  YAML::Node node = YAML::Clone(YamlFields::LoadFile(pad.source).node());
  node["profile"]["radius_mm"] = radius_mm;
  return LoadPad(YamlFields(node, pad.source, ""), rim);
}

PadSpec PadWithAngularSegments(const PadSpec& pad, int angular_segments, geom::RimPolygon rim) {
  if (!pad.is_axisymmetric())
    throw MakeInputError(pad.source, "angular_segments", "pad '" + pad.name + "' is a mesh, not a revolved profile");
  YAML::Node node = YAML::Clone(YamlFields::LoadFile(pad.source).node());
  node["angular_segments"] = angular_segments;
  return LoadPad(YamlFields(node, pad.source, ""), rim);
}

PadSpec LoadPad(const YamlFields& f, geom::RimPolygon rim) {
  f.RequireSchemaVersion(1);
  PadSpec pad;
  pad.rim = rim;
  pad.source = f.file();
  const std::string kind = f.StringOr("kind", "axisymmetric");
  pad.name = f.StringOr("name", fs::path(f.file()).stem().string());
  pad.file.description = f.StringOr("description", "");
  if (!IsValidUtf8(pad.name)) f.Fail("name", "the pad name (from the file name) is not valid UTF-8 text");
  if (kind == "axisymmetric") {
    pad.kind = PadKind::kAxisymmetric;
    f.RequireOnly(Keys(PadKeys(), {"mesh", "density_kg_m3"}));
    LoadAxisymmetricPad(f, pad);
  } else if (kind == "mesh") {
    pad.kind = PadKind::kMesh;
    f.RequireOnly(Keys(PadKeys(), {"profile", "angular_segments"}));
    LoadMeshPad(f, pad);
  } else {
    f.Fail("kind", "unknown pad kind '" + kind + "' (axisymmetric, mesh)");
  }
  return pad;
}

rft::SoilParameters LoadSoil(const std::string& name_or_path) {
  const std::string path = ResolveCatalogFile("soils", name_or_path);
  const YamlFields f = YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(Keys(SoilKeys()));
  rft::SoilParameters soil;
  soil.name = f.StringOr("name", fs::path(path).stem().string());
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
  } else {
    const double zeta_N_cm3 = f.Positive("zeta_N_cm3");
    limits::Require(limits::kZeta_N_cm3, zeta_N_cm3, f.file(), "zeta_N_cm3");
    soil.zeta_N_m3 = units::ZetaFromN_cm3(zeta_N_cm3);
  }
  if (f.Has("dynamic_term")) soil.dynamic_term = f.Bool("dynamic_term");
  if (soil.dynamic_term && soil.bulk_density_kg_m3 == 0.0)
    f.Fail("dynamic_term", "needs the soil's bulk_density_kg_m3");
  return soil;
}

void WritePad(const PadSpec& pad, const std::string& path) {
  YAML::Emitter y;
  y << YAML::BeginMap;
  WriteKeys(y, PadKeys(), PadToWrite{pad, path});
  y << YAML::EndMap;
  WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

void WriteSoil(const rft::SoilParameters& soil, const std::string& path) {
  WriteFileAtomically(path, [&](std::ostream& out) { WriteSoil(soil, out); });
}

void WriteSoil(const rft::SoilParameters& soil, std::ostream& out) {
  YAML::Emitter y;
  y << YAML::BeginMap;
  WriteKeys(y, SoilKeys(), soil);
  y << YAML::EndMap;
  out << y.c_str() << '\n';
}

}  // namespace touchdown::io

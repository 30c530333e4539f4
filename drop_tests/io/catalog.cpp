#include "drop_tests/io/catalog.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "drop_tests/io/field_table.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/io/yaml_fields.h"
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
constexpr double kMm = 1e-3;
using units::kDeg;
// Resolution caps, so a hand-written 1e9 is refused at load time instead of exhausting memory
// (or hanging the profile simplification, which is quadratic in the profile's points). The
// revolved mesh has about 0.5 N^2 triangles for N angular segments (~8k at the default 128,
// ~500k at 1024); 10000 profile pieces resolve any curve a pad drawing can specify.
constexpr int kMaxAngularSegments = 1024;
constexpr int kMaxProfileSegments = 10000;

// A soil file's number fields (zeta, with its 'agarwal2023' alternative, is read on its own).
const FieldTable<rft::SoilParameters>& SoilNumberFields() {
  using S = rft::SoilParameters;
  static const FieldTable<S> fields{
      {"reference_gravity_m_s2", &S::reference_gravity_m_s2, 1.0, Sign::kPositive, true, true},
      {"bulk_density_kg_m3", &S::bulk_density_kg_m3, 1.0, Sign::kPositive, true, true},
      {"internal_friction_angle_deg", &S::internal_friction_angle_rad, kDeg, Sign::kPositive, true, true},
      {"mu_surf", &S::surface_friction_coefficient, 1.0, Sign::kNonNegative, true, true},
      {"dynamic_lambda", &S::dynamic_lambda, 1.0, Sign::kNonNegative, true, true},
      {"dynamic_density_kg_m3", &S::dynamic_density_kg_m3, 1.0, Sign::kPositive, true, true},
  };
  return fields;
}

std::vector<geom::ProfilePoint> ReadProfileTable(const YamlFields& f) {
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

geom::AxisymmetricProfile ReadProfile(const YamlFields& f) {
  const std::string shape = f.String("shape");
  limits::Require(limits::kPadSize_mm, f.Positive("radius_mm"), f.file(), f.Path("radius_mm"));
  limits::Require(limits::kPadSize_mm, f.Positive("thickness_mm"), f.file(), f.Path("thickness_mm"));
  const double r = f.Positive("radius_mm") * kMm;
  const double h = f.Positive("thickness_mm") * kMm;
  const int segments = f.Has("segments") ? f.PositiveInt("segments") : 400;
  if (segments > kMaxProfileSegments)
    f.Fail("segments", "must be at most " + std::to_string(kMaxProfileSegments) + ", got " + std::to_string(segments));
  if (shape == "flat") {
    f.RequireOnly({"shape", "radius_mm", "thickness_mm"});
    return Guarded(f, [&] { return geom::MakeFlatProfile(r, h); });
  }
  if (shape == "chamfer") {
    f.RequireOnly({"shape", "radius_mm", "thickness_mm", "chamfer_mm"});
    const double c = f.Positive("chamfer_mm") * kMm;
    return Guarded(f, [&] { return geom::MakeChamferProfile(r, h, c); });
  }
  if (shape == "exponential") {
    // u = a0 (exp(a1 x) - 1): give a0 directly, or the rim height u(r) that fixes it.
    f.RequireOnly({"shape", "radius_mm", "thickness_mm", "a0_mm", "rim_height_mm", "a1_per_mm", "segments"});
    const double a1 = f.Positive("a1_per_mm") / kMm;
    if (f.Has("a0_mm") == f.Has("rim_height_mm")) f.Fail("a0_mm", "give exactly one of a0_mm and rim_height_mm");
    const double a0 = f.Has("a0_mm") ? f.Positive("a0_mm") * kMm : f.Positive("rim_height_mm") * kMm / std::expm1(a1 * r);
    return Guarded(f, [&] { return geom::MakeExponentialProfile(r, h, a0, a1, segments); });
  }
  if (shape == "spherical_cap") {
    f.RequireOnly({"shape", "radius_mm", "thickness_mm", "sphere_radius_mm", "segments"});
    const double R = f.Positive("sphere_radius_mm") * kMm;
    return Guarded(f, [&] { return geom::MakeSphericalCapProfile(r, h, R, segments); });
  }
  if (shape == "cone") {
    f.RequireOnly({"shape", "radius_mm", "thickness_mm", "half_angle_deg"});
    const double half_angle = f.Positive("half_angle_deg") * kDeg;
    return Guarded(f, [&] { return geom::MakeConeProfile(r, h, half_angle); });
  }
  if (shape == "table") {
    f.RequireOnly({"shape", "radius_mm", "thickness_mm", "points_mm"});
    std::vector<geom::ProfilePoint> points = ReadProfileTable(f);
    if (std::abs(points.back().x_m - r) > 1e-12) f.Fail("points_mm", "last point must be at the rim, x = radius_mm");
    return Guarded(f, [&] { return geom::MakeTabulatedProfile(std::move(points), h); });
  }
  f.Fail("shape", "unknown shape '" + shape + "' (flat, chamfer, exponential, spherical_cap, cone, table)");
}

Eigen::Vector3d ReadPointMm(const YamlFields& f, const std::string& key) {
  const YAML::Node list = f.node()[key];
  Eigen::Vector3d p;
  if (!list.IsSequence() || list.size() != 3) f.Fail(key, "must be a list of three numbers [x, y, z] in mm");
  for (int i = 0; i < 3; ++i)
    if (!YAML::convert<double>::decode(list[i], p(i)) || !std::isfinite(p(i)))
      f.Fail(key, "must be a list of three finite numbers [x, y, z] in mm");
  return p * kMm;
}

// The optional explicit inertia and centre of mass, shared by both pad kinds.
void ReadMassDistribution(const YamlFields& f, geom::PadMassModel& mass) {
  if (f.Has("inertia_kg_m2")) {
    const YamlFields i = f.Child("inertia_kg_m2");
    i.RequireOnly({"ixx", "iyy", "izz", "ixy", "ixz", "iyz"});
    auto product = [&](const char* key) { return i.Has(key) ? i.Number(key) : 0.0; };
    Eigen::Matrix3d m;
    m << i.Positive("ixx"), product("ixy"), product("ixz"),  //
        product("ixy"), i.Positive("iyy"), product("iyz"),   //
        product("ixz"), product("iyz"), i.Positive("izz");
    mass.inertia_com_kg_m2 = m;
  }
  if (f.Has("center_of_mass_mm")) {
    if (!f.Has("inertia_kg_m2")) f.Fail("center_of_mass_mm", "needs inertia_kg_m2 (about that centre) as well");
    mass.center_of_mass_m = ReadPointMm(f, "center_of_mass_mm");
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
  pad.mass_kg = f.Positive("mass_kg");
  pad.profile = ReadProfile(f.Child("profile"));
  geom::ValidateProfile(pad.profile, f.file());
  const int segments = f.Has("angular_segments") ? f.PositiveInt("angular_segments") : geom::kDefaultAngularSegments;
  if (segments < 6) f.Fail("angular_segments", "must be at least 6, got " + std::to_string(segments));
  if (segments > kMaxAngularSegments)
    f.Fail("angular_segments", "must be at most " + std::to_string(kMaxAngularSegments) + ", got " +
                                   std::to_string(segments));
  const Eigen::Vector3d reference =
      f.Has("reference_point_mm") ? ReadPointMm(f, "reference_point_mm")
                                  : Eigen::Vector3d(0.0, 0.0, pad.profile.thickness_m());
  geom::PadMassModel mass;
  mass.mass_kg = pad.mass_kg;
  ReadMassDistribution(f, mass);
  pad.body = GuardedBody(f, [&] {
    return geom::MakePadBody(geom::RevolveProfileToMesh(pad.profile, segments), mass, reference, f.file());
  });
}

void LoadMeshPad(const YamlFields& f, PadSpec& pad) {
  const YamlFields m = f.Child("mesh");
  m.RequireOnly({"file", "unit", "remesh_edge_mm"});
  fs::path file = m.String("file");
  if (file.is_relative()) file = fs::path(f.file()).parent_path() / file;  // relative to the YAML file
  pad.mesh_file = file.lexically_normal().string();
  geom::MeshLoadOptions options;
  options.unit = geom::ParseLengthUnit(m.String("unit"), f.file(), m.Path("unit"));
  if (m.Has("remesh_edge_mm")) options.remesh_edge_m = m.Positive("remesh_edge_mm") * kMm;
  geom::TriangleMesh mesh;
  try {
    mesh = geom::LoadTriangleMesh(pad.mesh_file, options).mesh;
  } catch (const InputError& e) {
    throw MakeInputError(f.file(), m.Path("file"), e.what());
  }

  geom::PadMassModel mass;
  if (f.Has("mass_kg") == f.Has("density_kg_m3")) f.Fail("mass_kg", "give exactly one of mass_kg and density_kg_m3");
  if (f.Has("mass_kg")) mass.mass_kg = f.Positive("mass_kg");
  if (f.Has("density_kg_m3")) mass.density_kg_m3 = f.Positive("density_kg_m3");
  ReadMassDistribution(f, mass);
  Eigen::Vector3d reference;
  if (f.Has("reference_point_mm")) {
    reference = ReadPointMm(f, "reference_point_mm");
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
}
}  // namespace

std::string DataDirectory() {
  if (const char* env = std::getenv("TOUCHDOWN_DATA_DIR"); env && *env) return env;
  return TOUCHDOWN_DATA_DIR;
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
    std::string known;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(DataDirectory() + "/" + kind, ec))
      if (entry.path().extension() == ".yaml") known += (known.empty() ? "" : ", ") + entry.path().stem().string();
    throw MakeInputError("", kind, "unknown name '" + name_or_path + "' (known: " + known + ")");
  }
  return path;
}

PadSpec LoadPad(const std::string& name_or_path) {
  const std::string path = ResolveCatalogFile("pads", name_or_path);
  const YamlFields f = YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  PadSpec pad;
  pad.source = path;
  const std::string kind = f.StringOr("kind", "axisymmetric");
  pad.name = f.StringOr("name", fs::path(path).stem().string());
  if (!IsValidUtf8(pad.name)) f.Fail("name", "the pad name (from the file name) is not valid UTF-8 text");
  if (kind == "axisymmetric") {
    pad.kind = PadKind::kAxisymmetric;
    f.RequireOnly({"schema_version", "name", "kind", "mass_kg", "profile", "description", "provenance",
                   "angular_segments", "reference_point_mm", "inertia_kg_m2", "center_of_mass_mm"});
    LoadAxisymmetricPad(f, pad);
  } else if (kind == "mesh") {
    pad.kind = PadKind::kMesh;
    f.RequireOnly({"schema_version", "name", "kind", "mesh", "mass_kg", "density_kg_m3", "description",
                   "provenance", "reference_point_mm", "inertia_kg_m2", "center_of_mass_mm"});
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
  std::vector<std::string> known{"schema_version", "name", "description", "atmosphere", "zeta_N_cm3", "provenance",
                                 "dynamic_term"};
  for (const std::string& key : FieldKeys(SoilNumberFields())) known.push_back(key);
  f.RequireOnly(known);
  rft::SoilParameters soil;
  soil.name = f.StringOr("name", fs::path(path).stem().string());
  if (!IsValidUtf8(soil.name)) f.Fail("name", "the soil name (from the file name) is not valid UTF-8 text");
  const std::string atmosphere = f.StringOr("atmosphere", "vacuum");
  const std::optional<rft::Atmosphere> parsed = rft::ParseAtmosphere(atmosphere);
  if (!parsed) f.Fail("atmosphere", "must be 'vacuum' or 'air', got '" + atmosphere + "'");
  soil.atmosphere = *parsed;
  ReadFields(f, SoilNumberFields(), soil);
  if (soil.internal_friction_angle_rad >= 90.0 * kDeg) f.Fail("internal_friction_angle_deg", "must be below 90");
  // The 3D laws' soil fields (rft/soil.h): Agarwal 2023's intruder-surface friction, and the
  // dynamic term lambda rho_c (v.n)^2 of the 3D contact (free drops, force, lander).
  if (soil.surface_friction_coefficient > 10.0) f.Fail("mu_surf", "must be at most 10 (a friction coefficient)");
  if (!f.Has("zeta_N_cm3")) f.Fail("zeta_N_cm3", "missing (a number, or 'agarwal2023' to derive it)");
  if (f.node()["zeta_N_cm3"].IsScalar() && f.node()["zeta_N_cm3"].Scalar() == "agarwal2023") {
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
  if (soil.dynamic_term && soil.dynamic_density_kg_m3 == 0.0 && soil.bulk_density_kg_m3 == 0.0)
    f.Fail("dynamic_term", "needs a density: dynamic_density_kg_m3 or bulk_density_kg_m3");
  return soil;
}

void WriteSoil(const rft::SoilParameters& soil, const std::string& path) {
  YAML::Emitter y;
  y << YAML::BeginMap << YAML::Key << "schema_version" << YAML::Value << 1 << YAML::Key << "name" << YAML::Value
    << soil.name << YAML::Key << "atmosphere" << YAML::Value << rft::AtmosphereName(soil.atmosphere) << YAML::Key << "zeta_N_cm3"
    << YAML::Value << units::ZetaToN_cm3(soil.zeta_N_m3);
  WriteFields(y, SoilNumberFields(), soil);
  if (soil.dynamic_term) y << YAML::Key << "dynamic_term" << YAML::Value << true;
  y << YAML::EndMap;
  WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

}  // namespace touchdown::io

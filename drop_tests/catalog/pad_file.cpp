#include "drop_tests/catalog/catalog.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/yaml_fields.h"
#include "footpad_geom/mesh_io.h"
#include "footpad_geom/pad_body_builder.h"
#include "footpad_geom/revolve.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

// A pad file (data/pads; docs/reference.md): a revolved profile or a mesh, loaded into its body,
// checked and written.
namespace touchdown::io {

namespace fs = std::filesystem;

namespace {
using units::kDeg;
using units::kMm;
// Resolution caps (rft/physical_limits.h).
using limits::kMaxAngularSegments;
using limits::kMaxProfileSegments;

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

}  // namespace

const char* PadShapeName(PadShape shape) { return NameIn(kPadShapeNames, shape); }

std::optional<PadShape> ParsePadShape(const std::string& name) { return FindName(kPadShapeNames, name); }

namespace {

// Each profile shape's number fields, as the file gives them (mm, degrees; kept in PadFileFields),
// read by LoadPad and written by WritePad. nullptr for an unknown shape.
const FieldTable<PadFileFields>* ProfileFields(PadShape shape) {
  using P = PadFileFields;
  static constexpr const char* kA0OrRimHeight = "one of `a0_mm`, `rim_height_mm` (exponential)";
  const auto with = [](std::initializer_list<NumberField<P>> own) {
    FieldTable<P> fields{{"radius_mm", &P::radius_mm, 1.0, Sign::kPositive, false, false, &limits::kPadSize_mm},
                         {"thickness_mm", &P::thickness_mm, 1.0, Sign::kPositive, false, false, &limits::kPadSize_mm}};
    fields.insert(fields.end(), own);
    return fields;
  };
  static const std::map<PadShape, FieldTable<P>> tables{
      {PadShape::kFlat, with({})},
      {PadShape::kChamfer,
       with({{"chamfer_mm", &P::chamfer_mm, 1.0, Sign::kPositive, false, false, nullptr, "*required* (chamfer)"}})},
      // u = a0 (exp(a1 x) - 1): give a0 directly, or the rim height u(r) that fixes it.
      {PadShape::kExponential,
       with({{"a0_mm", &P::a0_mm, 1.0, Sign::kPositive, true, true, nullptr, kA0OrRimHeight},
             {"rim_height_mm", &P::rim_height_mm, 1.0, Sign::kPositive, true, true, nullptr, kA0OrRimHeight},
             {"a1_per_mm", &P::a1_per_mm, 1.0, Sign::kPositive, false, false, nullptr, "*required* (exponential)"}})},
      {PadShape::kSphericalCap, with({{"sphere_radius_mm", &P::sphere_radius_mm, 1.0, Sign::kPositive, false, false,
                                       nullptr, "*required* (spherical_cap)"}})},
      {PadShape::kCone,
       with({{"half_angle_deg", &P::half_angle_deg, 1.0, Sign::kPositive, false, false, nullptr, "*required* (cone)"}})},
      {PadShape::kTable, with({})},
  };
  const auto it = tables.find(shape);
  return it == tables.end() ? nullptr : &it->second;
}

bool HasSegments(PadShape shape) { return shape == PadShape::kExponential || shape == PadShape::kSphericalCap; }

// A profile block's keys for its shape, in the order WritePad writes them.
KeyTable<PadFileFields> ProfileKeys(PadShape shape) {
  using P = PadFileFields;
  using Y = YAML::Emitter;
  KeyTable<P> k{{"shape", Always<P>, [](Y& y, const P& p) { y << PadShapeName(*p.shape); }}};
  AppendNumberKeys(k, *ProfileFields(shape));
  if (HasSegments(shape))
    k.push_back({"segments", [](const P& p) { return p.segments > 0; }, [](Y& y, const P& p) { y << p.segments; }});
  if (shape == PadShape::kTable)
    k.push_back({"points_mm", Always<P>, [](Y& y, const P& p) {
                   y << YAML::BeginSeq;
                   for (const std::array<double, 2>& q : p.points_mm)
                     y << YAML::Flow << YAML::BeginSeq << q[0] << q[1] << YAML::EndSeq;
                   y << YAML::EndSeq;
                 }});
  return k;
}

geom::AxisymmetricProfile ReadProfile(const YamlFields& f, PadFileFields& file) {
  const std::string shape_name = f.String("shape");
  file.shape = ParsePadShape(shape_name);
  if (!file.shape)
    f.Fail("shape", "unknown shape '" + shape_name + "' (flat, chamfer, exponential, spherical_cap, cone, table)");
  const PadShape shape = *file.shape;
  const FieldTable<PadFileFields>* fields = ProfileFields(shape);
  f.RequireOnly(Keys(ProfileKeys(shape)));
  ReadFields(f, *fields, file);
  const double r = file.radius_mm * kMm;
  const double h = file.thickness_mm * kMm;
  if (f.Has("segments")) file.segments = f.PositiveInt("segments");
  const int segments = file.segments > 0 ? file.segments : 400;
  if (segments > kMaxProfileSegments)
    f.Fail("segments", "must be at most " + std::to_string(kMaxProfileSegments) + ", got " + std::to_string(segments));
  if (shape == PadShape::kFlat) return Guarded(f, [&] { return geom::MakeFlatProfile(r, h); });
  if (shape == PadShape::kChamfer) {
    const double c = file.chamfer_mm * kMm;
    return Guarded(f, [&] { return geom::MakeChamferProfile(r, h, c); });
  }
  if (shape == PadShape::kExponential) {
    const double a1 = file.a1_per_mm / kMm;
    if (f.Has("a0_mm") == f.Has("rim_height_mm")) f.Fail("a0_mm", "give exactly one of a0_mm and rim_height_mm");
    const double a0 = f.Has("a0_mm") ? file.a0_mm * kMm : file.rim_height_mm * kMm / std::expm1(a1 * r);
    return Guarded(f, [&] { return geom::MakeExponentialProfile(r, h, a0, a1, segments); });
  }
  if (shape == PadShape::kSphericalCap) {
    const double R = file.sphere_radius_mm * kMm;
    return Guarded(f, [&] { return geom::MakeSphericalCapProfile(r, h, R, segments); });
  }
  if (shape == PadShape::kCone) {
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

// A pad file's numbers read on their own (their defaults differ by pad kind: the reference states them).
const NumberKey kPadMass{"mass_kg", Sign::kPositive, &limits::kMass_kg, ""};
const NumberKey kPadDensity{"density_kg_m3", Sign::kPositive, &limits::kDensity_kg_m3, ""};
const NumberKey kRemeshEdge{"remesh_edge_mm", Sign::kPositive, nullptr, "none"};

double Mass(const YamlFields& f) { return ReadNumber(f, kPadMass); }

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
  pad.file.mass_kg = Mass(f);
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
       [](Y& y, const W& w) { y << w.pad.file.remesh_edge_mm; }, DocOf(kRemeshEdge)},
  };
  return keys;
}

// An inertia block's moments (ixx, iyy, izz: required) and products (ixy, ixz, iyz: 0 when absent).
const NumberKey kMoment{"ixx", Sign::kPositive, &limits::kInertia_kg_m2};
const NumberKey kProduct{"ixy", Sign::kAny, nullptr, nullptr, 0.0};

// An inertia block's keys (ixx, iyy, izz, ixy, ixz, iyz), as a pad file and a lander file give it.
const KeyTable<std::array<double, 6>>& InertiaKeys() {
  using I = std::array<double, 6>;
  const auto entry = [](const char* key, int k) -> FileKey<I> {
    NumberKey number = k < 3 ? kMoment : kProduct;
    number.key = key;
    return {key, Always<I>, [k](YAML::Emitter& y, const I& i) { y << i[k]; }, DocOf(number)};
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
      {"mass_kg", [](const W& w) { return w.pad.file.mass_kg > 0.0; }, [](Y& y, const W& w) { y << w.pad.file.mass_kg; },
       DocOf(kPadMass)},
      {"density_kg_m3", [](const W& w) { return w.pad.file.density_kg_m3 > 0.0; },
       [](Y& y, const W& w) { y << w.pad.file.density_kg_m3; }, DocOf(kPadDensity)},
      {"profile", axisymmetric,
       [](Y& y, const W& w) {
         WriteMap(y, ProfileKeys(*w.pad.file.shape), w.pad.file);
       }},
      {"mesh", [=](const W& w) { return !axisymmetric(w); },
       [](Y& y, const W& w) {
         WriteMap(y, MeshKeys(), w);
       }},
      {"angular_segments", [=](const W& w) { return axisymmetric(w) && w.pad.file.angular_segments > 0; },
       [](Y& y, const W& w) { y << w.pad.file.angular_segments; }},
      {"reference_point_mm", [](const W& w) { return w.pad.file.reference_point_mm.has_value(); },
       [](Y& y, const W& w) { WritePoint(y, *w.pad.file.reference_point_mm); }},
      {"inertia_kg_m2", [](const W& w) { return w.pad.file.inertia_kg_m2.has_value(); },
       [](Y& y, const W& w) {
         WriteMap(y, InertiaKeys(), *w.pad.file.inertia_kg_m2, YAML::Flow);
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
    pad.file.remesh_edge_mm = ReadNumber(m, kRemeshEdge);
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
  if (f.Has("mass_kg")) mass.mass_kg = pad.file.mass_kg = Mass(f);
  if (f.Has("density_kg_m3")) mass.density_kg_m3 = pad.file.density_kg_m3 = ReadNumber(f, kPadDensity);
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
  const auto moment = [&](const char* key) { return ReadNumber(i, {key, kMoment.sign, kMoment.range}); };
  const auto product = [&](const char* key) { return ReadNumberOr(i, {key, kProduct.sign}, kProduct.default_value); };
  Eigen::Matrix3d m;
  m << moment("ixx"), product("ixy"), product("ixz"),  //
      product("ixy"), moment("iyy"), product("iyz"),   //
      product("ixz"), product("iyz"), moment("izz");
  geom::ValidateInertia(m, i.file(), i.prefix());
  return m;
}

PadSpec LoadPad(const std::string& name_or_path) {
  return LoadPad(YamlFields::LoadFile(ResolveCatalogFile("pads", name_or_path)));
}

int PadRimSegments(const PadSpec& pad) {
  if (!pad.is_axisymmetric()) return 0;
  return pad.file.angular_segments > 0 ? pad.file.angular_segments : geom::kDefaultAngularSegments;
}

namespace {
// The pad's file as a YAML node made from what the pad holds (WritePad's fields; a mesh path
// relative to its own file), so a variant of a resolved pad is re-made from memory, never by
// reading its file again (which may have changed, or never existed for a pad built in memory).
YAML::Node PadNode(const PadSpec& pad) {
  YAML::Emitter y;
  WriteMap(y, PadKeys(), PadToWrite{pad, pad.source});
  return YAML::Load(y.c_str());
}
}  // namespace

PadSpec FlatPadWithRadius(const PadSpec& pad, double radius_mm, geom::RimPolygon rim) {
  if (pad.file.shape != PadShape::kFlat)
    throw MakeInputError(pad.source, "profile.shape", "pad '" + pad.name + "' is not a flat revolved profile");
  YAML::Node node = PadNode(pad);
  node["profile"]["radius_mm"] = radius_mm;
  return LoadPad(YamlFields(node, pad.source, ""), rim);
}

PadSpec PadWithAngularSegments(const PadSpec& pad, int angular_segments, geom::RimPolygon rim) {
  if (!pad.is_axisymmetric())
    throw MakeInputError(pad.source, "angular_segments", "pad '" + pad.name + "' is a mesh, not a revolved profile");
  YAML::Node node = PadNode(pad);
  node["angular_segments"] = angular_segments;
  return LoadPad(YamlFields(node, pad.source, ""), rim);
}

PadSpec LoadPad(const YamlFields& f, geom::RimPolygon rim) {
  f.RequireSchemaVersion(1);
  PadSpec pad;
  pad.rim = rim;
  pad.source = f.file();
  const std::string kind = f.StringOr("kind", "axisymmetric");
  pad.name = f.Name("name", fs::path(f.file()).stem().string());
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

void WritePad(const PadSpec& pad, const std::string& path) {
  YAML::Emitter y;
  WriteMap(y, PadKeys(), PadToWrite{pad, path});
  WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

std::vector<BlockDoc> PadFileSchema() {
  const std::string read_by = "drop_tests/catalog/pad_file.cpp";
  std::vector<KeyDoc> profile;
  for (PadShape shape : {PadShape::kFlat, PadShape::kChamfer, PadShape::kExponential, PadShape::kSphericalCap,
                         PadShape::kCone, PadShape::kTable})
    for (const KeyDoc& k : DocsOf(ProfileKeys(shape)))
      if (std::none_of(profile.begin(), profile.end(), [&](const KeyDoc& p) { return p.key == k.key; }))
        profile.push_back(k);
  return {MakeBlock("pad", read_by, DocsOf(PadKeys(), {"mesh", "density_kg_m3"})),
          MakeBlock("pad.profile", read_by, profile),
          MakeBlock("pad.mesh_kind", read_by, DocsOf(PadKeys(), {"profile", "angular_segments"})),
          MakeBlock("pad.mesh", read_by, DocsOf(MeshKeys())),
          MakeBlock("pad.inertia_kg_m2", read_by, DocsOf(InertiaKeys()))};
}

}  // namespace touchdown::io

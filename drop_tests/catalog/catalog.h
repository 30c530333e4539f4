#pragma once
// The pads and soils a user names on the command line: a name from the bundled data/
// directory (`flat`, `fjs1_lp`) or a path to a YAML file. Loading validates everything,
// so the physics never sees a bad number.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "drop_tests/formats/schema_doc.h"
#include "footpad_geom/axisymmetric_profile.h"
#include "footpad_geom/pad_body.h"
#include "footpad_geom/revolve.h"
#include <iosfwd>

#include "rft/physical_limits.h"
#include "rft/soil.h"
#include "rft/enum_names.h"

namespace touchdown::io {

class YamlFields;

// A pad is `kind: axisymmetric` (a profile, data/pads/flat.yaml) or `kind: mesh` (a mesh file,
// data/pads/hex.yaml). Every pad gets its rigid body: an axisymmetric pad is revolved
// (`angular_segments` around the rim, default geom::kDefaultAngularSegments). The pad frame B
// has its origin at `reference_point_mm`, in the pad's own coordinates; its default is the top
// centre (the rod attachment of the paper's rig): (0, 0, h) above an axisymmetric pad's lowest
// point, the top centre of the bounding box of a mesh. Mass: `mass_kg`, or for a mesh
// `density_kg_m3`; inertia and centre of mass of the uniform solid unless `inertia_kg_m2`
// {ixx, iyy, izz, ixy, ixz, iyz} (about the centre of mass, the tensor's own entries, so ixy =
// -integral of x y dm) and optionally `center_of_mass_mm` are given.
enum class PadKind { kAxisymmetric, kMesh };  // `kind: axisymmetric` or `kind: mesh`

// A revolved pad's `profile.shape`. The names table is the one place its file names live.
enum class PadShape { kFlat, kChamfer, kExponential, kSphericalCap, kCone, kTable };
inline constexpr std::array<EnumName<PadShape>, 6> kPadShapeNames{{{PadShape::kFlat, "flat"},
                                                                                {PadShape::kChamfer, "chamfer"},
                                                                                {PadShape::kExponential, "exponential"},
                                                                                {PadShape::kSphericalCap, "spherical_cap"},
                                                                                {PadShape::kCone, "cone"},
                                                                                {PadShape::kTable, "table"}}};
const char* PadShapeName(PadShape shape);
std::optional<PadShape> ParsePadShape(const std::string& name);

// What a pad file says, in its own units, kept with the pad so WritePad writes a file LoadPad
// reads back to the same pad. A 0 (or an empty optional) is a field the file leaves out.
struct PadFileFields {
  std::string description;
  double mass_kg = 0.0;
  double density_kg_m3 = 0.0;  // a mesh pad's alternative to mass_kg
  // An axisymmetric pad's `profile` (the shape's own parameters) and `angular_segments`.
  std::optional<PadShape> shape;  // empty for a mesh pad
  double radius_mm = 0.0, thickness_mm = 0.0, chamfer_mm = 0.0, a0_mm = 0.0, rim_height_mm = 0.0, a1_per_mm = 0.0,
         sphere_radius_mm = 0.0, half_angle_deg = 0.0;
  int segments = 0;
  std::vector<std::array<double, 2>> points_mm;  // shape: table
  int angular_segments = 0;
  // A mesh pad's `mesh` (the file as resolved; written relative to the pad file).
  std::string mesh_unit;
  double remesh_edge_mm = 0.0;
  std::optional<std::array<double, 3>> reference_point_mm;
  std::optional<std::array<double, 6>> inertia_kg_m2;  // ixx, iyy, izz, ixy, ixz, iyz
  std::optional<std::array<double, 3>> center_of_mass_mm;
};

struct PadSpec {
  std::string name;
  std::string source;  // the YAML file it came from
  PadKind kind = PadKind::kAxisymmetric;
  // The exact generator curve, for the rig drop's profile integral; no points for a mesh pad.
  geom::AxisymmetricProfile profile;
  double mass_kg = 0.0;
  geom::PadBody body;  // every pad, in its pad frame B
  std::string mesh_file;  // a mesh pad's mesh, resolved path
  PadFileFields file;     // what the YAML file says (WritePad)
  // How a revolved pad's rings stand for their circles: inscribed as a pad file meshes it; area
  // preserving only as a scenario's simulation.pad_rim re-meshes it (not a pad-file field).
  geom::RimPolygon rim = geom::RimPolygon::kInscribed;

  bool is_axisymmetric() const { return !profile.points.empty(); }
};

// data/ of this build, or $TOUCHDOWN_DATA_DIR when set.
std::string DataDirectory();
// `kind` is a data/ subfolder ("pads", "soils", "scenarios"). A name with a '/' or a
// ".yaml"/".yml" ending is a path; otherwise data/<kind>/<name>.yaml.
std::string ResolveCatalogFile(const std::string& kind, const std::string& name_or_path);
// As ResolveCatalogFile, but a relative path is first looked for beside `referring_file` (the file
// that names it), so a scenario's or targets file's own files travel with it.
std::string ResolveCatalogFileNear(const std::string& referring_file, const std::string& kind,
                                   const std::string& name_or_path);
// The names data/<kind>/ holds (its .yaml files without the ending), sorted.
std::vector<std::string> CatalogNames(const std::string& kind);

// The input file a command runs (a campaign, a lander scenario, a sweep, a study) is a path or
// the name of a bundled one, as pads and soils are. A shelf is where such names live: the files
// of data/<kind>/ whose `type:` is `type` (data/studies holds both studies and the lander
// scenarios they start from; only the studies are study names).
struct CatalogShelf {
  std::string kind;   // the data/ subfolder
  std::string type;   // the files' `type:` field
  std::string label;  // what they are, in words ("lander scenarios")
};
enum class InputDocument {
  kCampaign,  // campaign: campaign scenarios
  kLander,    // lander: lander scenarios
  kSweep,     // sweep: sweeps and stability studies (a study is a lander sweep)
  kTrade,     // trade: sweeps
  kStudy,     // stability: stability studies
};
// Where a command's input is looked for by name, in order.
std::vector<CatalogShelf> ShelvesOf(InputDocument document);
// The names on a shelf (data/<kind>/*.yaml of its type, without the ending), sorted.
std::vector<std::string> ShelfNames(const CatalogShelf& shelf);
// The file a command reads: `name_or_path` itself when a file of that name exists or it reads as
// a path ('/' in it, a .yaml/.yml ending: the loader then says what is wrong with it); otherwise
// the bundled file of that name on the first of `document`'s shelves holding it. InputError
// naming it, the nearest bundled name and the known ones when it is neither.
std::string ResolveInputDocument(InputDocument document, const std::string& name_or_path);

PadSpec LoadPad(const std::string& name_or_path);
// The reference of a pad file's and a soil file's keys, from the tables their loaders read with
// (schema_doc.h; `touchdown schema`, docs/reference.md).
std::vector<BlockDoc> PadFileSchema();
std::vector<BlockDoc> SoilFileSchema();
// Bekker's pressure-sinkage parameters as a soil file's `bekker` block gives them (n, k_c_kN_m_n1,
// k_phi_kN_m_n2): one table, which the soil file and a model file's per-soil override both read
// with (the key, the factor from file units to SI, the range in file units, the member set).
struct BekkerFileField {
  const char* key;
  double file_to_si;
  const limits::Range* range;
  double rft::BekkerParameters::*member;
};
const std::array<BekkerFileField, 3>& BekkerPressureSinkageFields();
// A pad from its file's YAML as read (YamlFields::LoadFile of the resolved file), possibly edited in
// memory first (calibrate --targets changes a profile constant without touching the file); a
// revolved pad's rings `rim` (a mesh pad ignores it).
PadSpec LoadPad(const YamlFields& f, geom::RimPolygon rim = geom::RimPolygon::kInscribed);

// An inertia tensor block {ixx, iyy, izz, ixy, ixz, iyz} [kg m^2], products 0 when absent: the
// moments within limits::kInertia_kg_m2 and the tensor a rigid body's (geom::ValidateInertia:
// positive definite, I1 + I2 >= I3). A pad's inertia_kg_m2 and a lander's body_inertia_kg_m2.
Eigen::Matrix3d ReadInertia(const YamlFields& block);
// An axisymmetric pad revolved at another number of rim segments: the pad's own file fields
// (pad.file, in memory; its file is not read again) with `angular_segments` replaced, its rings'
// polygons `rim`.
// InputError naming the pad file for a mesh pad or a count outside the range LoadPad accepts.
PadSpec PadWithAngularSegments(const PadSpec& pad, int angular_segments,
                               geom::RimPolygon rim = geom::RimPolygon::kInscribed);
// A flat revolved pad at another radius: the pad's own file fields (in memory) with
// profile.radius_mm replaced, its rings' polygons `rim`. InputError naming the pad file for
// a pad whose profile is not `shape: flat`.
PadSpec FlatPadWithRadius(const PadSpec& pad, double radius_mm, geom::RimPolygon rim = geom::RimPolygon::kInscribed);
// The rim segments a revolved pad is meshed at (its file's angular_segments, or the default); 0 for
// a mesh pad.
int PadRimSegments(const PadSpec& pad);
// A pad file that LoadPad reads back to the same pad (from pad.file; a mesh by its resolved path,
// relative to `path`'s directory).
void WritePad(const PadSpec& pad, const std::string& path);
rft::SoilParameters LoadSoil(const std::string& name_or_path);
// A soil file that LoadSoil reads back to the same soil (zeta as a number, in N/cm^3).
void WriteSoil(const rft::SoilParameters& soil, const std::string& path);
// The same text to a stream (an output file another command writes: calibrate --law bekker).
void WriteSoil(const rft::SoilParameters& soil, std::ostream& out);

}  // namespace touchdown::io

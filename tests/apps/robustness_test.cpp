// The robustness table: every bad input we know of, and a few extreme but legal ones,
// run through the touchdown executable exactly as a user would; docs/robustness.md is the
// rendered table. The test fails when a case crashes (a signal), exits with a status other
// than 0 (ran), 2 (input refused) or 3 (integration failed), prints more than one line on a
// refusal, or when the rendered table differs from docs/robustness.md.
//
// To regenerate the document after a deliberate change (a new case, a reworded message):
//   TOUCHDOWN_UPDATE_DOCS=1 build/tests/apps_hardening_tests --gtest_filter=Robustness.*
// Outputs are normalised so the table is the same on every machine and in every build
// (sanitizers included): the cases run in a scratch directory with relative paths, the data
// directory prints as DATA, and numbers are rounded to three significant digits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sqlite3.h>
#include <sys/stat.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "tests/apps/robustness_cli.h"

namespace touchdown::testing_cli {
namespace {

struct Case {
  std::string input;   // which input the case is about
  std::string what;    // the case, in a few words
  std::string args;    // touchdown arguments, run in the scratch directory
  std::vector<std::pair<std::string, std::string>> files = {};  // written there first
  // Anything files cannot hold (a symlink, a FIFO, a directory, a database), made in the
  // scratch directory before the run.
  std::function<void(const fs::path& dir)> setup = {};
};

// ---- inputs -------------------------------------------------------------------------------

const std::string kFlatProfile = "profile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n";

std::string Pad(const std::string& body) { return "schema_version: 1\nmass_kg: 1.6\n" + body; }

// A 10 x 10 x 5 mm box, as OFF (quads), with optional extra faces or an offset copy.
std::string BoxOff(bool inverted = false, bool second_box = false) {
  std::string v = "0 0 0\n10 0 0\n10 10 0\n0 10 0\n0 0 5\n10 0 5\n10 10 5\n0 10 5\n";
  std::vector<std::string> quads = {"0 3 2 1", "4 5 6 7", "0 1 5 4", "1 2 6 5", "2 3 7 6", "3 0 4 7"};
  if (inverted)
    quads = {"1 2 3 0", "7 6 5 4", "4 5 1 0", "5 6 2 1", "6 7 3 2", "7 4 0 3"};
  int nv = 8, nf = 6;
  std::string f;
  for (const std::string& q : quads) f += "4 " + q + "\n";
  if (second_box) {  // the same box shifted by (5, 5, 2): the two intersect
    v += "5 5 2\n15 5 2\n15 15 2\n5 15 2\n5 5 7\n15 5 7\n15 15 7\n5 15 7\n";
    for (const std::string& q : quads) {
      int a, b, c, d;
      std::sscanf(q.c_str(), "%d %d %d %d", &a, &b, &c, &d);
      f += "4 " + std::to_string(a + 8) + " " + std::to_string(b + 8) + " " + std::to_string(c + 8) + " " +
           std::to_string(d + 8) + "\n";
    }
    nv = 16;
    nf = 12;
  }
  return "OFF\n" + std::to_string(nv) + " " + std::to_string(nf) + " 0\n" + v + f;
}

std::string MeshPad(const std::string& file, const std::string& extra = "") {
  return "schema_version: 1\nkind: mesh\nmesh: {file: " + file + ", unit: mm" + extra + "}\nmass_kg: 0.5\n";
}

// An ASCII STL of the box with its last facet left out.
std::string OpenBoxStl() {
  const double v[8][3] = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 5}, {10, 0, 5}, {10, 10, 5}, {0, 10, 5}};
  const int t[11][3] = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}};
  std::string s = "solid open\n";
  for (const auto& tri : t) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (int i : tri) {
      char line[96];
      std::snprintf(line, sizeof line, "vertex %g %g %g\n", v[i][0], v[i][1], v[i][2]);
      s += line;
    }
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid open\n";
}

// A binary STL: one facet whose first coordinate is NaN.
std::string NanStl() {
  std::string b(80, ' ');
  const uint32_t n = 1;
  b.append(reinterpret_cast<const char*>(&n), 4);
  const float values[12] = {0, 0, 0, std::nanf(""), 0, 0, 1, 0, 0, 0, 1, 0};
  b.append(reinterpret_cast<const char*>(values), sizeof values);
  b.append(2, '\0');  // the attribute byte count
  return b;
}

const std::string kHugeListPly =
    std::string("ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n") +
    std::string("\xff\xff\xff\x7f", 4);

std::string Soil(const std::string& body) { return "schema_version: 1\nname: test_soil\n" + body; }

std::string Sweep(const std::string& body) { return "schema_version: 1\ntype: sweep\n" + body; }
const std::string kSweepBase = "fixed: {pad: flat, soil: fjs1_lp}\n";

std::string Lander(const std::string& body) { return "schema_version: 1\ntype: lander\n" + body; }
const std::string kLanderGround = "ground: {soil: fjs1_lp}\n";
const std::string kLanderInitial = "initial: {drop_height_m: 0.1}\n";

std::string Model(const std::string& body) { return "schema_version: 1\ntype: model\n" + body; }

const std::string kDropsHeader = "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace\n";
const std::string kGoodTrace = "t_s,penetration_m,force_N\n0,0,0\n0.001,0.0005,30\n0.002,0.0009,60\n0.003,0.001,20\n";

// A dataset directory `name` with drops.csv `drops` and trace t.csv `trace`.
std::vector<std::pair<std::string, std::string>> Dataset(const std::string& name, const std::string& drops,
                                                         const std::string& trace = kGoodTrace) {
  return {{name + "/drops.csv", drops}, {name + "/t.csv", trace}};
}

std::string Calibrate(const std::string& name) { return "calibrate " + name + " --param zeta --out " + name + ".yaml"; }

// ---- Exit statuses with clear errors, and inputs that would be accepted but wrong ----

// A results database whose meta table holds `version` as its format.
void MakeResultsDb(const fs::path& path, const std::string& version) {
  fs::create_directories(path.parent_path());
  sqlite3* db = nullptr;
  sqlite3_open(path.string().c_str(), &db);
  const std::string sql = "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
                          "INSERT INTO meta VALUES('format_version', '" + version + "');";
  sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
  sqlite3_close(db);
}

// Two closed boxes as one OFF mesh: the 10 x 10 x 5 mm box of BoxOff() and a second box whose
// eight corners (in BoxOff()'s order) are `second`.
std::string TwoBoxesOff(const std::string& second) {
  const std::string v = "0 0 0\n10 0 0\n10 10 0\n0 10 0\n0 0 5\n10 0 5\n10 10 5\n0 10 5\n" + second;
  const std::vector<std::string> quads = {"0 3 2 1", "4 5 6 7", "0 1 5 4", "1 2 6 5", "2 3 7 6", "3 0 4 7"};
  std::string f;
  for (int offset : {0, 8})
    for (const std::string& q : quads) {
      int a, b, c, d;
      std::sscanf(q.c_str(), "%d %d %d %d", &a, &b, &c, &d);
      f += "4 " + std::to_string(a + offset) + " " + std::to_string(b + offset) + " " + std::to_string(c + offset) +
           " " + std::to_string(d + offset) + "\n";
    }
  return "OFF\n16 12 0\n" + v + f;
}

// The box of BoxOff() with a second, smaller closed box inside it.
std::string NestedBoxOff() { return TwoBoxesOff("2 2 1\n8 2 1\n8 8 1\n2 8 1\n2 2 4\n8 2 4\n8 8 4\n2 8 4\n"); }

std::string with_soil_cmd() { return "drop --pad flat --speed 1 --soil "; }
std::string rig_cmd() { return "drop --pad flat --soil fjs1_lp "; }

void AddExitStatusAndInputCases(std::vector<Case>& c) {
  const std::string force = " --soil fjs1_lp --depth 0.002";
  const std::string good_pad = Pad(kFlatProfile);
  // Section 3: an input path that is not a readable file says what it is.
  c.push_back({"input path", "pad file is a symlink loop", "drop --pad loop.yaml --soil fjs1_lp --speed 1", {},
               [](const fs::path& d) { fs::create_symlink("loop.yaml", d / "loop.yaml"); }});
  c.push_back({"input path", "pad file is a directory", "drop --pad pad_dir.yaml --soil fjs1_lp --speed 1", {},
               [](const fs::path& d) { fs::create_directories(d / "pad_dir.yaml"); }});
  c.push_back({"input path", "pad file is a FIFO", "drop --pad pipe.yaml --soil fjs1_lp --speed 1", {},
               [](const fs::path& d) { ::mkfifo((d / "pipe.yaml").c_str(), 0600); }});
  c.push_back({"input path", "pad file is a device", "drop --pad /dev/null --soil fjs1_lp --speed 1"});
  c.push_back({"input path", "mesh file is a directory", "force --pad mesh_dir.yaml" + force,
               {{"mesh_dir.yaml", MeshPad("dir.stl")}}, [](const fs::path& d) { fs::create_directories(d / "dir.stl"); }});
  c.push_back({"input path", "results.sqlite is corrupt", "export corrupt_db --to out_x1",
               {{"corrupt_db/results.sqlite", std::string(4096, 'x')}}});
  c.push_back({"input path", "results.sqlite is a directory", "export dir_db --to out_x2", {},
               [](const fs::path& d) { fs::create_directories(d / "dir_db" / "results.sqlite"); }});
  c.push_back({"sweep results", "unknown format_version", "export future_db --to out_x3", {},
               [](const fs::path& d) { MakeResultsDb(d / "future_db" / "results.sqlite", "99"); }});
  // Section 3: text that is not UTF-8, ids that cannot name files.
  c.push_back({"pad YAML", "name with a byte that is not UTF-8", "drop --pad latin1.yaml --soil fjs1_lp --speed 1",
               {{"latin1.yaml", "name: \"pad\xe9\"\n" + good_pad}}});
  c.push_back({"dataset CSV", "drop_id with a '/'", Calibrate("ds_slash"),
               Dataset("ds_slash", kDropsHeader + "a/b,flat,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n")});
  c.push_back({"dataset CSV", "drop_id with a byte that is not UTF-8", Calibrate("ds_latin1"),
               Dataset("ds_latin1", kDropsHeader + "d\xe9,flat,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n")});
  // Section 3: messages that named the wrong problem.
  c.push_back({"pad YAML", "radius_mm 1e300", "drop --pad huge_radius.yaml --soil fjs1_lp --speed 1",
               {{"huge_radius.yaml", Pad("profile: {shape: flat, radius_mm: 1e300, thickness_mm: 16}\n")}}});
  c.push_back({"sweep YAML", "random samples 2^40 - 1", "sweep samples.yaml --threads 1 --progress lines --out out_s13",
               {{"samples.yaml", Sweep(kSweepBase + "random: {samples: 1099511627775, seed: 1, "
                                                   "impact_speed_m_s: {uniform: [0.5, 2]}}\n")}}});
  c.push_back({"scenario YAML", "speeds 1.0 and 1.004 (distinct drops)", "campaign close_speeds.yaml --out out_c13",
               {{"close_speeds.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [1.0, 1.004]}\n"}}});
  c.push_back({"scenario YAML", "speed 1.0 listed twice", "campaign same_speed.yaml --out out_c14",
               {{"same_speed.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [1.0, 1]}\n"}}});
  c.push_back({"CLI flag", "sweep --batch 0", "sweep soft.yaml --batch 0 --out out_f13"});
  // Section 4: duplicate keys, in any YAML file.
  c.push_back({"pad YAML", "mass_kg given twice", "drop --pad dup_mass.yaml --soil fjs1_lp --speed 1",
               {{"dup_mass.yaml", good_pad + "mass_kg: 2.0\n"}}});
  c.push_back({"sweep YAML", "grid block given twice", "sweep dup_grid.yaml --threads 1 --progress lines --out out_s14",
               {{"dup_grid.yaml", Sweep(kSweepBase + "grid: {impact_speed_m_s: [1]}\ngrid: {pad_mass_kg: [1, 2]}\n")}}});
  c.push_back({"soil YAML", "duplicate key in a nested mapping", with_soil_cmd() + "dup_nested.yaml",
               {{"dup_nested.yaml", Soil("zeta_N_cm3: 3\nprovenance: {source: a, source: b}\n")}}});
  // Section 4: physically meaningless magnitudes, refused with the valid range.
  const std::string rig = "drop --pad flat --soil fjs1_lp ";
  c.push_back({"CLI flag", "drop --speed 1e308", rig + "--speed 1e308"});
  c.push_back({"CLI flag", "drop --speed 1e200", rig + "--speed 1e200"});
  c.push_back({"CLI flag", "drop --free --tilt-deg 1e308", rig + "--speed 1 --free --tilt-deg 1e308"});
  c.push_back({"CLI flag", "drop --free --omega 1e300,0,0", rig + "--speed 1 --free --omega 1e300,0,0"});
  c.push_back({"CLI flag", "drop --fast without --free", rig + "--speed 1 --fast"});
  c.push_back({"CLI flag", "drop --free --fast on a mesh pad", "drop --pad hex --soil fjs1_lp --speed 1 --free --fast"});
  c.push_back({"CLI flag", "force --depth 1e308", "force --pad flat --soil fjs1_lp --depth 1e308"});
  c.push_back({"CLI flag", "force --tilt-deg 1e308", "force --pad flat --soil fjs1_lp --depth 0.005 --tilt-deg 1e308"});
  c.push_back({"CLI flag", "force --omega 1e300,0,0", "force --pad flat --soil fjs1_lp --depth 0.005 --omega 1e300,0,0"});
  c.push_back({"CLI flag", "force --velocity 1e200,0,-1e200",
               "force --pad flat --soil fjs1_lp --depth 0.005 --velocity 1e200,0,-1e200"});
  c.push_back({"soil YAML", "zeta 1e308 N/cm^3", with_soil_cmd() + "zeta_huge.yaml",
               {{"zeta_huge.yaml", Soil("zeta_N_cm3: 1e308\n")}}});
  c.push_back({"mesh", "coordinates of 1e30 mm", "force --pad far_mesh.yaml" + force,
               {{"far_mesh.yaml", MeshPad("far.obj")},
                {"far.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nv 0 0 1e30\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"}}});
  c.push_back({"mesh", "a box inside a box (nested shells)", "force --pad nested.yaml" + force,
               {{"nested.yaml", MeshPad("nested.off")}, {"nested.off", NestedBoxOff()}}});
  c.push_back({"extreme", "force at the limits (100 m/s, 1000 rad/s, 10 m deep, tilt 180 deg)",
               "force --pad flat --soil fjs1_lp --depth 10 --tilt-deg 180 --velocity 60,0,-80 --omega 0,0,1000"});
  // Section 4: every magnitude a lander, study, drop, soil or pad takes has one range
  // (rft/physical_limits.h), refused at load with it wherever it is given.
  {
    const std::string body = "schema_version: 1\ncog_height_mm: 230\npad: flat\n";
    const std::string inertia = "body_inertia_kg_m2: {ixx: 0.05, iyy: 0.05, izz: 0.06}\n";
    const std::string legs = "legs: {joint_radius_mm: 300, hip_radius_mm: 120, hip_height_mm: 200";
    const std::string mass = "total_mass_kg: 20\n";
    const auto lander = [&](const std::string& name, const std::string& what, const std::string& file,
                            std::vector<std::pair<std::string, std::string>> files = {}) {
      files.push_back({name + "_lander.yaml", file});
      files.push_back({name + ".yaml", Lander("lander: " + name + "_lander.yaml\n" + kLanderGround + kLanderInitial)});
      c.push_back({"lander YAML", what, "lander " + name + ".yaml --out out_" + name, files});
    };
    lander("pr_mass", "total_mass_kg 1e30", body + "total_mass_kg: 1e30\n" + inertia + legs + "}\n");
    lander("pr_cog", "cog_height_mm 1e9", "schema_version: 1\ncog_height_mm: 1e9\npad: flat\n" + mass + inertia + legs + "}\n");
    lander("pr_joint", "joint_radius_mm 1e12",
           body + mass + inertia + "legs: {joint_radius_mm: 1e12, hip_radius_mm: 120, hip_height_mm: 200}\n");
    lander("pr_inertia", "body inertia ixx 1e30 kg m^2 (ran for minutes)",
           body + mass + "body_inertia_kg_m2: {ixx: 1e30, iyy: 0.05, izz: 0.06}\n" + legs + "}\n");
    lander("pr_triangle", "body inertia breaking I1 + I2 >= I3 (0.01, 0.01, 0.06)",
           body + mass + "body_inertia_kg_m2: {ixx: 0.01, iyy: 0.01, izz: 0.06}\n" + legs + "}\n");
    lander("pr_cone", "cone_limit half_angle_deg 500",
           body + mass + inertia + legs + ", cone_limit: {half_angle_deg: 500, stiffness_N_m_rad: 10}}\n");
    lander("pr_stiff", "absorber stiffness_N_m 1e300",
           body + mass + inertia + legs + ", absorber: {kind: spring_damper, stiffness_N_m: 1e300}}\n");
    lander("pr_damp", "absorber damping_N_s_m 1e300",
           body + mass + inertia + legs + ", absorber: {kind: spring_damper, stiffness_N_m: 1e4, damping_N_s_m: 1e300}}\n");
    const auto scenario = [&](const std::string& name, const std::string& what, const std::string& file) {
      c.push_back({"lander YAML", what, "lander " + name + ".yaml --out out_" + name, {{name + ".yaml", Lander(file)}}});
    };
    const std::string shipped = "lander: sutoh2017_lander\n";
    scenario("pr_vh", "horizontal_velocity_m_s [1e10, 0]",
             shipped + kLanderGround + "initial: {drop_height_m: 0.1, horizontal_velocity_m_s: [1e10, 0]}\n");
    scenario("pr_rate", "angular_rate_deg_s [1e10, 0, 0]",
             shipped + kLanderGround + "initial: {drop_height_m: 0.1, angular_rate_deg_s: [1e10, 0, 0]}\n");
    scenario("pr_g", "gravity_m_s2 1e12", shipped + "gravity_m_s2: 1e12\n" + kLanderGround + kLanderInitial);
    scenario("pr_height", "ground height_m 1e300 (ran, another answer)",
             shipped + "ground: {soil: fjs1_lp, height_m: 1e300}\n" + kLanderInitial);
    const std::string study = "schema_version: 1\ntype: stability\nlander: {scenario: lander_case_A}\n";
    c.push_back({"study YAML", "gravity 1e6 m/s^2", "stability pr_gs.yaml --out out_pr_gs",
                 {{"pr_gs.yaml", study + "grid: {gravity_m_s2: [1.62, 1e6]}\n"}}});
    const std::string sampled = study + "random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 5]}}\n";
    c.push_back({"CLI flag", "stability --samples 1e12 (the study file's bound is 1e9)",
                 "stability pr_s.yaml --samples 1e12 --out out_pr_s1", {{"pr_s.yaml", sampled}}});
    c.push_back({"CLI flag", "stability --samples abc", "stability pr_s.yaml --samples abc --out out_pr_s2",
                 {{"pr_s.yaml", sampled}}});
    c.push_back({"CLI flag", "drop --gravity 1e300", rig + "--speed 1 --gravity 1e300"});
    c.push_back({"CLI flag", "drop --law li2013 on a Bekker soil without zeta",
                 "drop --pad flat --soil lunar_nominal_bekker --speed 1 --law li2013"});
    c.push_back({"CLI flag", "drop --zeta 5 on a soil running on the bekker law",
                 "drop --pad flat --soil lunar_nominal_bekker --speed 1 --zeta 5"});
    c.push_back({"soil YAML", "bekker k_phi 1e300", with_soil_cmd() + "pr_kphi.yaml",
                 {{"pr_kphi.yaml", Soil("law: bekker\nbekker: {n: 1, k_c_kN_m_n1: 0, k_phi_kN_m_n2: 1e300, "
                                        "cohesion_kPa: 0.2, friction_angle_deg: 30, shear_modulus_K_mm: 10}\n")}}});
    c.push_back({"mesh", "density_kg_m3 1e30", "force --pad pr_dense.yaml" + force,
                 {{"pr_dense.yaml", "schema_version: 1\nkind: mesh\nmesh: {file: box.off, unit: mm}\n"
                                    "density_kg_m3: 1e30\n"},
                  {"box.off", BoxOff()}}});
  }
  // Section 4: the soil fields the README documents.
  c.push_back({"soil YAML", "mu_surf and the dynamic term (README fields)",
               "force --pad flat --law agarwal2023 --depth 0.005 --soil dynamic.yaml",
               {{"dynamic.yaml", Soil("zeta_N_cm3: 3\nbulk_density_kg_m3: 1600\ninternal_friction_angle_deg: 37\n"
                                      "mu_surf: 0.3\ndynamic_term: true\ndynamic_lambda: 1.2\n")}}});
  // Section 4: spreadsheet datasets load (UTF-8 BOM, CRLF, every field quoted). The stroke is
  // samples 1-4 (the force falls at 5); calibrate fits the two between its first and last.
  c.push_back({"dataset CSV", "Excel/pandas export: BOM, CRLF, QUOTE_ALL", Calibrate("ds_excel"),
               Dataset("ds_excel",
                       "\xEF\xBB\xBF\"drop_id\",\"pad\",\"soil\",\"atmosphere\",\"impact_speed_m_s\",\"pad_mass_kg\","
                       "\"gravity_m_s2\",\"trace\"\r\n\"d0\",\"flat\",\"fjs1_lp\",\"vacuum\",\"1.0\",\"1.6\",\"9.81\","
                       "\"t.csv\"\r\n",
                       "\xEF\xBB\xBF\"t_s\",\"penetration_m\",\"force_N\"\r\n\"0\",\"0\",\"0\"\r\n\"0.001\",\"0.0005\","
                       "\"30\"\r\n\"0.002\",\"0.0009\",\"60\"\r\n\"0.003\",\"0.0012\",\"80\"\r\n\"0.004\",\"0.0014\","
                       "\"95\"\r\n\"0.005\",\"0.0015\",\"20\"\r\n")});
  c.push_back({"dataset CSV", "quoted field not closed", Calibrate("ds_quote"),
               Dataset("ds_quote", kDropsHeader + "\"d0,flat,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n")});
  // Section 4: synth seeds as sweep seeds.
  c.push_back({"synth YAML", "seed 2^64", "synth seed.synth.yaml --out out_y1",
               {{"seed.synth.yaml", "schema_version: 1\ntype: synth\nseed: 18446744073709551616\n"
                                    "drops:\n  - {pads: [flat], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"}}});
}

// Inputs that crashed, hung or lost data when touchdown was tried as a new user would.
void AddNewUserDefectCases(std::vector<Case>& c) {
  // Aliases: one inside its own anchor, and aliases of aliases, in any YAML file.
  c.push_back({"pad YAML", "an alias inside its own anchor", "drop --pad rec.yaml --soil fjs1_lp --speed 1",
               {{"rec.yaml", "a: &a [*a]\n"}}});
  std::string laughs = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level <= 8; ++level) {
    const std::string prev = "*l" + std::to_string(level - 1);
    laughs += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " [" + prev;
    for (int i = 1; i < 10; ++i) laughs += ", " + prev;
    laughs += "]\n";
  }
  c.push_back({"soil YAML", "aliases of aliases (10^9 values)", with_soil_cmd() + "laughs.yaml",
               {{"laughs.yaml", Soil("zeta_N_cm3: 3\n" + laughs)}}});
  c.push_back({"pad YAML", "a second YAML document", "drop --pad two_docs.yaml --soil fjs1_lp --speed 1",
               {{"two_docs.yaml", Pad(kFlatProfile) + "---\nmass_kg: 9\n"}}});
  // A mesh pad where only rig drops run.
  c.push_back({"synth YAML", "a mesh pad (rig drops only)", "synth hex.synth.yaml --out out_n1",
               {{"hex.synth.yaml", "schema_version: 1\ntype: synth\nseed: 1\n"
                                   "drops:\n  - {pads: [hex], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"}}});
  c.push_back({"dataset CSV", "diagnose with a mesh pad", "diagnose ds_hex --out out_n2",
               Dataset("ds_hex", kDropsHeader + "d0,hex,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n"
                                 "d1,hex,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\nd2,hex,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n",
                       "t_s,penetration_m,force_N\n0,0,0\n0.001,0.0005,30\n0.002,0.0009,60\n0.003,0.001,20\n"
                       "0.004,0.001,20\n0.005,0.001,20\n")});
  // A symbolic link the user put in an output touchdown fills in place is never written through.
  const auto linked_plots = [](const std::string& out) {
    return [out](const fs::path& d) {
      fs::create_directories(d / out);
      std::ofstream(d / out / ".touchdown-output") << "touchdown output\nkind: sweep\n";
      fs::create_directories(d / "mine");
      std::ofstream(d / "mine" / "exceedance.png") << "mine\n";
      fs::create_directory_symlink("../mine", d / out / "plots");
    };
  };
  c.push_back({"output path", "stability output whose plots/ is a link to the user's directory",
               "stability link_study.yaml --out out_n3",
               {{"link_study.yaml", "schema_version: 1\ntype: stability\nlander: {scenario: lander_case_A}\n"
                                    "grid: {slope_deg: [0]}\n"}},
               linked_plots("out_n3")});
  c.push_back({"output path", "trade output whose plots/ is a link to the user's directory",
               "trade link_trade.yaml --out out_n4",
               {{"link_trade.yaml", Sweep("traces: none\nfixed: {soil: fjs1_lp}\ngrid: {pad: [flat], impact_speed_m_s: [1.0]}\n")}},
               linked_plots("out_n4")});
}

// The fourth round of hostile inputs: names that become file names, numbers reported from samples,
// numbers a derivation or a source file lets past a range, fits that fail, unbounded work.
void AddFourthRoundCases(std::vector<Case>& c) {
  const std::string flat_pad = Pad(kFlatProfile);
  // Every name that becomes part of a path is checked where it is read.
  c.push_back({"pad YAML", "name ../../../PWNED in a campaign (wrote outside --out)", "campaign evil_campaign.yaml --out out_q1",
               {{"evil_pad.yaml", "name: ../../../PWNED\n" + flat_pad},
                {"evil_campaign.yaml", "drops:\n  - {pad: evil_pad.yaml, soil: fjs1_lp, impact_speeds_m_s: [1.0]}\n"}}});
  c.push_back({"pad YAML", "absolute name /some/dir/ABS", "drop --pad abs_pad.yaml --soil fjs1_lp --speed 1",
               {{"abs_pad.yaml", "name: /some/dir/ABS\n" + flat_pad}}});
  c.push_back({"pad YAML", "name ../x in a trade study (per-pad tables)", "trade evil_trade.yaml --out out_q2",
               {{"evil_trade_pad.yaml", "name: ../x\n" + flat_pad},
                {"evil_trade.yaml", Sweep("fixed: {soil: fjs1_lp}\ngrid: {pad: [evil_trade_pad.yaml], impact_speed_m_s: [1.0]}\n")}}});
  c.push_back({"soil YAML", "name with a '/'", with_soil_cmd() + "slash_soil.yaml",
               {{"slash_soil.yaml", "schema_version: 1\nname: a/b\nzeta_N_cm3: 3\n"}}});
  c.push_back({"sweep YAML", "name ../sweep", "sweep evil_sweep.yaml --threads 1 --progress lines --out out_q3",
               {{"evil_sweep.yaml", Sweep("name: ../sweep\n" + kSweepBase + "grid: {impact_speed_m_s: [1]}\n")}}});
  c.push_back({"lander YAML", "scenario name with a control character", "lander evil_lander.yaml --out out_q4",
               {{"evil_lander.yaml", Lander("name: \"a\\tb\"\nlander: sutoh2017_lander\n" + kLanderGround + kLanderInitial)}}});
  // Peaks read from the solution between samples: the pad stops within one sample period.
  c.push_back({"extreme", "free drop stopping within one sample (zeta 1000)",
               "drop --pad flat --soil fjs1_lp --speed 1 --zeta 1000 --free"});
  c.push_back({"extreme", "free drop of 10 g stopping within one sample",
               "drop --pad flat --soil fjs1_lp --speed 1 --zeta 1000 --mass 0.01 --free"});
  // A derived zeta meets the range a given one must.
  const std::string agarwal = "zeta_N_cm3: agarwal2023\nbulk_density_kg_m3: 1540\n";
  c.push_back({"soil YAML", "agarwal2023 zeta at a friction angle of 89.999 deg", with_soil_cmd() + "phi_89.yaml",
               {{"phi_89.yaml", Soil(agarwal + "internal_friction_angle_deg: 89.999\n")}}});
  c.push_back({"soil YAML", "agarwal2023 zeta at a friction angle of 85 deg", with_soil_cmd() + "phi_85.yaml",
               {{"phi_85.yaml", Soil(agarwal + "internal_friction_angle_deg: 85\n")}}});
  c.push_back({"CLI flag", "force --law agarwal2023 on a soil of friction angle 89.9 deg",
               "force --pad flat --soil phi_899.yaml --depth 0.01 --law agarwal2023",
               {{"phi_899.yaml", Soil("zeta_N_cm3: 3\nbulk_density_kg_m3: 1540\ninternal_friction_angle_deg: 89.9\n")}}});
  // Every number of a validation source in range at load.
  const auto source = [&](const std::string& name, const std::string& what, const std::string& body) {
    c.push_back({"validation sources", what, "validate --sources " + name + " --out out_" + name,
                 {{name + "/dynamic_rft.yaml", "schema_version: 1\ntype: validation_model\ninertial_drag_lambda: 1.1\nsource: s\n"},
                  {name + "/src.yaml", "schema_version: 1\ntype: validation_source\nid: src\ncitation: c\nread_at: r\n"
                                       "projectile:\n  pad: " + DataDir() + "/validation/pads/kd2007_steel_sphere.yaml\n"
                                       "  description: d\nmedium:\n  soil: " + DataDir() +
                                       "/validation/soils/kd2007_glass_beads.yaml\n  description: d\n  zeta_route: derived\n" +
                                       body}}});
  };
  const std::string law = "measured_law: {kind: katsuragi_durian, d1_mm: D1, d1_uncertainty_mm: 1, k_over_m_per_s2: KM, "
                          "k_over_m_uncertainty_per_s2: 1, how: quoted, where: w}\npoints:\n  - {id: p, impact_speed_m_s: 1, "
                          "quantity: final_depth, from_law: true, how: derived_from_measured_law, where: w}\n";
  const auto with = [](std::string s, const std::string& d1, const std::string& km) {
    s.replace(s.find("D1"), 2, d1);
    s.replace(s.find("KM"), 2, km);
    return s;
  };
  source("vq1", "law d1_mm 1e308 (exit 1 before)", "gravity_m_s2: 9.81\n" + with(law, "1e308", "1040"));
  source("vq2", "law k_over_m_per_s2 1e300 (exit 1 before)", "gravity_m_s2: 9.81\n" + with(law, "87", "1e300"));
  source("vq3", "gravity_m_s2 1e308 (exit 1 before)", "gravity_m_s2: 1e308\n" + with(law, "87", "1040"));
  source("vq4", "measured depth 1e9 mm (simulated before)",
         "gravity_m_s2: 9.81\npoints:\n  - {id: p, impact_speed_m_s: 1, quantity: final_depth, depth_mm: 1e9, how: quoted, "
         "where: w}\n");
  // A fit's targets in range; a failed fit exits 3 and writes no model.
  const auto targets = [&](const std::string& name, const std::string& what, const std::string& value) {
    c.push_back({"targets YAML", what, "calibrate --targets " + name + ".yaml --out " + name + "_model.yaml",
                 {{name + ".yaml", "schema_version: 1\ntype: targets\nparameters: [{name: z, soil: fjs1_lp, field: zeta_N_cm3, "
                                   "lower: 1, upper: 8, start: 3, source: s}]\ntargets: [{name: d, drop: {pad: flat, soil: "
                                   "fjs1_lp, speed_m_s: 1}, quantity: final_penetration_m, " + value + ", use: fit, source: s}]\n"}}});
  };
  targets("tq1", "target value 1e308 (exit 0 with a failed fit before)", "value: 1e308, uncertainty: 0.001");
  targets("tq2", "target uncertainty 1e-320 (exit 0 with a failed fit before)", "value: 0.01, uncertainty: 1e-320");
  // Unbounded work.
  const std::string study = "schema_version: 1\ntype: stability\nlander: {scenario: lander_case_A}\n"
                            "random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 10]}}\n";
  c.push_back({"CLI flag", "stability --method subset --samples 1e9 (11 GB before the first landing)",
               "stability uq.yaml --method subset --samples 1000000000 --progress none --out out_q5", {{"uq.yaml", study}}});
  c.push_back({"lander YAML", "cone_limit stiffness 1e12 N m/rad at 5 deg (minutes a landing)", "lander stiff_cone.yaml --out out_q6",
               {{"stiff_cone_lander.yaml",
                 "schema_version: 1\ntotal_mass_kg: 4.3\ncog_height_mm: 230\npad: " + DataDir() + "/landers/sutoh2017_footpad.yaml\n"
                 "body_inertia_kg_m2: {ixx: 0.05, iyy: 0.05, izz: 0.06}\nlegs: {joint_radius_mm: 300, hip_radius_mm: 120, "
                 "hip_height_mm: 200, cone_limit: {half_angle_deg: 5, stiffness_N_m_rad: 1e12, damping_N_m_s_rad: 0.16}}\n"},
                {"stiff_cone.yaml", Lander("lander: stiff_cone_lander.yaml\n" + kLanderGround + kLanderInitial)}}});
  c.push_back({"lander YAML", "simulation.max_evaluations 100: the work limit reached", "lander few_evals.yaml --out out_q7",
               {{"few_evals.yaml", Lander("lander: sutoh2017_lander\n" + kLanderGround + kLanderInitial +
                                          "simulation: {max_evaluations: 100}\n")}}});
  c.push_back({"CLI flag", "stability shards of one --out given different --methods",
               "stability uq.yaml --method subset --samples 10 --shard 0/2 --progress none --out out_q8", {{"uq.yaml", study}},
               [](const fs::path& d) {
                 fs::create_directories(d / "out_q8" / "shard_1_of_2");
                 std::ofstream(d / "out_q8" / ".touchdown-output") << "touchdown output\nkind: sweep\n";
                 std::ofstream(d / "out_q8" / "shard_1_of_2" / "method") << "importance\n";
               }});
  // Smaller ones.
  c.push_back({"diagnose", "--min-step-explained nan", "diagnose measured --min-step-explained nan --out out_q9"});
  c.push_back({"CLI flag", "--threads abc", "diagnose measured --threads abc --out out_q10"});
  c.push_back({"sweep YAML", "free_drop_model: ~ (read as the default before)",
               "sweep tilde.yaml --threads 1 --progress lines --out out_q11",
               {{"tilde.yaml", Sweep("simulation: {free_drop_model: ~}\n" + kSweepBase + "grid: {impact_speed_m_s: [1]}\n")}}});
  c.push_back({"soil YAML", "atmosphere: (nothing)", with_soil_cmd() + "empty_atmosphere.yaml",
               {{"empty_atmosphere.yaml", Soil("zeta_N_cm3: 3\natmosphere:\n")}}});
  c.push_back({"pad YAML", "YAML merge key <<", "drop --pad merge.yaml --soil fjs1_lp --speed 1",
               {{"merge.yaml", "schema_version: 1\nmass_kg: 1.6\nbase: &b {shape: flat, radius_mm: 50, thickness_mm: 16}\n"
                               "profile: {<<: *b}\n"}}});
  c.push_back({"CLI flag", "drop --mass 1e-320", rig_cmd() + "--speed 1 --mass 1e-320"});
  c.push_back({"CLI flag", "drop --gravity 1e-300", rig_cmd() + "--speed 1 --gravity 1e-300"});
  c.push_back({"CLI flag", "drop --trace '' (wrote nothing, said nothing)", rig_cmd() + "--speed 1 --trace ''"});
  c.push_back({"CLI flag", "drop --free --tilt-deg 90", rig_cmd() + "--speed 1 --free --tilt-deg 90"});
  c.push_back({"scenario YAML", "campaign with a mesh pad", "campaign mesh_campaign.yaml --out out_q12",
               {{"mesh_campaign.yaml", "drops:\n  - {pad: hex, soil: fjs1_lp, impact_speeds_m_s: [1.0]}\n"}}});
  c.push_back({"CLI flag", "campaign --model (a model file for every drop)",
               "campaign model_campaign.yaml --model campaign_model.yaml --out out_q13",
               {{"model_campaign.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [1.0]}\n"},
                {"campaign_model.yaml", Model("soils: {fjs1_lp: {zeta_N_cm3: 2.0}}\n")}}});
}

// Two 10 x 10 x 5 mm boxes 10 mm apart: two closed shells, neither inside the other.
std::string TwoSeparateBoxesOff() {
  return TwoBoxesOff("20 0 0\n30 0 0\n30 10 0\n20 10 0\n20 0 5\n30 0 5\n30 10 5\n20 10 5\n");
}

// Wrong exit statuses and unclear or missing messages: file names that are not UTF-8, the
// targets fit's bounds, messages that now name the field, the value and the valid range, and
// inputs that were accepted silently.
void AddMessageCases(std::vector<Case>& c) {
  // Arguments that are not UTF-8 (the shell's printf makes the byte 0xff).
  const std::string lander = Lander("lander: sutoh2017_lander\n" + kLanderGround + kLanderInitial);
  const auto latin1_file = [](const std::string& name, const std::string& bytes) {
    return [name, bytes](const fs::path& d) { std::ofstream(d / name, std::ios::binary) << bytes; };
  };
  c.push_back({"input path", "lander scenario file name not UTF-8", "lander \"$(printf 'l\\377.yaml')\" --out out_u1",
               {}, latin1_file("l\xff.yaml", lander)});
  c.push_back({"input path", "study file name not UTF-8", "stability \"$(printf 's\\377.yaml')\" --out out_u2", {},
               latin1_file("s\xff.yaml", "schema_version: 1\ntype: stability\nlander: {scenario: lander_case_A}\n"
                                          "grid: {slope_deg: [0, 5]}\n")});
  c.push_back({"input path", "campaign file name not UTF-8", "campaign \"$(printf 'c\\377.yaml')\" --out out_u3", {},
               latin1_file("c\xff.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [1.0]}\n")});
  c.push_back({"output path", "calibrate --out name not UTF-8", "calibrate ds_u4 --out \"$(printf 'm\\377.yaml')\"",
               Dataset("ds_u4", kDropsHeader + "d0,flat,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n")});
  // calibrate --targets.
  const std::string target = "targets: [{name: d, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1}, quantity: "
                             "final_penetration_m, value: 0.01, uncertainty: 0.001, use: fit, source: s}]\n";
  const std::string zeta = "parameters: [{name: z, soil: fjs1_lp, field: zeta_N_cm3, lower: 1, upper: 8, start: 3, "
                           "source: s}]\n";
  const std::string head = "schema_version: 1\ntype: targets\n";
  c.push_back({"targets YAML", "upper 1e300", "calibrate --targets t_huge.yaml --out t5.yaml",
               {{"t_huge.yaml", head + "parameters: [{name: z, soil: fjs1_lp, field: zeta_N_cm3, lower: 1, "
                                       "upper: 1e300, start: 3, source: s}]\n" + target}}});
  c.push_back({"targets YAML", "one field freed by two parameters", "calibrate --targets t_twice.yaml --out t6.yaml",
               {{"t_twice.yaml", head + "parameters: [{name: z, soil: fjs1_lp, field: zeta_N_cm3, lower: 1, upper: 8, "
                                        "start: 3, source: s}, {name: z2, soil: fjs1_lp, field: zeta_N_cm3, lower: 1, "
                                        "upper: 8, start: 3, source: s}]\n" + target}}});
  c.push_back({"targets YAML", "dynamic_lambda bounded below 0", "calibrate --targets t_lambda.yaml --out t9.yaml",
               {{"t_lambda.yaml", head + "parameters: [{name: l, soil: fjs1_lp, field: dynamic_lambda, lower: -1, "
                                         "upper: 4, start: 1, source: s}]\n" + target}}});
  c.push_back({"targets YAML", "a Bekker field on a soil whose law is not bekker", "calibrate --targets t_bekker.yaml --out t10.yaml",
               {{"t_bekker.yaml", head + "parameters: [{name: n, soil: fjs1_lp, field: bekker.n, lower: 0.5, "
                                         "upper: 1.5, start: 1, source: s}]\n" + target}}});
  c.push_back({"targets YAML", "negative ratio target", "calibrate --targets t_ratio.yaml --out t7.yaml",
               {{"t_ratio.yaml", head + zeta + "targets: [{name: r, ratio: {numerator: {drop: {pad: flat, soil: fjs1_lp, "
                                               "speed_m_s: 1}, quantity: peak_force_N}, denominator: {drop: {pad: flat, "
                                               "soil: fjs1_lp, speed_m_s: 2}, quantity: peak_force_N}}, value: -0.5, "
                                               "uncertainty: 0.1, use: fit, source: s}]\n"}}});
  c.push_back({"targets YAML", "fit pressed against a lower bound of 4, relative_step 0.1 (stays within the bounds)",
               "calibrate --targets t_edge.yaml --out t8.yaml",
               {{"t_edge.yaml", head + "fit: {relative_step: 0.1}\nparameters: [{name: z, soil: fjs1_lp, field: "
                                       "zeta_N_cm3, lower: 4, upper: 52, start: 4.2, source: s}]\n" +
                                       "targets: [{name: d, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1}, quantity: "
                                       "final_penetration_m, value: 0.05, uncertainty: 0.0001, use: fit, source: s}]\n"}}});
  c.push_back({"CLI flag", "calibrate --report with one zeta for every soil", "calibrate ds_u8 --out ds_u8.yaml --per all --report r.json",
               Dataset("ds_u8", kDropsHeader + "d0,flat,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n")});
  // Messages naming the field, the value and the valid range.
  const std::string lander_sweep = "lander: {scenario: lander_case_A}\n";
  const std::string study = "schema_version: 1\ntype: stability\n" + lander_sweep;
  c.push_back({"sweep YAML", "random seed 1e20", "sweep seed_big.yaml --threads 1 --progress lines --out out_u9",
               {{"seed_big.yaml", Sweep(kSweepBase + "random: {samples: 2, seed: 1e20, impact_speed_m_s: {uniform: "
                                                     "[0.5, 2]}}\n")}}});
  c.push_back({"study YAML", "map.bins [1, 300]", "stability bins.yaml --out out_u10",
               {{"bins.yaml", study + "grid: {slope_deg: [0, 5], roll_deg: [0, 5]}\n"
                                      "study: {map: {x: slope_deg, y: roll_deg, bins: [1, 300]}}\n"}}});
  c.push_back({"study YAML", "map.bins: 5 (not a pair)", "stability bins5.yaml --out out_u11",
               {{"bins5.yaml", study + "grid: {slope_deg: [0, 5], roll_deg: [0, 5]}\n"
                                       "study: {map: {x: slope_deg, y: roll_deg, bins: 5}}\n"}}});
  c.push_back({"sweep YAML", "choice probabilities: three for two values",
               "sweep probs.yaml --threads 1 --progress lines --out out_u12",
               {{"probs.yaml", Sweep(kSweepBase + "random: {samples: 2, seed: 1, impact_speed_m_s: {choice: [1, 2], "
                                                  "probabilities: [0.2, 0.3, 0.5]}}\n")}}});
  c.push_back({"sweep YAML", "choice probability 1.5", "sweep prob15.yaml --threads 1 --progress lines --out out_u13",
               {{"prob15.yaml", Sweep(kSweepBase + "random: {samples: 2, seed: 1, impact_speed_m_s: {choice: [1, 2], "
                                                   "probabilities: [1.5, -0.5]}}\n")}}});
  c.push_back({"study YAML", "map over a one-value grid axis", "stability one_value.yaml --out out_u14",
               {{"one_value.yaml", study + "grid: {slope_deg: [5], roll_deg: [0, 5]}\n"
                                           "study: {map: {x: slope_deg, y: roll_deg}}\n"}}});
  c.push_back({"lander YAML", "a Bekker soil patch on an RFT (li2013) ground", "lander bekker_patch.yaml --out out_u15",
               {{"bekker_patch.yaml", Lander("lander: sutoh2017_lander\nground: {soil: fjs1_lp, patches: [{soil: "
                                             "soft_sand_bekker, rectangle_m: [-1, -1, 0, 1]}]}\n" + kLanderInitial)}}});
  c.push_back({"synth YAML", "unknown pad in drops[1]", "synth pad.synth.yaml --out out_u16",
               {{"pad.synth.yaml", "schema_version: 1\ntype: synth\nseed: 1\ndrops:\n"
                                   "  - {pads: [flat], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"
                                   "  - {pads: [hexagon], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"}}});
  c.push_back({"synth YAML", "the same drop made twice", "synth twice.synth.yaml --out out_u17",
               {{"twice.synth.yaml", "schema_version: 1\ntype: synth\nseed: 1\ndrops:\n"
                                     "  - {pads: [flat], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"
                                     "  - {pads: [flat], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"}}});
  c.push_back({"synth YAML", "a drop that never stops (true zeta 1e-6)", "synth stuck.synth.yaml --out out_u18",
               {{"stuck.synth.yaml", "schema_version: 1\ntype: synth\nseed: 1\ntrue_zeta_N_cm3: {fjs1_lp: 0.000001}\n"
                                     "drops:\n  - {pads: [flat], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"}}});
  // Accepted silently before.
  const std::string ground = "lander: sutoh2017_lander\n" + kLanderInitial;
  c.push_back({"lander YAML", "patches: []", "lander no_patches.yaml --out out_u19",
               {{"no_patches.yaml", Lander(ground + "ground: {soil: fjs1_lp, patches: []}\n")}}});
  c.push_back({"lander YAML", "patch polygon crossing itself (bow tie)", "lander bow_tie.yaml --out out_u20",
               {{"bow_tie.yaml", Lander(ground + "ground: {soil: fjs1_lp, patches: [{soil: fjs1_cp, "
                                                 "polygon_m: [[0, 0], [1, 1], [1, 0], [0, 1]]}]}\n")}}});
  c.push_back({"lander YAML", "patch polygon with no area (corners on a line)", "lander flat_polygon.yaml --out out_u21",
               {{"flat_polygon.yaml", Lander(ground + "ground: {soil: fjs1_lp, patches: [{soil: fjs1_cp, "
                                                      "polygon_m: [[0, 0], [1, 1], [2, 2]]}]}\n")}}});
  const std::string asc_header = "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 0.1\n";
  c.push_back({"terrain raster", "a row one value short", "lander short_row.yaml --out out_t1",
               {{"short_row.yaml", Lander(ground + "ground: {soil: fjs1_lp, terrain: {file: short_row.asc}}\n")},
                {"short_row.asc", asc_header + "0 0 0\n0 0\n0 0 0\n"}}});
  c.push_back({"terrain raster", "NODATA inside the window", "lander nodata.yaml --out out_t2",
               {{"nodata.yaml", Lander(ground + "ground: {soil: fjs1_lp, terrain: {file: nodata.asc}}\n")},
                {"nodata.asc", asc_header + "NODATA_value -9999\n0 0 0\n0 -9999 0\n0 0 0\n"}}});
  c.push_back({"terrain raster", "the pads start outside a 20 cm raster", "lander small_site.yaml --out out_t3",
               {{"small_site.yaml", Lander(ground + "ground: {soil: fjs1_lp, terrain: {file: small_site.asc}}\n")},
                {"small_site.asc", asc_header + "0 0 0\n0 0 0\n0 0 0\n"}}});
  c.push_back({"mesh", "two separate boxes (two shells)", "force --pad two_shells.yaml --soil fjs1_lp --depth 0.002",
               {{"two_shells.yaml", MeshPad("two_shells.off")}, {"two_shells.off", TwoSeparateBoxesOff()}}});
  c.push_back({"sweep results", "merge the same shard twice", "merge out_w9 ./out_w9 --out out_u23"});
  c.push_back({"study YAML", "every landing fails (--max-drop-evaluations 20)",
               "stability all_fail.yaml --max-drop-evaluations 20 --threads 1 --progress none --out out_u24",
               {{"all_fail.yaml", study + "grid: {slope_deg: [0, 5]}\n"}}});
}

std::vector<Case> Cases() {
  std::vector<Case> c;
  // Pad YAML.
  c.push_back({"pad YAML", "unknown field (typo)", "drop --pad typo.yaml --soil fjs1_lp --speed 1",
               {{"typo.yaml", Pad(kFlatProfile + "angular_segmnts: 64\n")}}});
  c.push_back({"pad YAML", "negative radius", "drop --pad neg_radius.yaml --soil fjs1_lp --speed 1",
               {{"neg_radius.yaml", Pad("profile: {shape: flat, radius_mm: -50, thickness_mm: 16}\n")}}});
  c.push_back({"pad YAML", "angular_segments 1e9", "drop --pad segments.yaml --soil fjs1_lp --speed 1",
               {{"segments.yaml", Pad(kFlatProfile + "angular_segments: 1000000000\n")}}});
  c.push_back({"pad YAML", "profile segments 1e9", "drop --pad profile_segments.yaml --soil fjs1_lp --speed 1",
               {{"profile_segments.yaml",
                 Pad("profile: {shape: exponential, radius_mm: 50, thickness_mm: 16, a0_mm: 4, a1_per_mm: 0.0319, "
                     "segments: 1000000000}\n")}}});
  c.push_back({"pad YAML", "unknown profile shape", "drop --pad shape.yaml --soil fjs1_lp --speed 1",
               {{"shape.yaml", Pad("profile: {shape: hexagon, radius_mm: 50, thickness_mm: 16}\n")}}});
  c.push_back({"pad YAML", "malformed YAML (unclosed brace)", "drop --pad malformed.yaml --soil fjs1_lp --speed 1",
               {{"malformed.yaml", Pad("profile: {shape: flat, radius_mm: 50\n")}}});
  c.push_back({"pad YAML", "unsupported schema version", "drop --pad schema.yaml --soil fjs1_lp --speed 1",
               {{"schema.yaml", "schema_version: 2\nmass_kg: 1.6\n" + kFlatProfile}}});
  c.push_back({"pad YAML", "table profile point not a pair", "drop --pad table.yaml --soil fjs1_lp --speed 1",
               {{"table.yaml", Pad("profile: {shape: table, radius_mm: 50, thickness_mm: 16, "
                                   "points_mm: [[0, 0], [50]]}\n")}}});
  c.push_back({"pad YAML", "mass .nan", "drop --pad nan_mass.yaml --soil fjs1_lp --speed 1",
               {{"nan_mass.yaml", "mass_kg: .nan\n" + kFlatProfile}}});
  c.push_back({"pad YAML", "empty file", "drop --pad empty.yaml --soil fjs1_lp --speed 1", {{"empty.yaml", ""}}});
  c.push_back({"pad YAML", "top level is a list", "drop --pad list.yaml --soil fjs1_lp --speed 1",
               {{"list.yaml", "- mass_kg: 1.6\n"}}});
  c.push_back({"pad YAML", "missing file", "drop --pad nowhere.yaml --soil fjs1_lp --speed 1"});
  c.push_back({"pad YAML", "unknown catalogue name", "drop --pad hexagon --soil fjs1_lp --speed 1"});
  c.push_back({"pad YAML", "mesh pad on the rig (vertical rod)", "drop --pad hex --soil fjs1_lp --speed 1"});
  // Meshes (through a mesh pad YAML and `force`).
  const std::string force = " --soil fjs1_lp --depth 0.002";
  c.push_back({"mesh", "remesh_edge_mm 1e-6 (about 1e15 triangles)", "force --pad remesh.yaml" + force,
               {{"remesh.yaml", MeshPad("box.off", ", remesh_edge_mm: 0.000001")}, {"box.off", BoxOff()}}});
  c.push_back({"mesh", "mesh file missing", "force --pad no_mesh.yaml" + force,
               {{"no_mesh.yaml", MeshPad("missing.stl")}}});
  c.push_back({"mesh", "STL with a facet missing (open)", "force --pad open.yaml" + force,
               {{"open.yaml", MeshPad("open.stl")}, {"open.stl", OpenBoxStl()}}});
  c.push_back({"mesh", "binary STL with a NaN coordinate", "force --pad nan_stl.yaml" + force,
               {{"nan_stl.yaml", MeshPad("nan.stl")}, {"nan.stl", NanStl()}}});
  c.push_back({"mesh", "OFF declaring 1e9 vertices and faces", "force --pad huge_off.yaml" + force,
               {{"huge_off.yaml", MeshPad("huge.off")}, {"huge.off", "OFF\n1000000000 1000000000 0\n0 0 0\n"}}});
  c.push_back({"mesh", "OFF face declaring 1e9 corners", "force --pad huge_face.yaml" + force,
               {{"huge_face.yaml", MeshPad("huge_face.off")},
                {"huge_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000 0 1 2\n"}}});
  c.push_back({"mesh", "PLY list declaring 2^31 indices", "force --pad huge_ply.yaml" + force,
               {{"huge_ply.yaml", MeshPad("huge.ply")}, {"huge.ply", kHugeListPly}}});
  c.push_back({"mesh", "OBJ face index out of range", "force --pad bad_obj.yaml" + force,
               {{"bad_obj.yaml", MeshPad("bad.obj")},
                {"bad.obj", "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 9\n"}}});
  c.push_back({"mesh", "two intersecting boxes", "force --pad intersect.yaml" + force,
               {{"intersect.yaml", MeshPad("two_boxes.off")}, {"two_boxes.off", BoxOff(false, true)}}});
  c.push_back({"mesh", "inside-out box (reoriented)", "force --pad inverted.yaml" + force,
               {{"inverted.yaml", MeshPad("inverted.off")}, {"inverted.off", BoxOff(true)}}});
  c.push_back({"mesh", "unknown format .3mf", "force --pad threemf.yaml" + force,
               {{"threemf.yaml", MeshPad("pad.3mf")}, {"pad.3mf", "not a mesh"}}});
  c.push_back({"mesh", "unknown unit", "force --pad inch.yaml" + force,
               {{"inch.yaml", "kind: mesh\nmesh: {file: box.off, unit: inch}\nmass_kg: 0.5\n"}, {"box.off", BoxOff()}}});
  // Soil YAML.
  const std::string with_soil = "drop --pad flat --speed 1 --soil ";
  c.push_back({"soil YAML", "negative zeta", with_soil + "neg_zeta.yaml", {{"neg_zeta.yaml", Soil("zeta_N_cm3: -3\n")}}});
  c.push_back({"soil YAML", "zeta missing", with_soil + "no_zeta.yaml", {{"no_zeta.yaml", Soil("atmosphere: vacuum\n")}}});
  c.push_back({"soil YAML", "unknown atmosphere", with_soil + "water.yaml",
               {{"water.yaml", Soil("zeta_N_cm3: 3\natmosphere: water\n")}}});
  c.push_back({"soil YAML", "friction angle 95 deg", with_soil + "phi.yaml",
               {{"phi.yaml", Soil("zeta_N_cm3: 3\ninternal_friction_angle_deg: 95\n")}}});
  c.push_back({"soil YAML", "agarwal2023 without density", with_soil + "agarwal.yaml",
               {{"agarwal.yaml", Soil("zeta_N_cm3: agarwal2023\ninternal_friction_angle_deg: 37\n")}}});
  // Campaign scenario YAML.
  c.push_back({"scenario YAML", "drops is not a list", "campaign not_list.yaml --out out_c1",
               {{"not_list.yaml", "drops: 5\n"}}});
  c.push_back({"scenario YAML", "impact speed is text", "campaign text_speed.yaml --out out_c2",
               {{"text_speed.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [fast]}\n"}}});
  c.push_back({"scenario YAML", "negative speed in a list", "campaign neg_speed.yaml --out out_c3",
               {{"neg_speed.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [1.0, -2]}\n"}}});
  // Sweep YAML.
  const std::string sweep_run = " --threads 1 --progress lines --out ";
  c.push_back({"sweep YAML", "grid count 1e9", "sweep count.yaml" + sweep_run + "out_w1",
               {{"count.yaml", Sweep(kSweepBase + "grid: {impact_speed_m_s: {from: 0.5, to: 2, count: 1000000000}}\n")}}});
  c.push_back({"sweep YAML", "2^40 drops and more", "sweep many.yaml" + sweep_run + "out_w2",
               {{"many.yaml", Sweep(kSweepBase + "grid: {impact_speed_m_s: {from: 0.5, to: 2, count: 100000}}\n"
                                                 "random: {samples: 1000000000, seed: 1, pad_mass_kg: {uniform: [1, 2]}}\n")}}});
  c.push_back({"sweep YAML", "random samples without a seed", "sweep seed.yaml" + sweep_run + "out_w3",
               {{"seed.yaml", Sweep(kSweepBase + "random: {samples: 3, impact_speed_m_s: {uniform: [0.5, 2]}}\n")}}});
  c.push_back({"sweep YAML", "parameter set twice", "sweep twice.yaml" + sweep_run + "out_w4",
               {{"twice.yaml", Sweep(kSweepBase + "grid: {pad: [flat, c4], impact_speed_m_s: [1]}\n")}}});
  c.push_back({"sweep YAML", "unknown parameter", "sweep unknown.yaml" + sweep_run + "out_w5",
               {{"unknown.yaml", Sweep(kSweepBase + "grid: {impact_velocity: [1]}\n")}}});
  c.push_back({"sweep YAML", "uniform with low > high", "sweep uniform.yaml" + sweep_run + "out_w6",
               {{"uniform.yaml", Sweep(kSweepBase + "random: {samples: 2, seed: 1, impact_speed_m_s: {uniform: [2, 1]}}\n")}}});
  c.push_back({"sweep YAML", "negative wall-clock limit", "sweep wall.yaml" + sweep_run + "out_w7",
               {{"wall.yaml", Sweep("max_drop_wall_time_s: -1\n" + kSweepBase + "grid: {impact_speed_m_s: [1]}\n")}}});
  c.push_back({"sweep YAML", "trace_max_samples 2", "sweep trace_max.yaml" + sweep_run + "out_w8",
               {{"trace_max.yaml", Sweep("trace_max_samples: 2\n" + kSweepBase + "grid: {impact_speed_m_s: [1]}\n")}}});
  c.push_back({"sweep YAML", "zeta 1e-6: the pad never stops (drop recorded as failed)",
               "sweep soft.yaml" + sweep_run + "out_w9",
               {{"soft.yaml", Sweep(kSweepBase + "grid: {impact_speed_m_s: [1], zeta_N_cm3: [0.000001, 3.5]}\n")}}});
  c.push_back({"sweep YAML", "--max-drop-wall-time 1e-9: every drop over its limit",
               "sweep limit.yaml --max-drop-wall-time 1e-9" + sweep_run + "out_w10",
               {{"limit.yaml", Sweep(kSweepBase + "grid: {impact_speed_m_s: [0.7, 1.5]}\n")}}});
  const std::string lander_sweep = "lander: {scenario: lander_case_A}\n";
  c.push_back({"sweep YAML", "pad_soils case D (Table II has A, B, C)", "sweep case_d.yaml" + sweep_run + "out_w11",
               {{"case_d.yaml", Sweep(lander_sweep + "grid: {pad_soils: [A, D]}\n")}}});
  c.push_back({"sweep YAML", "pad_soils with three soils", "sweep three.yaml" + sweep_run + "out_w12",
               {{"three.yaml", Sweep(lander_sweep + "grid: {pad_soils: [[fjs1_cp, fjs1_lp, fjs1_lp]]}\n")}}});
  c.push_back({"sweep YAML", "soil and pad_soils both", "sweep both_soils.yaml" + sweep_run + "out_w13",
               {{"both_soils.yaml", Sweep(lander_sweep + "fixed: {soil: fjs1_cp}\ngrid: {pad_soils: [A, B]}\n")}}});
  c.push_back({"sweep YAML", "pad_soils in a single-pad sweep", "sweep pad_soils_pad.yaml" + sweep_run + "out_w14",
               {{"pad_soils_pad.yaml", Sweep(kSweepBase + "grid: {impact_speed_m_s: [1], pad_soils: [A]}\n")}}});
  c.push_back({"sweep YAML", "trade on a lander sweep", "trade trade_lander.yaml --out out_w15",
               {{"trade_lander.yaml", Sweep(lander_sweep + "grid: {impact_speed_m_s: [1.0, 1.4]}\n")}}});
  // Stability study YAML (docs/stability_studies.md).
  const std::string study = "schema_version: 1\ntype: stability\n" + lander_sweep + "grid: {slope_deg: [0, 5]}\n";
  c.push_back({"study YAML", "map over a parameter the study does not vary",
               "stability map.yaml --progress lines --out out_t1",
               {{"map.yaml", study + "study: {map: {x: slope_deg, y: roll_deg}}\n"}}});
  c.push_back({"study YAML", "--samples without random samples", "stability grid_only.yaml --samples 5 --out out_t2",
               {{"grid_only.yaml", study}}});
  c.push_back({"study YAML", "slope 90 deg", "stability steep.yaml --out out_t3",
               {{"steep.yaml", "schema_version: 1\ntype: stability\n" + lander_sweep + "grid: {slope_deg: [0, 90]}\n"}}});
  // Validation sources (docs/validation.md).
  c.push_back({"validation sources", "--sources is not a directory", "validate --sources no_such_dir --out out_v1"});
  c.push_back({"validation sources", "a source whose id is not its file name", "validate --sources vs --out out_v2",
               {{"vs/dynamic_rft.yaml", "schema_version: 1\ntype: validation_model\ninertial_drag_lambda: 1.1\nsource: s\n"},
                {"vs/a.yaml", "schema_version: 1\ntype: validation_source\nid: b\n"}}});
  // Lander scenario YAML.
  c.push_back({"lander YAML", "unknown lander", "lander no_lander.yaml --out out_l1",
               {{"no_lander.yaml", Lander("lander: apollo\n" + kLanderGround + kLanderInitial)}}});
  c.push_back({"lander YAML", "slope 95 deg", "lander slope.yaml --out out_l2",
               {{"slope.yaml", Lander("lander: sutoh2017_lander\nground: {soil: fjs1_lp, slope_deg: 95}\n" +
                                      kLanderInitial)}}});
  c.push_back({"lander YAML", "drop height and touchdown speed both given", "lander both.yaml --out out_l3",
               {{"both.yaml", Lander("lander: sutoh2017_lander\n" + kLanderGround +
                                     "initial: {drop_height_m: 0.1, touchdown_speed_m_s: 1}\n")}}});
  c.push_back({"lander YAML", "simulation duration 1e9 s", "lander long.yaml --out out_l4",
               {{"long.yaml", Lander("lander: sutoh2017_lander\n" + kLanderGround + kLanderInitial +
                                     "simulation: {duration_s: 1000000000}\n")}}});
  c.push_back({"lander YAML", "pitch 85 deg", "lander pitch.yaml --out out_l5",
               {{"pitch.yaml", Lander("lander: sutoh2017_lander\n" + kLanderGround +
                                      "initial: {drop_height_m: 0.1, pitch_deg: 85}\n")}}});
  // Import mapping YAML and raw DAQ files (`touchdown import`).
  {
    const std::string head = "schema_version: 1\ntype: import\nname: rig\ndaq: {delimiter: \",\", time: {column: t, unit: s}}\n"
                             "channels: {force: {column: f, gain: 1.0}, displacement: {column: x, gain: 0.001}}\n";
    const std::string drop = "  - {file: raw.csv, drop_id: d1, pad: flat, soil: fjs1_lp, atmosphere: vacuum, "
                             "impact_speed_m_s: 1.0, pad_mass_kg: 1.6, gravity_m_s2: 9.81}\n";
    std::string raw = "t,f,x\n";
    for (int i = 0; i < 200; ++i)
      raw += std::to_string(i * 1e-3) + "," + (i < 50 ? "0" : std::to_string(10.0 * (i - 50))) + "," +
             (i < 50 ? "0" : std::to_string(0.1 * (i - 50))) + "\n";
    c.push_back({"import mapping", "a drop id with a path separator", "import i1.yaml --out out_i1",
                 {{"i1.yaml", head + "drops:\n" + std::regex_replace(drop, std::regex("drop_id: d1"), "drop_id: ../d1")},
                  {"raw.csv", raw}}});
    c.push_back({"import mapping", "a name that climbs out", "import i2.yaml --out out_i2",
                 {{"i2.yaml", std::regex_replace(head, std::regex("name: rig"), "name: ../../rig") + "drops:\n" + drop},
                  {"raw.csv", raw}}});
    c.push_back({"raw DAQ file", "a text cell in the force column", "import i3.yaml --out out_i3",
                 {{"i3.yaml", head + "drops:\n" + drop}, {"raw.csv", raw + "0.2,abc,20\n"}}});
    c.push_back({"import mapping", "a raw file that is missing", "import i4.yaml --out out_i4",
                 {{"i4.yaml", head + "drops:\n" + std::regex_replace(drop, std::regex("raw\\.csv"), "gone.csv")}}});
  }
  // Model YAML.
  const std::string with_model = "drop --pad flat --soil fjs1_lp --speed 1 --model ";
  c.push_back({"model YAML", "wrong type", with_model + "m_type.yaml", {{"m_type.yaml", "type: sweep\n"}}});
  c.push_back({"model YAML", "reversed zeta interval", with_model + "m_interval.yaml",
               {{"m_interval.yaml", Model("soils: {fjs1_lp: {zeta_N_cm3: 3, zeta_interval_N_cm3: [4, 2]}}\n")}}});
  c.push_back({"model YAML", "confidence 1.5", with_model + "m_confidence.yaml",
               {{"m_confidence.yaml", Model("soils: {fjs1_lp: {zeta_N_cm3: 3, confidence: 1.5}}\n")}}});
  c.push_back({"model YAML", "unknown effect", with_model + "m_effect.yaml",
               {{"m_effect.yaml", Model("effects: {magic_damping: {c: 1}}\n")}}});
  // Dataset CSV (through `calibrate`).
  const std::string row = "d0,flat,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n";
  {
    auto add = [&](const std::string& what, const std::string& name,
                   std::vector<std::pair<std::string, std::string>> files) {
      c.push_back({"dataset CSV", what, Calibrate(name), std::move(files)});
    };
    add("missing column", "ds_column",
        Dataset("ds_column", "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,trace\nd0,flat,fjs1_lp,vacuum,1,1.6,t.csv\n"));
    add("non-numeric speed", "ds_text", Dataset("ds_text", kDropsHeader + "d0,flat,fjs1_lp,vacuum,fast,1.6,9.81,t.csv\n"));
    add("duplicate drop id", "ds_dup", Dataset("ds_dup", kDropsHeader + row + row));
    add("unknown pad", "ds_pad", Dataset("ds_pad", kDropsHeader + "d0,hexagon,fjs1_lp,vacuum,1,1.6,9.81,t.csv\n"));
    add("trace file missing", "ds_trace", {{"ds_trace/drops.csv", kDropsHeader + row}});
    add("row with a missing cell", "ds_cells", Dataset("ds_cells", kDropsHeader + "d0,flat,fjs1_lp,vacuum,1,1.6,t.csv\n"));
    add("negative mass", "ds_mass", Dataset("ds_mass", kDropsHeader + "d0,flat,fjs1_lp,vacuum,1,-1.6,9.81,t.csv\n"));
    add("trace time not increasing", "ds_time",
        Dataset("ds_time", kDropsHeader + row, "t_s,penetration_m,force_N\n0,0,0\n0.002,0.001,10\n0.001,0.002,20\n"));
    add("trace with a duplicate column", "ds_dupcol",
        Dataset("ds_dupcol", kDropsHeader + row, "t_s,penetration_m,force_N,t_s\n0,0,0,0\n"));
    add("trace number 1e999", "ds_overflow",
        Dataset("ds_overflow", kDropsHeader + row, "t_s,penetration_m,force_N\n0,0,0\n0.001,1e999,5\n"));
    add("data after a blank line", "ds_blank", Dataset("ds_blank", kDropsHeader + row + "\n" + row));
    add("empty drops.csv", "ds_empty", Dataset("ds_empty", ""));
  }
  // Command-line flags.
  c.push_back({"CLI flag", "speed is text", "drop --pad flat --soil fjs1_lp --speed fast"});
  c.push_back({"CLI flag", "misspelt option", "drop --pad flat --soil fjs1_lp --sped 1"});
  c.push_back({"CLI flag", "required option missing", "drop --soil fjs1_lp --speed 1"});
  c.push_back({"CLI flag", "unknown command", "fly --to moon"});
  c.push_back({"CLI flag", "infinite gravity", "drop --pad flat --soil fjs1_lp --speed 1 --gravity inf"});
  c.push_back({"CLI flag", "sweep --max-drop-wall-time -5", "sweep soft.yaml --max-drop-wall-time -5 --out out_f4"});
  c.push_back({"CLI flag", "sweep --threads -1", "sweep count.yaml --threads -1 --out out_f1"});
  c.push_back({"CLI flag", "sweep --shard 3/2", "sweep soft.yaml --shard 3/2 --out out_f2"});
  c.push_back({"CLI flag", "sweep --max-drop-wall-time nan", "sweep soft.yaml --max-drop-wall-time nan --out out_f3"});
  // Output paths: touchdown never writes over, into or around what it did not write.
  {
    const std::string scenario = "o_lander.yaml";
    const std::pair<std::string, std::string> lander = {scenario, Lander("lander: sutoh2017_lander\n" + kLanderGround +
                                                                         kLanderInitial)};
    const std::string run = "lander " + scenario + " --out ";
    c.push_back({"output path", "a directory of the user's (holds notes.txt)", run + "o_k", {lander, {"o_k/notes.txt", "mine"}}});
    c.push_back({"output path", "the current directory", run + ".", {lander}});
    c.push_back({"output path", "the parent directory", run + "..", {lander}});
    c.push_back({"output path", "a file of the user's", run + "o_file", {lander, {"o_file", "mine"}}});
    c.push_back({"output path", "the command's input file", run + scenario, {lander}});
    c.push_back({"output path", "trailing slash (a new directory)", run + "o_new/", {lander}});
    c.push_back({"output path", "compare DS --out DS (the measured dataset)", "compare o_ds --out o_ds",
                 Dataset("o_ds", kDropsHeader + row)});
    c.push_back({"output path", "calibrate --out inside the measured dataset", "calibrate o_ds2 --out o_ds2/model.yaml",
                 Dataset("o_ds2", kDropsHeader + row)});
    c.push_back({"output path", "drop --trace onto a directory", "drop --pad flat --soil fjs1_lp --speed 1 --trace o_dir",
                 {{"o_dir/x", ""}}});
    c.push_back({"output path", "drop --trace onto a file of the user's",
                 "drop --pad flat --soil fjs1_lp --speed 1 --trace o_trace.csv", {{"o_trace.csv", "mine"}}});
  }
  // Extreme but legal inputs.
  const std::string rig = "drop --pad flat --soil fjs1_lp ";
  c.push_back({"extreme", "10 m/s impact", rig + "--speed 10"});
  c.push_back({"extreme", "100 m/s impact", rig + "--speed 100"});
  c.push_back({"extreme", "placed at 0 m/s", rig + "--speed 0"});
  c.push_back({"extreme", "1 g of mass", rig + "--speed 1 --mass 0.001"});
  c.push_back({"extreme", "zeta 100 N/cm^3", rig + "--speed 1 --zeta 100"});
  c.push_back({"extreme", "zeta 1e-6 N/cm^3 (never stops)", rig + "--speed 1 --zeta 0.000001"});
  c.push_back({"extreme", "lunar gravity 1.62", rig + "--speed 1 --gravity 1.62"});
  c.push_back({"extreme", "Martian gravity 3.71", rig + "--speed 1 --gravity 3.71"});
  c.push_back({"extreme", "curved pad, 10 m/s, lunar gravity", "drop --pad curved --soil fjs1_lp --speed 10 --gravity 1.62"});
  c.push_back({"extreme", "pad edge-on (tilt 90 deg), 5 mm deep", "force --pad flat --soil fjs1_lp --depth 0.005 --tilt-deg 90"});
  c.push_back({"extreme", "pad nearly edge-on (tilt 89 deg), 5 mm deep",
               "force --pad flat --soil fjs1_lp --depth 0.005 --tilt-deg 89"});
  c.push_back({"extreme", "pad buried 1 m deep", "force --pad flat --soil fjs1_lp --depth 1"});
  c.push_back({"extreme", "pad 1 cm above the surface (depth -0.01)", "force --pad flat --soil fjs1_lp --depth -0.01"});
  // Gnuplot runs without a shell, with paths relative to the output, so an
  // --out with a quote or a shell injection attempt plots like any other (tests/apps/
  // plot_outputs_test.cpp checks the PNGs and that no PWNED file appears); a relative --out; a
  // sweep whose drops all failed plots placeholders instead of an invalid script.
  {
    const std::string trade_sweep =
        Sweep("traces: none\nfixed: {soil: fjs1_lp}\ngrid: {pad: [flat, curved], impact_speed_m_s: [0.7, 1.0]}\n");
    c.push_back({"plot output", "trade --out with a quote", "trade plot_trade.yaml --out \"it's\"",
                 {{"plot_trade.yaml", trade_sweep}}});
    c.push_back({"plot output", "trade --out with a shell injection attempt",
                 "trade plot_trade.yaml --out \"x'; touch PWNED; echo '\"", {{"plot_trade.yaml", trade_sweep}}});
    c.push_back({"plot output", "trade with a relative --out", "trade plot_trade.yaml --out results/pad_trade",
                 {{"plot_trade.yaml", trade_sweep}, {"results/README", "results go here\n"}}});
    c.push_back({"plot output", "trade of a sweep whose drops all failed", "trade plot_failed.yaml --out out_p4",
                 {{"plot_failed.yaml", Sweep(kSweepBase + "grid: {impact_speed_m_s: [1], zeta_N_cm3: [0.000001]}\n")}}});
    c.push_back({"plot output", "campaign --out with a quote", "campaign plot_campaign.yaml --out \"it's campaign\"",
                 {{"plot_campaign.yaml", "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [1.0]}\n"}}});
    c.push_back({"plot output", "lander --out with a shell injection attempt",
                 "lander plot_lander.yaml --out \"y'; touch PWNED; echo '\"",
                 {{"plot_lander.yaml", Lander("lander: sutoh2017_lander\n" + kLanderGround +
                                             "initial: {touchdown_speed_m_s: 1.0}\nsimulation: {duration_s: 0.03}\n")}}});
  }
  // Sweeps: the deterministic per-drop evaluation limit.
  {
    const std::string run = " --threads 1 --progress lines --out ";
    const std::string body = Sweep(kSweepBase + "grid: {impact_speed_m_s: [0.7, 1.5]}\n");
    c.push_back({"sweep YAML", "--max-drop-evaluations 50: every drop over its limit",
                 "sweep evals.yaml --max-drop-evaluations 50" + run + "out_s6_1", {{"evals.yaml", body}}});
    c.push_back({"sweep YAML", "--max-drop-evaluations 2.5", "sweep evals.yaml --max-drop-evaluations 2.5" + run +
                 "out_s6_2", {{"evals.yaml", body}}});
    c.push_back({"sweep YAML", "max_drop_evaluations: -1", "sweep evals.yaml" + run + "out_s6_3",
                 {{"evals.yaml", Sweep("max_drop_evaluations: -1\n" + kSweepBase + "grid: {impact_speed_m_s: [1]}\n")}}});
  }
  AddExitStatusAndInputCases(c);
  AddNewUserDefectCases(c);
  // Targets YAML (calibrate --targets, docs/calibration_targets.md).
  {
    const std::string target = "targets: [{name: d, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1}, quantity: "
                               "final_penetration_m, value: 0.01, uncertainty: 0.001, use: fit, source: s}]\n";
    const auto targets = [&](const std::string& parameter) {
      return "schema_version: 1\ntype: targets\nparameters: [" + parameter + "]\n" + target;
    };
    c.push_back({"targets YAML", "bounds inverted", "calibrate --targets t_bounds.yaml --out t1.yaml",
                 {{"t_bounds.yaml", targets("{name: z, soil: fjs1_lp, field: zeta_N_cm3, lower: 8, upper: 1, start: 3, source: s}")}}});
    c.push_back({"targets YAML", "start outside the bounds", "calibrate --targets t_start.yaml --out t2.yaml",
                 {{"t_start.yaml", targets("{name: z, soil: fjs1_lp, field: zeta_N_cm3, lower: 1, upper: 8, start: 9, source: s}")}}});
    c.push_back({"targets YAML", "unknown pad field", "calibrate --targets t_field.yaml --out t3.yaml",
                 {{"t_field.yaml", targets("{name: a, pad: flat, field: profile.a1_per_mm, lower: 1, upper: 8, start: 3, source: s}")}}});
    c.push_back({"targets YAML", "target names an unknown lander scenario", "calibrate --targets t_lander.yaml --out t4.yaml",
                 {{"t_lander.yaml", "schema_version: 1\ntype: targets\ntargets: [{name: r, lander: lander_case_Q, quantity: "
                                    "final_roll_deg, value: 0, uncertainty: 1, use: fit, source: s}]\n"}}});
  }
  AddMessageCases(c);
  AddFourthRoundCases(c);
  // How the sensors sample (synth's sensor_sampling, diagnose --sensor-sampling).
  c.push_back({"synth YAML", "sensor_sampling: averaged", "synth sampling.synth.yaml --out out_w1",
               {{"sampling.synth.yaml", "schema_version: 1\ntype: synth\nseed: 1\nsensor_sampling: averaged\n"
                                        "drops:\n  - {pads: [flat], soils: [fjs1_lp], impact_speeds_m_s: [1.0]}\n"}}});
  c.push_back({"diagnose", "--sensor-sampling averaged", "diagnose measured --sensor-sampling averaged --out out_w3", {}});
  // Designated training drops (diagnose --fit-on): one not in the dataset, or every drop.
  const std::string fit_drops = kDropsHeader + "d0,flat,fjs1_lp,vacuum,1.0,1.6,9.81,t.csv\n"
                                               "d1,flat,fjs1_lp,vacuum,1.2,1.6,9.81,t.csv\n"
                                               "d2,flat,fjs1_lp,vacuum,1.4,1.6,9.81,t.csv\n";
  c.push_back({"diagnose", "--fit-on a drop not in the dataset", "diagnose ds_fit1 --fit-on d0,d9 --out out_w4",
               Dataset("ds_fit1", fit_drops)});
  c.push_back({"diagnose", "--fit-on every drop (none left to predict)", "diagnose ds_fit2 --fit-on d0,d1,d2 --out out_w5",
               Dataset("ds_fit2", fit_drops)});
  // Unknown options are named before a missing required one; inputs by bundled name.
  c.push_back({"CLI flag", "misspelt option, a required one missing", "drop --sped 1"});
  c.push_back({"CLI flag", "misspelt option as --name=value", "drop --pad flat --soil fjs1_lp --speed=1 --gravty=1.6"});
  c.push_back({"CLI flag", "unknown option before the command", "--verbose drop --pad flat --soil fjs1_lp --speed 1"});
  c.push_back({"CLI flag", "lander scenario by a mistyped name", "lander lander_cas_B --out out_h1"});
  c.push_back({"CLI flag", "stability by a lander scenario's name (not a study)",
               "stability lunar_paper_lander_scenario --out out_h2"});
  // A static bearing (docs/validation.md) whose measured range runs backwards.
  c.push_back({"validation sources", "static bearing pressure range reversed", "validate --sources vb --out out_v3",
               {{"vb/dynamic_rft.yaml", "schema_version: 1\ntype: validation_model\ninertial_drag_lambda: 1.1\nsource: s\n"},
                {"vb/lunar.yaml",
                 "schema_version: 1\ntype: validation_source\nid: lunar\ncitation: c\nread_at: r\nprojectile:\n  pad: " +
                     DataDir() + "/validation/pads/surveyor_flat_disc.yaml\n  description: d\nmedium:\n  soil: " +
                     DataDir() + "/validation/soils/surveyor3_mare_soil.yaml\n  description: d\n  zeta_route: derived\n"
                     "gravity_m_s2: 1.62\nstatic_bearing:\n  - {id: b, pressure_N_cm2: [6, 2], depth_mm: [20, 50], "
                     "diameter_mm: [200, 300], how: quoted, where: w}\n"}}});
  // The shards of a rare-event run share one --out: one split N into another's DIR would wait forever.
  c.push_back({"CLI flag", "stability --method subset --shard 0/3 into an --out holding shard_0_of_2",
               "stability rare.yaml --method subset --samples 10 --shard 0/3 --progress none --out out_t4",
               {{"rare.yaml", "schema_version: 1\ntype: stability\nlander: {scenario: lander_case_A}\n"
                              "random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 10]}}\n"}},
               [](const fs::path& d) {
                 fs::create_directories(d / "out_t4" / "shard_0_of_2");
                 std::ofstream(d / "out_t4" / ".touchdown-output") << "touchdown output\nkind: sweep\n";
               }});
  // The free drops' model of a sweep: a value it does not know, and the fast model on a mesh pad.
  c.push_back({"sweep YAML", "unknown free_drop_model", "sweep fdm.yaml --threads 1 --progress lines --out out_fdm1",
               {{"fdm.yaml", Sweep("simulation: {free_drop_model: quick}\nfixed: {pad: flat, soil: fjs1_lp, "
                                   "impact_speed_m_s: 1}\n")}}});
  c.push_back({"sweep YAML", "free_drop_model fast with a mesh pad",
               "sweep fdm_mesh.yaml --threads 1 --progress lines --out out_fdm2",
               {{"fdm_mesh.yaml", Sweep("simulation: {free_drop_model: fast}\nfixed: {pad: hex, soil: fjs1_lp, "
                                        "impact_speed_m_s: 1}\n")}}});
  return c;
}

// ---- rendering ----------------------------------------------------------------------------

std::string Sig(double v) {
  if (v == 0.0) v = 0.0;  // no "-0"
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", v);
  return s;
}

std::string Replace(std::string s, const std::string& from, const std::string& to) {
  if (from.empty()) return s;
  for (size_t p = 0; (p = s.find(from, p)) != std::string::npos; p += to.size()) s.replace(p, from.size(), to);
  return s;
}

std::string FirstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

// What a successful run produced, in one line.
std::string Outcome(const std::string& args, const CliRun& r) {
  const std::string command = args.substr(0, args.find(' '));
  try {
    if (command == "drop") {
      const auto j = nlohmann::json::parse(r.out);
      return "final penetration " + Sig(j["final_penetration_m"].get<double>() * 1e3) + " mm, peak force " +
             Sig(j["peak_force_N"].get<double>()) + " N, at rest after " +
             Sig(j["time_to_rest_s"].get<double>() * 1e3) + " ms";
    }
    if (command == "force") {
      const auto j = nlohmann::json::parse(r.out);
      double f[3], scale = 0.0;
      for (int k = 0; k < 3; ++k) scale = std::max(scale, std::abs(f[k] = j["force_N"][k].get<double>()));
      // Components at round-off level (1e-9 of the largest) depend on the compiler's operation
      // order: shown as 0 so the table is the same in every build.
      for (double& v : f)
        if (std::abs(v) <= 1e-9 * scale) v = 0.0;
      return "force (" + Sig(f[0]) + ", " + Sig(f[1]) + ", " + Sig(f[2]) + ") N on " +
             Sig(j["submerged_area_m2"].get<double>() * 1e4) + " cm^2";
    }
  } catch (const std::exception& e) {
    return std::string("(unexpected output: ") + e.what() + ")";
  }
  if (command == "sweep") {
    std::smatch m;
    const std::regex totals(R"(: (\d+) drops.*; (\d+) failed)");
    if (!std::regex_search(r.out, m, totals)) return "(no sweep summary)";
    std::string text = m[1].str() + " drops, " + m[2].str() + " failed";
    const std::regex failure(R"(failed: ([^\n]*))");
    if (std::regex_search(r.err, m, failure)) text += "; first: " + m[1].str();
    return text;
  }
  return "ok";
}

std::string Cell(std::string s) {
  s = Replace(s, "|", "\\|");
  return s.empty() ? "(nothing)" : s;
}

}  // namespace

TEST(Robustness, TableOfBadInputsMatchesDocs) {
  Sandbox box("robustness");
  const std::vector<Case> cases = Cases();
  ASSERT_GE(cases.size(), 40u);
  std::string table =
      "| # | input | case | command | exit | what touchdown says or computes |\n"
      "|---|---|---|---|---|---|\n";
  int n = 0;
  for (const Case& c : cases) {
    ++n;
    SCOPED_TRACE(c.what);
    for (const auto& [name, bytes] : c.files) box.Write(name, bytes);
    if (c.setup) c.setup(box.dir());
    const CliRun r = box.Touchdown(c.args);
    // A crash is never an answer; neither is an unexpected status or a multi-line refusal.
    EXPECT_EQ(r.signal, 0) << "touchdown " << c.args << " crashed: " << r.err;
    EXPECT_TRUE(r.status == 0 || r.status == 2 || r.status == 3)
        << "touchdown " << c.args << " exited with " << r.status << ": " << r.err;
    std::string result;
    if (r.status == 0) {
      result = Outcome(c.args, r);
    } else {
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
      result = FirstLine(r.err);
    }
    result = Replace(Replace(result, box.dir().string() + "/", ""), box.dir().string(), ".");
    result = Replace(result, DataDir(), "DATA");
    const std::string status = r.signal ? "signal " + std::to_string(r.signal) : std::to_string(r.status);
    table += "| " + std::to_string(n) + " | " + c.input + " | " + Cell(c.what) + " | `touchdown " + c.args + "` | " +
             status + " | " + Cell(result) + " |\n";
  }

  const std::string doc =
      "# Robustness: bad and extreme inputs\n\n"
      "Generated by `tests/apps/robustness_test.cpp` (do not edit by hand): each row runs the `touchdown`\n"
      "executable on one input, in a scratch directory holding the files the case writes (pads, soils,\n"
      "scenarios, sweeps, models, datasets and meshes, named as in the command). Exit status 0: it ran\n"
      "(the result is summarised); 2: the input was refused with the one line shown on stderr and nothing\n"
      "was written; 3: the integrator failed and says why. No case may crash, hang or print a partial\n"
      "result. Numbers are rounded to three significant digits; DATA is the bundled `data/` directory.\n"
      "Regenerate after a deliberate change with\n"
      "`TOUCHDOWN_UPDATE_DOCS=1 build/tests/apps_hardening_tests --gtest_filter=Robustness.*`;\n"
      "the test fails while this file and the table differ.\n\n"
      "Fuzzing (`tools/run_fuzzers.sh`, one libFuzzer target per parser) covers the inputs no table can\n"
      "list; see the README's Hardening section.\n\n" +
      table;
  const fs::path path = fs::path(TOUCHDOWN_SOURCE_DIR) / "docs" / "robustness.md";
  const char* update = std::getenv("TOUCHDOWN_UPDATE_DOCS");
  if (update && std::string(update) == "1") {
    std::ofstream(path, std::ios::binary) << doc;
    GTEST_SKIP() << "rewrote " << path.string();
  }
  EXPECT_EQ(Slurp(path), doc) << "docs/robustness.md is out of date: rerun with TOUCHDOWN_UPDATE_DOCS=1 "
                                 "(and review the diff)";
}

}  // namespace touchdown::testing_cli

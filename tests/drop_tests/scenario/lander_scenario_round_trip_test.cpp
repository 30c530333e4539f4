// Lander scenarios: the three bundled cases (A, B, C), loaded, written resolved and the resolved
// copy loaded again give the same scenario and the same setup (model, terrain patches and
// soils, release state); a second write is the same text. A resolved copy whose derived values
// no longer match the files it names is refused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

#include <yaml-cpp/yaml.h>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/scenario/lander_outputs.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "rft/input_error.h"
#include "tests/round_trip.h"

namespace touchdown::scenario {
namespace {

namespace fs = std::filesystem;

struct LanderScenarioRoundTrip : testing_scratch::ScratchDirTest {};

void ExpectSameScenario(const LanderScenario& a, const LanderScenario& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(fs::weakly_canonical(a.source), fs::weakly_canonical(b.source));
  EXPECT_EQ(a.gravity_m_s2, b.gravity_m_s2);
  EXPECT_EQ(a.lander.name, b.lander.name);
  EXPECT_EQ(a.lander.total_mass_kg, b.lander.total_mass_kg);
  EXPECT_EQ(a.lander.body_mass_kg, b.lander.body_mass_kg);
  EXPECT_EQ(a.lander.body_inertia_B, b.lander.body_inertia_B);
  EXPECT_EQ(a.lander.pad.name, b.lander.pad.name);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    EXPECT_EQ(a.lander.legs[i].joint_B, b.lander.legs[i].joint_B);
    EXPECT_EQ(a.lander.legs[i].hip_B, b.lander.legs[i].hip_B);
    EXPECT_EQ(a.lander.legs[i].absorber.has_value(), b.lander.legs[i].absorber.has_value());
    EXPECT_EQ(a.lander.legs[i].cone.has_value(), b.lander.legs[i].cone.has_value());
    EXPECT_EQ(a.lander.legs[i].load_limit_N, b.lander.legs[i].load_limit_N);
  }
  EXPECT_EQ(a.ground.height_m, b.ground.height_m);
  EXPECT_EQ(a.ground.slope_rad, b.ground.slope_rad);
  EXPECT_EQ(a.ground.downhill_azimuth_rad, b.ground.downhill_azimuth_rad);
  EXPECT_EQ(a.ground.law, b.ground.law);
  EXPECT_EQ(a.ground.default_soil, b.ground.default_soil);
  EXPECT_EQ(a.initial.drop_height_m, b.initial.drop_height_m);
  EXPECT_EQ(a.initial.touchdown_speed_m_s, b.initial.touchdown_speed_m_s);
  EXPECT_EQ(a.initial.release_vertical_speed_m_s, b.initial.release_vertical_speed_m_s);
  EXPECT_EQ(a.initial.horizontal_velocity_m_s, b.initial.horizontal_velocity_m_s);
  EXPECT_EQ(a.initial.roll_rad, b.initial.roll_rad);
  EXPECT_EQ(a.initial.pitch_rad, b.initial.pitch_rad);
  EXPECT_EQ(a.initial.yaw_relative_to_slope_rad, b.initial.yaw_relative_to_slope_rad);
  EXPECT_EQ(a.initial.align_to_slope, b.initial.align_to_slope);
  EXPECT_EQ(a.initial.angular_rate_B, b.initial.angular_rate_B);
  EXPECT_EQ(a.initial.pad_attitude, b.initial.pad_attitude);
  EXPECT_EQ(a.options.duration_s, b.options.duration_s);
  EXPECT_EQ(a.options.sample_rate_hz, b.options.sample_rate_hz);
  EXPECT_EQ(a.options.capture_speed_m_s, b.options.capture_speed_m_s);
  EXPECT_EQ(a.options.scale_tolerances, b.options.scale_tolerances);
  EXPECT_EQ(a.options.integrator.rtol, b.options.integrator.rtol);
  EXPECT_EQ(a.options.integrator.max_step, b.options.integrator.max_step);
  EXPECT_EQ(a.options.integrator.stiff, b.options.integrator.stiff);
  EXPECT_EQ(a.options.pad_spin_tolerance_factor, b.options.pad_spin_tolerance_factor);
  EXPECT_EQ(a.pad_angular_segments, b.pad_angular_segments);
  EXPECT_EQ(a.lander.pad.body.surface.size(), b.lander.pad.body.surface.size());
  EXPECT_EQ(a.paper_ground_case, b.paper_ground_case);
  ASSERT_EQ(a.paper.has_value(), b.paper.has_value());
  if (a.paper) {
    EXPECT_EQ(a.paper->roll_pitch_within_deg, b.paper->roll_pitch_within_deg);
    EXPECT_EQ(a.paper->source, b.paper->source);
    EXPECT_EQ(a.paper->used_for_fit, b.paper->used_for_fit);
    EXPECT_EQ(a.paper->fit_by, b.paper->fit_by);
    EXPECT_EQ(a.paper->reading, b.paper->reading);
  }
  // The setup the run starts from: patches resolved to the same corners, the same soils and pose.
  const lander::LanderSetup p = ResolveLander(a), q = ResolveLander(b);
  ASSERT_EQ(p.terrain.patches.size(), q.terrain.patches.size());
  for (size_t k = 0; k < p.terrain.patches.size(); ++k) {
    EXPECT_EQ(p.terrain.patches[k].name, q.terrain.patches[k].name);
    EXPECT_EQ(p.terrain.patches[k].soil, q.terrain.patches[k].soil);
    EXPECT_EQ(p.terrain.patches[k].polygon_W, q.terrain.patches[k].polygon_W);
  }
  ASSERT_EQ(p.terrain.soils.size(), q.terrain.soils.size());
  for (size_t k = 0; k < p.terrain.soils.size(); ++k) EXPECT_EQ(p.terrain.soils[k].name, q.terrain.soils[k].name);
  EXPECT_EQ(p.initial.p_WB, q.initial.p_WB);
  EXPECT_EQ(p.initial.v_WB_W, q.initial.v_WB_W);
  EXPECT_EQ(p.initial.R_WB, q.initial.R_WB);
  EXPECT_EQ(p.model.body_mass_kg, q.model.body_mass_kg);
}

// A scenario of `head` and `simulation: <simulation>`, written to `path`, that the loader must refuse
// naming simulation.<field> and saying `says`.
void ExpectSimulationRefused(const std::string& path, const std::string& head, const std::string& simulation,
                             const std::string& field, const std::string& says) {
  std::ofstream(path) << head << "simulation: " << simulation << "\n";
  try {
    LoadLanderScenario(path);
    ADD_FAILURE() << simulation << " accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("simulation." + field), std::string::npos) << what;
    EXPECT_NE(what.find(says), std::string::npos) << what;
  }
}

void RoundTripLanderScenario(const std::string& source, const std::string& first, const std::string& second) {
  const std::string out = fs::path(first).parent_path().string();
  testing_scratch::ExpectRoundTrip(
      LoadLanderScenario(source), first, second,
      [&](const LanderScenario& s, const std::string& path) { WriteResolvedLanderScenario(s, path, out); },
      LoadLanderScenario, ExpectSameScenario);
}

TEST_F(LanderScenarioRoundTrip, BundledCases) {
  for (const char* c : {"A", "B", "C"}) {
    SCOPED_TRACE(c);
    const std::string name = std::string("lander_case_") + c;
    RoundTripLanderScenario(io::DataDirectory() + "/scenarios/" + name + ".yaml", Path(name + "_1.yaml"), Path(name + "_2.yaml"));
    EXPECT_NE(Slurp(Path(name + "_1.yaml")).find("roll_pitch_within_deg: 0.5"), std::string::npos);
  }
}

TEST_F(LanderScenarioRoundTrip, OptionsAndAttitude) {
  std::ofstream(Path("tilted.yaml")) << "schema_version: 1\ntype: lander\nname: tilted\nlander: sutoh2017_lander\n"
                                        "gravity_m_s2: 1.62\n"
                                        "ground: {slope_deg: 7.5, downhill_azimuth_deg: 30, soil: fjs1_cp,\n"
                                        "  patches: [{soil: fjs1_lp, rectangle_m: [-1, -1, 0, 0]}]}\n"
                                        "initial: {touchdown_speed_m_s: 1.2, horizontal_velocity_m_s: [0.3, -0.1],\n"
                                        "  roll_deg: 2.5, yaw_relative_to_slope_deg: 45, align_to_slope: true}\n"
                                        "simulation: {duration_s: 0.5, sample_rate_hz: 500, atol: 1e-8,"
                                        " max_step_s: 0.001, stiff: true}\n";
  fs::create_directories(dir_ / "out");
  RoundTripLanderScenario(Path("tilted.yaml"), Path("out/tilted_1.yaml"), Path("out/tilted_2.yaml"));
  const std::string text = Slurp(Path("out/tilted_1.yaml"));
  EXPECT_NE(text.find("max_step_s: 0.001"), std::string::npos);
  EXPECT_NE(text.find("source: ../tilted.yaml"), std::string::npos);
}

// The `initial` block is read and written from one key list: a resolved copy writes its keys in
// that list's order and nothing else, and a copy from a drop height and one from a touchdown speed
// write every key of it between them.
TEST_F(LanderScenarioRoundTrip, InitialBlockIsWrittenFromTheKeysItIsReadWith) {
  std::ofstream(Path("speed.yaml")) << "schema_version: 1\ntype: lander\nname: speed\nlander: sutoh2017_lander\n"
                                       "ground: {soil: fjs1_lp}\ninitial: {touchdown_speed_m_s: 1.2, pitch_deg: 3}\n";
  std::ofstream(Path("height.yaml")) << "schema_version: 1\ntype: lander\nname: height\nlander: sutoh2017_lander\n"
                                        "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n";
  const std::vector<std::string>& keys = LanderInitialKeys();
  std::set<std::string> written;
  for (const char* name : {"speed", "height"}) {
    SCOPED_TRACE(name);
    const std::string copy = Path(std::string(name) + "_resolved.yaml");
    WriteResolvedLanderScenario(LoadLanderScenario(Path(std::string(name) + ".yaml")), copy, dir_.string());
    size_t at = 0;  // the keys come in the list's order
    for (const auto& kv : YAML::LoadFile(copy)["initial"]) {
      const std::string key = kv.first.as<std::string>();
      const auto it = std::find(keys.begin() + at, keys.end(), key);
      ASSERT_NE(it, keys.end()) << key << " is written out of order or is not in LanderInitialKeys";
      at = static_cast<size_t>(it - keys.begin()) + 1;
      written.insert(key);
    }
  }
  EXPECT_EQ(written, std::set<std::string>(keys.begin(), keys.end()));
}

// simulation.pad_angular_segments re-meshes the lander's revolved pads (a resolution, like rtol): the
// lander keeps its mass, CoG and joints; the resolved copy says it and loads to the same pads.
TEST_F(LanderScenarioRoundTrip, PadAngularSegmentsReMeshTheLandersPads) {
  const std::string head = "schema_version: 1\ntype: lander\nname: coarse\nlander: sutoh2017_lander\n"
                           "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n";
  std::ofstream(Path("fine.yaml")) << head;
  std::ofstream(Path("coarse.yaml")) << head << "simulation: {pad_angular_segments: 32}\n";
  const LanderScenario fine = LoadLanderScenario(Path("fine.yaml"));
  const LanderScenario coarse = LoadLanderScenario(Path("coarse.yaml"));
  EXPECT_EQ(fine.pad_angular_segments, 0);
  EXPECT_EQ(coarse.pad_angular_segments, 32);
  EXPECT_EQ(coarse.lander.pad.body.surface.size(),
            io::PadWithAngularSegments(fine.lander.pad, 32).body.surface.size());
  EXPECT_LT(3 * coarse.lander.pad.body.surface.size(), fine.lander.pad.body.surface.size());
  EXPECT_EQ(coarse.lander.body_mass_kg, fine.lander.body_mass_kg);
  for (int i = 0; i < lander::kNumLegs; ++i) EXPECT_EQ(coarse.lander.legs[i].joint_B, fine.lander.legs[i].joint_B);
  fs::create_directories(dir_ / "out");
  RoundTripLanderScenario(Path("coarse.yaml"), Path("out/coarse_1.yaml"), Path("out/coarse_2.yaml"));
  EXPECT_NE(Slurp(Path("out/coarse_1.yaml")).find("pad_angular_segments: 32"), std::string::npos);
  // A study's reference model undoes the re-meshing: the pads as their file says.
  EXPECT_EQ(coarse.pad_file_angular_segments, io::PadRimSegments(fine.lander.pad));
  const LanderScenario as_file = AtPadFileMesh(coarse);
  EXPECT_EQ(as_file.pad_angular_segments, 0);
  EXPECT_EQ(as_file.lander.pad.body.surface.size(), fine.lander.pad.body.surface.size());
  EXPECT_EQ(as_file.lander.body_mass_kg, fine.lander.body_mass_kg);
  EXPECT_EQ(AtPadFileMesh(fine).lander.pad.body.surface.size(), fine.lander.pad.body.surface.size());

  std::ofstream(Path("bad.yaml")) << head << "simulation: {pad_angular_segments: 3}\n";
  try {
    LoadLanderScenario(Path("bad.yaml"));
    ADD_FAILURE() << "3 segments accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("simulation.pad_angular_segments"), std::string::npos) << what;
    EXPECT_NE(what.find("at least 6, got 3"), std::string::npos) << what;
  }
}

// The largest distance of a pad vertex from the pad's axis (z_B through the frame's origin).
double RimRadius(const LanderScenario& s) {
  const Eigen::Matrix3Xd& v = s.lander.pad.body.vertices_B;
  return v.topRows<2>().colwise().norm().maxCoeff();
}

// simulation.pad_rim: area_preserving re-meshes the pads with every ring scaled to its circle's
// area; the resolved copy says it and loads to the
// same pads, the reference model (AtPadFileMesh) is inscribed again, and the rim is refused without
// pad_angular_segments or with an unknown name.
TEST_F(LanderScenarioRoundTrip, PadRimAreaPreservingIsAReMeshing) {
  const std::string head = "schema_version: 1\ntype: lander\nname: coarse\nlander: sutoh2017_lander\n"
                           "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n";
  std::ofstream(Path("plain.yaml")) << head << "simulation: {pad_angular_segments: 16}\n";
  std::ofstream(Path("inscribed.yaml")) << head << "simulation: {pad_angular_segments: 16, pad_rim: inscribed}\n";
  std::ofstream(Path("area.yaml")) << head << "simulation: {pad_angular_segments: 16, pad_rim: area_preserving}\n";
  const LanderScenario plain = LoadLanderScenario(Path("plain.yaml"));
  const LanderScenario inscribed = LoadLanderScenario(Path("inscribed.yaml"));
  const LanderScenario area = LoadLanderScenario(Path("area.yaml"));
  EXPECT_EQ(plain.pad_rim, geom::RimPolygon::kInscribed);
  EXPECT_EQ(inscribed.pad_rim, geom::RimPolygon::kInscribed);
  EXPECT_EQ(area.pad_rim, geom::RimPolygon::kAreaPreserving);
  EXPECT_EQ(area.lander.pad.rim, geom::RimPolygon::kAreaPreserving);
  ASSERT_EQ(plain.lander.pad.body.surface.size(), inscribed.lander.pad.body.surface.size());
  EXPECT_EQ(plain.lander.pad.body.vertices_B, inscribed.lander.pad.body.vertices_B);
  // sutoh2017_footpad (flat, r = 27.5 mm): the rim at r, or at r sqrt((2 pi / 16) / sin(2 pi / 16)).
  EXPECT_NEAR(RimRadius(plain), 0.0275, 1e-15);
  EXPECT_NEAR(RimRadius(area), 0.0275 * geom::AreaPreservingRadiusScale(16), 1e-15);
  EXPECT_EQ(area.lander.body_mass_kg, plain.lander.body_mass_kg);
  fs::create_directories(dir_ / "out");
  RoundTripLanderScenario(Path("area.yaml"), Path("out/area_1.yaml"), Path("out/area_2.yaml"));
  EXPECT_NE(Slurp(Path("out/area_1.yaml")).find("pad_rim: area_preserving"), std::string::npos);
  EXPECT_EQ(LoadLanderScenario(Path("out/area_1.yaml")).lander.pad.body.vertices_B, area.lander.pad.body.vertices_B);
  // The default writes nothing new: a plain re-meshing's resolved copy has no pad_rim.
  RoundTripLanderScenario(Path("plain.yaml"), Path("out/plain_1.yaml"), Path("out/plain_2.yaml"));
  EXPECT_EQ(Slurp(Path("out/plain_1.yaml")).find("pad_rim"), std::string::npos);
  const LanderScenario as_file = AtPadFileMesh(area);
  EXPECT_EQ(as_file.pad_rim, geom::RimPolygon::kInscribed);
  EXPECT_EQ(as_file.lander.pad.rim, geom::RimPolygon::kInscribed);
  EXPECT_EQ(as_file.lander.pad.body.vertices_B, AtPadFileMesh(plain).lander.pad.body.vertices_B);

  const auto refused = [&](const std::string& simulation, const std::string& says) {
    ExpectSimulationRefused(Path("bad.yaml"), head, simulation, "pad_rim", says);
  };
  refused("{pad_rim: area_preserving}", "needs pad_angular_segments");
  refused("{pad_angular_segments: 16, pad_rim: circumscribed}", "must be 'inscribed' or 'area_preserving'");
}

// simulation.pad_spin_tolerance_factor (the studies' fast model) reaches the run's options, the
// resolved copy says it (and nothing when it is the default), and it is refused outside [1, 1000]
// and beside a scalar atol, which has no per-state scale to multiply.
TEST_F(LanderScenarioRoundTrip, PadSpinToleranceFactorIsAnOptionOfTheRun) {
  const std::string head = "schema_version: 1\ntype: lander\nname: spin\nlander: sutoh2017_lander\n"
                           "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n";
  std::ofstream(Path("loose.yaml")) << head << "simulation: {rtol: 1.0e-5, pad_spin_tolerance_factor: 30}\n";
  std::ofstream(Path("plain.yaml")) << head << "simulation: {rtol: 1.0e-5}\n";
  EXPECT_EQ(LoadLanderScenario(Path("loose.yaml")).options.pad_spin_tolerance_factor, 30.0);
  EXPECT_EQ(LoadLanderScenario(Path("plain.yaml")).options.pad_spin_tolerance_factor, 1.0);
  fs::create_directories(dir_ / "out");
  RoundTripLanderScenario(Path("loose.yaml"), Path("out/loose_1.yaml"), Path("out/loose_2.yaml"));
  EXPECT_NE(Slurp(Path("out/loose_1.yaml")).find("pad_spin_tolerance_factor: 30"), std::string::npos);
  EXPECT_EQ(LoadLanderScenario(Path("out/loose_1.yaml")).options.pad_spin_tolerance_factor, 30.0);
  RoundTripLanderScenario(Path("plain.yaml"), Path("out/plain_1.yaml"), Path("out/plain_2.yaml"));
  EXPECT_EQ(Slurp(Path("out/plain_1.yaml")).find("pad_spin_tolerance_factor"), std::string::npos);

  const auto refused = [&](const std::string& simulation, const std::string& says) {
    ExpectSimulationRefused(Path("bad.yaml"), head, simulation, "pad_spin_tolerance_factor", says);
  };
  refused("{pad_spin_tolerance_factor: 0.5}", "0.5");
  refused("{pad_spin_tolerance_factor: 2000}", "2000");
  refused("{atol: 1.0e-9, pad_spin_tolerance_factor: 30}", "needs the scaled tolerances");
}

TEST_F(LanderScenarioRoundTrip, APaperCheckUsedForAFitSaysByWhat) {
  const std::string head = "schema_version: 1\ntype: lander\nname: fitted\nlander: sutoh2017_lander\n"
                           "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n";
  std::ofstream(Path("fitted.yaml")) << head << "paper: {roll_pitch_within_deg: 0.5, source: s, used_for_fit: true,"
                                                " fit_by: data/targets/sutoh2017.yaml}\n";
  fs::create_directories(dir_ / "out");
  RoundTripLanderScenario(Path("fitted.yaml"), Path("out/fitted_1.yaml"), Path("out/fitted_2.yaml"));
  const LanderScenario s = LoadLanderScenario(Path("fitted.yaml"));
  ASSERT_TRUE(s.paper.has_value());
  EXPECT_TRUE(s.paper->used_for_fit);
  EXPECT_EQ(s.paper->fit_by, "data/targets/sutoh2017.yaml");
  EXPECT_FALSE(LoadLanderScenario(io::DataDirectory() + "/scenarios/lander_case_B.yaml").paper->used_for_fit);
  // used_for_fit needs its fit_by, and fit_by its used_for_fit: true.
  for (const char* paper : {"{roll_pitch_within_deg: 0.5, used_for_fit: true}", "{roll_pitch_within_deg: 0.5, fit_by: x}",
                            "{ground_case: A, used_for_fit: false}"}) {
    std::ofstream(Path("bad.yaml")) << head << "paper: " << paper << "\n";
    EXPECT_THROW(LoadLanderScenario(Path("bad.yaml")), InputError) << paper;
  }
}

// The lander's paper check names the reading of the paper's LP/CP sentence it compares with: the
// shipped cases the default R1z; the resolved copy and the summary's paper_check carry it; an
// unknown reading, or one without the check it marks, is refused naming the field.
TEST_F(LanderScenarioRoundTrip, APaperCheckNamesItsReading) {
  for (const char* c : {"A", "B", "C"}) {
    const LanderScenario s = LoadLanderScenario(io::DataDirectory() + "/scenarios/lander_case_" + c + ".yaml");
    ASSERT_TRUE(s.paper.has_value()) << c;
    EXPECT_EQ(s.paper->reading, PaperReading::kR1z) << c;
  }
  const std::string head = "schema_version: 1\ntype: lander\nname: read\nlander: sutoh2017_lander\n"
                           "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n";
  std::ofstream(Path("r1.yaml")) << head << "paper: {roll_pitch_within_deg: 0.5, source: s, reading: R1}\n";
  fs::create_directories(dir_ / "out");
  RoundTripLanderScenario(Path("r1.yaml"), Path("out/r1_1.yaml"), Path("out/r1_2.yaml"));
  const LanderScenario s = LoadLanderScenario(Path("r1.yaml"));
  ASSERT_TRUE(s.paper.has_value());
  EXPECT_EQ(s.paper->reading, PaperReading::kR1);
  EXPECT_EQ(LanderPaperCheckJson(*s.paper, 0.1, -0.2).at("reading"), "R1");
  LanderPaperCheck none = *s.paper;
  none.reading.reset();
  EXPECT_FALSE(LanderPaperCheckJson(none, 0.1, -0.2).contains("reading"));
  for (const char* paper : {"{roll_pitch_within_deg: 0.5, reading: R5}", "{roll_pitch_within_deg: 0.5, reading: r1z}",
                            "{ground_case: A, reading: R1}"}) {
    std::ofstream(Path("bad.yaml")) << head << "paper: " << paper << "\n";
    try {
      LoadLanderScenario(Path("bad.yaml"));
      ADD_FAILURE() << paper << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("paper.reading"), std::string::npos) << e.what();
    }
  }
}

TEST_F(LanderScenarioRoundTrip, ResolvedCopyMustMatchItsFiles) {
  WriteResolvedLanderScenario(LoadLanderScenario(io::DataDirectory() + "/scenarios/lander_case_B.yaml"),
                              Path("resolved.yaml"), dir_.string());
  std::string text = Slurp(Path("resolved.yaml"));
  const std::string from = "body_mass_kg: 3.98", to = "body_mass_kg: 3.99";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), to);
  std::ofstream(Path("edited.yaml")) << text;
  try {
    LoadLanderScenario(Path("edited.yaml"));
    FAIL() << "an edited derived value was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lander.body_mass_kg"), std::string::npos) << e.what();
  }
}


// A resolved copy is checked on the setup it builds, and that setup comes back for its landing
// (built once): the one ResolveLander gives the loaded scenario. A scenario file builds none.
TEST_F(LanderScenarioRoundTrip, ResolvedCopyHandsBackItsSetup) {
  const std::string source = io::DataDirectory() + "/scenarios/lander_case_B.yaml";
  std::optional<lander::LanderSetup> setup;
  LanderScenario s = LoadLanderScenarioWithSetup(source, setup);
  EXPECT_FALSE(setup.has_value());
  s.initial.pad_attitude = PadAttitude::kLevel;  // written as its word, read back to the enum
  WriteResolvedLanderScenario(s, Path("resolved.yaml"), dir_.string());
  EXPECT_NE(Slurp(Path("resolved.yaml")).find("pad_attitude: level"), std::string::npos);
  const LanderScenario again = LoadLanderScenarioWithSetup(Path("resolved.yaml"), setup);
  EXPECT_EQ(again.initial.pad_attitude, PadAttitude::kLevel);
  ASSERT_TRUE(setup.has_value());
  const lander::LanderSetup built = ResolveLander(again);
  EXPECT_EQ(setup->initial.p_WB, built.initial.p_WB);
  EXPECT_EQ(setup->initial.R_WP, built.initial.R_WP);
  ASSERT_EQ(setup->terrain.patches.size(), built.terrain.patches.size());
  for (size_t k = 0; k < built.terrain.patches.size(); ++k)
    EXPECT_EQ(setup->terrain.patches[k].polygon_W, built.terrain.patches[k].polygon_W);
  ASSERT_EQ(setup->terrain.soils.size(), built.terrain.soils.size());
  for (size_t k = 0; k < built.terrain.soils.size(); ++k)
    EXPECT_EQ(setup->terrain.soils[k].name, built.terrain.soils[k].name);
}

}  // namespace
}  // namespace touchdown::scenario

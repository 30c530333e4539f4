// The two things the command line does first, from C++: the soil's force on a pad held in the
// soil (`touchdown force --pad flat --soil fjs1_lp --depth 0.02`) and one drop on the paper's rig
// (`touchdown drop --pad flat --soil fjs1_lp --speed 1`). Prints both as one JSON object, with the
// same fields and numbers as the command line prints.
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include <drop_tests/drop/drop_setup.h>
#include <drop_tests/drop/pad_drop.h>
#include <drop_tests/catalog/catalog.h>
#include <lander/integ/cvode_integrator.h>
#include <lander/pad/pad_pose.h>
#include <rft/contact_wrench.h>
#include <rft/gravity_constants.h>
#include <rft/ground.h>
#include <rft/input_error.h>
#include <rft/stress_law_3d_factory.h>

namespace td = touchdown;

// The soil's quasi-static RFT wrench on the pad with its lowest point `depth_m` below a level
// surface, the pad moving straight down: its stresses depend on the direction of motion, not its
// speed, so the soil's rate-dependent dynamic term is left out (as `touchdown force` without
// --dynamic).
nlohmann::json ForceAtDepth(const td::io::PadSpec& pad, td::rft::SoilParameters soil, double depth_m) {
  const double gravity_m_s2 = td::rft::kEarthGravity_m_s2;
  soil.dynamic_term = false;
  const td::rft::SoilContactModel contact =
      td::rft::MakeSoilContactModel(td::rft::LawKind::kLi2013, soil, gravity_m_s2, {});
  const td::rft::StressLaw3D& law = *contact.law;
  td::rft::PadKinematics k;
  k.R_WB = td::pad::TiltRotation(td::pad::TiltAxis::kX, 0.0);
  k.v_WB_W = Eigen::Vector3d(0.0, 0.0, -1.0);
  k.p_WB = td::pad::PlaceAtDepth(pad.body, k.R_WB, depth_m);
  const td::rft::ContactWrench w = td::rft::ComputeContactWrench(pad.body.surface, k, td::rft::PlaneGround(), law);
  return {{"depth_m", depth_m},
          {"force_N", {w.force_W.x(), w.force_W.y(), w.force_W.z()}},
          {"submerged_area_m2", w.submerged_area_m2}};
}

int main(int argc, char** argv) {
  // Catalogue files by path; a name ("flat") would be looked up in $TOUCHDOWN_DATA_DIR.
  const std::string data = argc > 1 ? argv[1] : TOUCHDOWN_PACKAGE_DATA_DIR;
  try {
    const td::io::PadSpec pad = td::io::LoadPad(data + "/pads/flat.yaml");
    const td::rft::SoilParameters soil = td::io::LoadSoil(data + "/soils/fjs1_lp.yaml");

    td::drop::DropConditions conditions;
    conditions.impact_speed_m_s = 1.0;
    td::drop::ValidateConditions(conditions, "cpp_consumer");
    const td::drop::PadDrop drop = td::drop::RunDrop(td::drop::ResolveDrop(pad, soil, conditions));

    const nlohmann::json out{{"force", ForceAtDepth(pad, soil, 0.02)}, {"drop", td::drop::SummaryJson(drop)}};
    std::cout << out.dump(2) << std::endl;
  } catch (const td::InputError& e) {  // a bad file or value: exit 2, as the command line
    std::cerr << "cpp_consumer: " << e.what() << "\n";
    return 2;
  } catch (const td::integ::IntegrationFailure& e) {  // the solver failed: 3
    std::cerr << "cpp_consumer: " << e.what() << "\n";
    return 3;
  }
  return 0;
}

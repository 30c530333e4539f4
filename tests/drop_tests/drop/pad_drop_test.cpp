// One drop from the catalogue's pads: what the drop layer refuses before it simulates.
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"

#include <gtest/gtest.h>

#include <string>

#include "drop_tests/catalog/catalog.h"
#include "rft/input_error.h"

namespace touchdown::drop {
namespace {

TEST(PadDrop, RigDropOfAMeshPadIsRefused) {
  const io::PadSpec hex = io::LoadPad("hex");
  DropConditions conditions;
  conditions.impact_speed_m_s = 1.0;
  try {
    RunDrop(ResolveDrop(hex, io::LoadSoil("fjs1_lp"), conditions));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hex.yaml: a mesh pad drops only as a free pad"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace touchdown::drop

// The free drops' fast model (drop_factory.h, FreeDropModel; `touchdown drop --free --fast`): its
// answers against the reference model's within the studies' accuracy contract (final depth within
// 2 %, final tilt within 0.1 deg), the resolution it runs at, and the requests it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_request.h"
#include "rft/input_error.h"

namespace touchdown::drop {
namespace {

// The contract a study asks of a fast model (docs/stability_studies.md, "Fast model and re-checks").
constexpr double kDepthContract = 0.02;     // relative
constexpr double kTiltContract_deg = 0.1;

DropRequest FreeRequest(const std::string& pad, double tilt_deg, double horizontal_m_s, bool fast) {
  DropRequest r;
  r.pad = pad;
  r.soil = "fjs1_lp";
  r.speed_m_s = 1.0;
  r.free = true;
  r.tilt_deg = tilt_deg;
  r.horizontal_speed_m_s = horizontal_m_s;
  r.fast = fast;
  return r;
}

PadDrop Run(const DropRequest& r) {
  const RequestNaming naming;
  const io::PadSpec pad = RequestPad(r, naming);
  return RunDrop(ResolveDropRequest(r, pad, RequestConditions(r, naming), naming));
}

void ExpectWithinContract(const std::string& pad, double tilt_deg, double horizontal_m_s) {
  const PadDrop reference = Run(FreeRequest(pad, tilt_deg, horizontal_m_s, false));
  const PadDrop fast = Run(FreeRequest(pad, tilt_deg, horizontal_m_s, true));
  ASSERT_TRUE(reference.free && fast.free);
  const double depth = reference.free->final_penetration_m;
  EXPECT_NEAR(fast.free->final_penetration_m, depth, kDepthContract * depth);
  EXPECT_NEAR(fast.free->final_tilt_deg, reference.free->final_tilt_deg, kTiltContract_deg);
  // What it is for: fewer steps (rtol 1e-5), each on a tenth of the triangles.
  EXPECT_LT(fast.free->solver.steps, reference.free->solver.steps);
}

TEST(FreeDropFastModel, TiltedDropWithinTheContractOfTheReference) {
  // Flat pad tilted 5 deg at 1 m/s: measured 0.39 % deeper and 0.045 deg more tilted than the
  // reference at rtol 1e-9 (docs/lander_dynamics.md, "The free drops' fast model").
  ExpectWithinContract("flat", 5.0, 0.0);
}

TEST(FreeDropFastModel, SlidingDropWithinTheContractOfTheReference) {
  // Flat pad sliding at 0.5 m/s: measured 0.06 % and 0.001 deg.
  ExpectWithinContract("flat", 0.0, 0.5);
}

TEST(FreeDropFastModel, CurvedPadTiltedAndSlidingWithinTheContractOfTheReference) {
  // The curved pad tilted 10 deg and sliding at 0.3 m/s: measured 0.16 % and 0.010 deg.
  ExpectWithinContract("curved", 10.0, 0.3);
}

TEST(FreeDropFastModel, RunsAtItsStatedResolution) {
  const io::PadSpec flat = io::LoadPad("flat");
  const io::PadSpec fast = FreeDropPad(flat, FreeDropModel::kFast, "test", "fast");
  EXPECT_EQ(io::PadRimSegments(fast), kFastFreeDropRimSegments);
  EXPECT_EQ(fast.rim, geom::RimPolygon::kAreaPreserving);
  EXPECT_EQ(fast.mass_kg, flat.mass_kg);
  // 16 segments: the rim ring, the rings halved towards the axis, the top disc (geom::RevolveProfileToMesh).
  EXPECT_EQ(fast.body.surface.size(), 160u);
  EXPECT_EQ(FreeDropOptionsFor(FreeDropModel::kFast).integrator.rtol, kFastFreeDropRtol);
  // The reference is the pad as its file meshes it and the free drop's own options.
  const io::PadSpec same = FreeDropPad(flat, FreeDropModel::kReference, "test", "fast");
  EXPECT_EQ(same.body.surface.size(), flat.body.surface.size());
  EXPECT_EQ(FreeDropOptionsFor(FreeDropModel::kReference).integrator.rtol, pad::FreeDropOptions{}.integrator.rtol);
}

std::string Refusal(const DropRequest& r, const RequestNaming& naming) {
  try {
    const DropConditions c = RequestConditions(r, naming);
    ResolveDropRequest(r, RequestPad(r, naming), c, naming);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FreeDropFastModel, FastNeedsTheFreePad) {
  DropRequest r = FreeRequest("flat", 0.0, 0.0, true);
  r.free = false;
  EXPECT_EQ(Refusal(r, RequestNaming{}),
            "command line: --fast: needs --free (the fast model is the free pad's; the rig drop is one DOF)");
  const RequestNaming python{"touchdown.drop", false};
  EXPECT_EQ(Refusal(r, python),
            "touchdown.drop: fast: needs free (the fast model is the free pad's; the rig drop is one DOF)");
}

TEST(FreeDropFastModel, RefusesAMeshPad) {
  // A mesh pad's file fixes its mesh: there is no coarser one to run.
  EXPECT_EQ(Refusal(FreeRequest("hex", 5.0, 0.0, true), RequestNaming{}),
            "command line: --fast: pad 'hex' is a mesh: the fast model re-meshes revolved pads only");
}

}  // namespace
}  // namespace touchdown::drop

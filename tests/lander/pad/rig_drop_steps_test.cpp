// The dynamic term on a sampled smooth pad (the exponential curved pad): its I_3(d) must be
// smooth through the sample points, or the integrator cuts its step at each of the hundreds of
// joints the stroke crosses. Step counts are deterministic, so their ratio is asserted; the
// answers must stay those of the polyline's exact chord integral to the integration tolerance.
#include <gtest/gtest.h>

#include <cmath>

#include "footpad_geom/axisymmetric_intrusion.h"
#include "footpad_geom/axisymmetric_profile.h"
#include "lander/pad/effect_soil_response.h"
#include "lander/pad/rig_drop.h"
#include "rft/stress_law.h"
#include "tests/lander/pad/test_rig.h"

namespace touchdown::pad {
namespace rig_drop_steps {

using namespace test_rig;
constexpr double kRho = 1540.0, kLambda = 1.1;  // fjs1_lp's bulk density and dynamic lambda
constexpr double kThickness = 0.016, kA1 = 31.901;  // data/pads/curved.yaml, 400 rings
const rft::Li2013Law kLaw;

geom::AxisymmetricProfile Curved() {
  return geom::MakeExponentialProfile(kR, kThickness, kThickness / std::expm1(kA1 * kR), kA1, 400);
}

// The same polyline with every joint taken as a corner: the chords' exact integral.
geom::AxisymmetricProfile AsCorners(geom::AxisymmetricProfile p) {
  for (geom::ProfilePoint& q : p.points) q.smooth = false;
  return p;
}

RigDropResult Drop(const geom::AxisymmetricIntrusion& pad, double zeta, double lambda, double speed) {
  rft::EffectTerms terms;
  terms.inertial_lambda = lambda;
  const EffectSoilResponse response(pad, {zeta, kRho, false, terms});
  return RunRig(response, kMass, kG, speed);
}

double Relative(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

TEST(RigDropSteps, DynamicTermOnTheCurvedPadTakesAboutTheQuasiStaticSteps) {
  const geom::AxisymmetricIntrusion pad(Curved(), kLaw);
  for (double zeta : {3.48e6, 7.0e6})
    for (double speed : {0.7, 1.0, 1.5}) {
      const long dynamic = Drop(pad, zeta, kLambda, speed).solver.steps;
      const long quasi_static = Drop(pad, zeta, 0.0, speed).solver.steps;
      EXPECT_LE(dynamic, 1.3 * quasi_static) << "zeta " << zeta << " speed " << speed;
    }
}

TEST(RigDropSteps, SmoothJointsKeepThePolylineAnswers) {
  const geom::AxisymmetricIntrusion smooth(Curved(), kLaw), corners(AsCorners(Curved()), kLaw);
  for (double speed : {0.7, 1.0, 1.5}) {
    const RigDropResult a = Drop(smooth, 3.48e6, kLambda, speed), b = Drop(corners, 3.48e6, kLambda, speed);
    EXPECT_LT(Relative(a.final_penetration_m, b.final_penetration_m), 1e-8) << speed;
    EXPECT_LT(Relative(a.peak_force_N, b.peak_force_N), 1e-8) << speed;
    EXPECT_LT(Relative(a.time_to_rest_s, b.time_to_rest_s), 1e-8) << speed;
    // The cause: the chords' kinks cost the polyline several times the steps.
    EXPECT_GT(b.solver.steps, 4 * a.solver.steps) << speed;
  }
}

TEST(RigDropSteps, CosineIntegralIsSmoothThroughSampledJointsAndExactAtCorners) {
  const geom::AxisymmetricProfile profile = Curved();
  const geom::AxisymmetricIntrusion smooth(profile, kLaw), corners(AsCorners(profile), kLaw);
  const double u = profile.points[200].u_m, h = 1e-9;
  for (int k = 0; k <= 3; ++k) {
    auto jump = [&](const geom::AxisymmetricIntrusion& pad) {
      const double below = (pad.CosinePowerIntegral(u, k) - pad.CosinePowerIntegral(u - h, k)) / h;
      const double above = (pad.CosinePowerIntegral(u + h, k) - pad.CosinePowerIntegral(u, k)) / h;
      return std::fabs(above - below) / std::fabs(below);
    };
    EXPECT_LT(jump(smooth), 1e-5) << "k " << k;
    EXPECT_GT(jump(corners), 1e-4) << "k " << k;  // the chords' kink: cos^k(beta) / sin(beta) jumps
    // Past the top of the pad every piece is whole: the polyline's exact sum, blended or not.
    EXPECT_EQ(smooth.CosinePowerIntegral(0.02, k), corners.CosinePowerIntegral(0.02, k)) << "k " << k;
  }
}

}  // namespace rig_drop_steps
}  // namespace touchdown::pad

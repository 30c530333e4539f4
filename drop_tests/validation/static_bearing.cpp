#include "drop_tests/validation/static_bearing.h"

#include <cmath>
#include <numbers>

#include "drop_tests/drop/force_request.h"
#include "rft/contact_wrench.h"
#include "rft/units.h"

namespace touchdown::validation {

double StaticBearingPressure(const io::PadSpec& flat_pad, const rft::SoilParameters& soil, double gravity_m_s2,
                             double depth_m, double diameter_m) {
  // Area-preserving rims: the meshed bottom has the bearing area the pressure is taken over.
  const io::PadSpec pad = io::FlatPadWithRadius(flat_pad, 0.5 * diameter_m * units::kMmPerM, geom::RimPolygon::kAreaPreserving);
  rft::SoilParameters quasi_static = soil;
  quasi_static.dynamic_term = false;  // a static test: lambda rho v^2 vanishes at zero speed
  rft::PadKinematics k;
  k.v_WB_W = {0.0, 0.0, -rft::kQuasiStaticProbeSpeed_m_s};
  const drop::HeldPadWrench held =
      drop::ComputeHeldPadWrench(pad, quasi_static, soil.rft_law_3d, gravity_m_s2, depth_m, k);
  const double area = std::numbers::pi * 0.25 * diameter_m * diameter_m;
  return held.wrench.force_W.z() / area;
}

const char* RangeAgreementName(RangeAgreement a) { return NameIn(kRangeAgreementNames, a); }

RangeComparison CompareRanges(const Range& simulated, const Range& measured) {
  if (simulated.high < measured.low)
    return {RangeAgreement::kOutside, (simulated.high - measured.low) / measured.low};
  if (simulated.low > measured.high)
    return {RangeAgreement::kOutside, (simulated.low - measured.high) / measured.high};
  const bool inside = simulated.low >= measured.low && simulated.high <= measured.high;
  return {inside ? RangeAgreement::kInside : RangeAgreement::kOverlaps, 0.0};
}

}  // namespace touchdown::validation

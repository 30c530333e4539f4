#pragma once
// validate's static bearing pressure: the quasi-static vertical soil force on a flat pad of a
// bearing diameter D held with its bottom at depth d, over the bearing area pi D^2 / 4. The force
// is `touchdown force`'s (drop::ComputeHeldPadWrench) with the pad moving straight down at the
// quasi-static probe speed, the soil's dynamic term off (a static bearing test: zero speed), zeta
// scaled to the gravity as the soil says. A measured range is met by the model's range over the
// corners of the depth and diameter ranges: the pressure grows with depth and falls with the
// diameter (the side wall's share), so its extremes are at the corners.
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/validation/validation_source.h"
#include "rft/enum_names.h"
#include "rft/soil.h"

namespace touchdown::validation {

// [Pa]. `flat_pad`: a pad of profile shape flat (made at diameter_m, its rim area preserving).
double StaticBearingPressure(const io::PadSpec& flat_pad, const rft::SoilParameters& soil, double gravity_m_s2,
                             double depth_m, double diameter_m);

// How a simulated range stands against a measured one.
enum class RangeAgreement { kInside, kOverlaps, kOutside };
inline constexpr std::array<EnumName<RangeAgreement>, 3> kRangeAgreementNames{
    {{RangeAgreement::kInside, "inside"}, {RangeAgreement::kOverlaps, "overlaps"}, {RangeAgreement::kOutside, "outside"}}};
const char* RangeAgreementName(RangeAgreement a);
struct RangeComparison {
  RangeAgreement agreement = RangeAgreement::kOutside;
  // Outside: the gap to the nearer measured end over that end, signed (negative: the model is
  // below the measured range); 0 otherwise.
  double relative_distance = 0.0;
};
RangeComparison CompareRanges(const Range& simulated, const Range& measured);

}  // namespace touchdown::validation

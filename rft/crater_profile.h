#pragma once
// The height profile of one simple lunar impact crater (bowl, raised rim, ejecta blanket), as a
// pure function of the distance from its centre, relative to the surface before the impact.
//
// Fresh simple craters (D below about 15 km on the Moon), Pike 1977 ("Size-dependence in the shape
// of fresh craters on the Moon", in Roddy, Pepin & Merrill (eds.), Impact and Explosion Cratering,
// 489-509): rim-crest-to-floor depth d = 0.196 D^1.010 and rim height above the surroundings
// h = 0.036 D^1.014 (D, d, h in km). Taken here as the ratios d/D = 0.196 and h/D = 0.036 (the
// exponents' 1 % is below the scatter at metre scale, an assumption: Pike's fits are for
// D >= 400 m; the same ~0.2 is quoted for small fresh craters, Melosh 1989, Impact Cratering, ch. 8).
//
//   inside the rim (r <= R = D/2):  z = h - d (1 - (r/R)^2)      (a paraboloidal bowl: assumed)
//   outside the rim (r > R):        z = h (r/R)^-3               (ejecta thickness falling as
//                                    (r/R)^-3, McGetchin, Settle & Head 1973, EPSL 20, 226, whose
//                                    t = 0.14 R^0.74 (r/R)^-3 [m]; its amplitude is set here so the
//                                    blanket meets the rim: assumed, rim uplift and ejecta lumped)
//
// The profile is continuous; its slope jumps at the rim crest (a sharp rim). A height grid
// sampling it is then interpolated C1 (rft/height_field_ground.h), which rounds the crest over
// one cell.
//
// Degraded craters are shallower: `degradation` in [0, 1) scales d and h (and so the ejecta) by
// (1 - degradation), keeping the bowl's shape (assumed: a linear shallowing, not the diffusive
// degradation of Fassett & Thomson 2014, JGR Planets 119, 2255, which also widens the crater and
// rounds its rim). degradation 0.5 gives d/D = 0.098, about the d/D of the "degraded" classes
// reported for small lunar craters (an order of magnitude, not a fit).
namespace touchdown::rft {

struct CraterShape {
  double depth_to_diameter = 0.196;       // rim crest to floor, fresh (Pike 1977)
  double rim_height_to_diameter = 0.036;  // rim crest above the surroundings, fresh (Pike 1977)
  double ejecta_exponent = 3.0;           // thickness ~ (r/R)^-exponent outside the rim (McGetchin et al. 1973)
};

// A fresh crater's shape made shallower by `degradation` in [0, 1) as above.
CraterShape DegradedCraterShape(double degradation);

// Height [m] at distance r_m from the centre of a crater of diameter diameter_m, relative to the
// surface before the impact (0 far away).
double CraterHeight(const CraterShape& shape, double diameter_m, double r_m);

}  // namespace touchdown::rft

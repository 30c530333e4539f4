#pragma once
// Surface gravities that defaults and built-in setups take, in one place.
namespace touchdown::rft {

// The Earth's, as the paper's drops (Sutoh et al. 2017) and the shipped files take it: 9.81, not
// the standard 9.80665, so that a default agrees with data/ to the bit.
inline constexpr double kEarthGravity_m_s2 = 9.81;
// The Moon's, as the lunar studies take it (data/studies/lunar_paper_lander.yaml).
inline constexpr double kMoonGravity_m_s2 = 1.62;

}  // namespace touchdown::rft

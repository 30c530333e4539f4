#pragma once
// The rig the pad tests drop: a flat pad of radius kR (m) and mass kMass (kg) on a soil of
// zeta kZeta (N/m^3) under gravity kG (m/s^2).
#include <utility>

#include "lander/pad/rig_drop.h"

namespace touchdown::pad::test_rig {
inline constexpr double kR = 0.05, kMass = 1.6, kG = 9.81, kZeta = 2.0e6;

// A rig drop of `mass_kg` released to touch `soil` at `speed_m_s` under `gravity_m_s2`: its setup
// built around a response the caller holds.
inline RigDropResult RunRig(const VerticalSoilResponse& soil, double mass_kg, double gravity_m_s2, double speed_m_s,
                            const RigDropOptions& options = {}) {
  return RunRigDrop({{mass_kg}, &soil, {gravity_m_s2, speed_m_s}, options});
}
// The same on a soil given as a closed form F(d, v).
inline RigDropResult RunRig(VerticalResistance force, double mass_kg, double gravity_m_s2, double speed_m_s,
                            const RigDropOptions& options = {}) {
  const FunctionSoilResponse soil(std::move(force));
  return RunRig(soil, mass_kg, gravity_m_s2, speed_m_s, options);
}
}  // namespace touchdown::pad::test_rig

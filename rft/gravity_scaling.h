#pragma once
// How a soil's RFT stresses change with gravity: a model choice every soil states, because
// the two choices below differ by a factor of six on the Moon.
//
//   lithostatic  zeta(g) = zeta(g_ref) g / g_ref: the frictional resistance of a dry granular bed is
//                proportional to the overburden pressure rho g z (Agarwal, Goldman & Kamrin, PNAS
//                2023: xi_n = rho g f(mu)). The default, because it is what the intrusion
//                experiments in reduced gravity support (docs/gravity_scaling.md): an intruder that
//                settles under its own weight sinks equally deep whatever g, which lithostatic
//                scaling gives exactly (weight and resistance both scale with g).
//   none         zeta does not change with gravity, as a soil measured and used at one gravity, or
//                as Bekker's moduli (which carry no gravity): a lunar run then sees Earth's zeta.
// Files name it "lithostatic" or "none"; everything past the YAML edge holds the enum.
#include <optional>
#include <string_view>

namespace touchdown::rft {

enum class GravityScaling { kLithostatic, kNone };

inline const char* GravityScalingName(GravityScaling s) {
  return s == GravityScaling::kNone ? "none" : "lithostatic";
}

// nullopt for any other name (the caller reports it, naming its file and field).
inline std::optional<GravityScaling> ParseGravityScaling(std::string_view name) {
  if (name == "lithostatic") return GravityScaling::kLithostatic;
  if (name == "none") return GravityScaling::kNone;
  return std::nullopt;
}

}  // namespace touchdown::rft

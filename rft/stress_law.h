#pragma once
// A 2D stress law: the dimensionless stress coefficients alpha(beta, gamma) of a surface
// element, to be multiplied by the soil's scaling factor zeta and the element's depth.
// Li 2013 is the default; other laws (dynamic terms, Bekker-Wong-like laws) plug in here.
#include <memory>
#include <string>
#include <string_view>

#include "rft/li2013.h"

namespace touchdown::rft {

class StressLaw2D {
 public:
  virtual ~StressLaw2D() = default;
  virtual std::string_view name() const = 0;
  // beta: attack angle of the element [rad]; gamma: intrusion angle of its velocity [rad].
  virtual Alpha2 Alpha(double beta_rad, double gamma_rad) const = 0;
};

class Li2013Law final : public StressLaw2D {
 public:
  explicit Li2013Law(Li2013Coefficients coefficients = {}) : c_(coefficients) {}
  std::string_view name() const override { return "li2013"; }
  Alpha2 Alpha(double beta_rad, double gamma_rad) const override {
    return Li2013Alpha(c_, beta_rad, gamma_rad);
  }

 private:
  Li2013Coefficients c_;
};

}  // namespace touchdown::rft

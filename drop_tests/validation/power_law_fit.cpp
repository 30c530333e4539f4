#include "drop_tests/validation/power_law_fit.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

namespace touchdown::validation {

PowerLaw FitPowerLaw(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 2) throw std::invalid_argument("power-law fit: needs two or more (x, y) pairs");
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double xi = x[static_cast<size_t>(i)], yi = y[static_cast<size_t>(i)];
    if (!(xi > 0.0) || !(yi > 0.0) || !std::isfinite(xi) || !std::isfinite(yi))
      throw std::invalid_argument("power-law fit: every x and y must be positive and finite");
    design(i, 0) = std::log(xi);
    design(i, 1) = 1.0;
    rhs(i) = std::log(yi);
  }
  if (design.col(0).maxCoeff() == design.col(0).minCoeff())
    throw std::invalid_argument("power-law fit: x must take two or more distinct values");
  const Eigen::Vector2d coef = design.colPivHouseholderQr().solve(rhs);
  return {coef(0), std::exp(coef(1))};
}

}  // namespace touchdown::validation

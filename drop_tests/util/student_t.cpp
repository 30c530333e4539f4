#include "drop_tests/util/student_t.h"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

namespace touchdown::io {

double StudentTTwoSided(double confidence, double degrees_of_freedom) {
  if (!(confidence > 0.0 && confidence < 1.0))
    throw std::invalid_argument("StudentTTwoSided: confidence must be in (0, 1), got " + std::to_string(confidence));
  if (!(degrees_of_freedom > 0.0) || !std::isfinite(degrees_of_freedom))
    throw std::invalid_argument("StudentTTwoSided: degrees of freedom must be positive, got " +
                                std::to_string(degrees_of_freedom));
  return boost::math::quantile(boost::math::students_t(degrees_of_freedom), 0.5 + confidence / 2.0);
}

}  // namespace touchdown::io

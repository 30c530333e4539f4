#include "rft/pad_level_terms.h"

namespace touchdown::rft {

Eigen::Vector3d PadLevelTerms::CompactionStress(const Eigen::Vector3d& n, const Eigen::Vector3d& v) const {
  const double vn = n.dot(v);
  if (!(vn > 0.0)) return Eigen::Vector3d::Zero();
  return (-compaction_k_kg_m3 * vn * vn) * n;
}

}  // namespace touchdown::rft

#include "free_set.h"

#include <cmath>

namespace ik {

FreeAngles find_free_angles(const Eigen::VectorXd& angles, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                            const Eigen::VectorXd& gradient, std::vector<int>& free, Eigen::VectorXd& mask) {
  FreeAngles found;
  double norm2 = 0;
  for (Eigen::Index i = 0; i < angles.size(); ++i) {
    const bool blocked = lower[i] >= upper[i] || pushed_past_limit(angles[i], lower[i], upper[i], -gradient[i]);
    mask[i] = blocked ? 0.0 : 1.0;
    if (blocked) continue;
    free[found.count++] = static_cast<int>(i);
    norm2 += gradient[i] * gradient[i];
  }
  found.gradient_norm = std::sqrt(norm2);
  return found;
}

}  // namespace ik

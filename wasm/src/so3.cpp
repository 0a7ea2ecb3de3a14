#include "so3.h"

#include <Eigen/Geometry>
#include <cmath>

namespace ik {

Eigen::Vector3d so3_log(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);  // Eigen's conversion is stable near 0 and near pi
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d v = q.vec();
  const double n = v.norm();
  // theta = 2 atan2(|v|, w); e = theta * v / |v|, and 2 v / w to first order for tiny |v|.
  if (n < 1e-8) return (2.0 / q.w()) * v;
  return (2.0 * std::atan2(n, q.w()) / n) * v;
}

Eigen::Matrix3d so3_hat(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Eigen::Matrix3d so3_right_jacobian_inverse(const Eigen::Vector3d& e) {
  const double theta2 = e.squaredNorm();
  const double theta = std::sqrt(theta2);
  // 1/theta^2 - cot(theta/2) / (2 theta); its series 1/12 + theta^2/720 + theta^4/30240 near 0.
  const double c = theta < 1e-3 ? 1.0 / 12 + theta2 / 720 + theta2 * theta2 / 30240
                                : 1.0 / theta2 - 1.0 / (2 * theta * std::tan(theta / 2));
  const Eigen::Matrix3d h = so3_hat(e);
  return Eigen::Matrix3d::Identity() + 0.5 * h + c * h * h;
}

}  // namespace ik

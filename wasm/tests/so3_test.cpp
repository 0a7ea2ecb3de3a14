// The SO(3) log map and the inverse right Jacobian (so3.h), against Eigen's AngleAxis and
// central differences, near 0, in general and near pi.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "so3.h"

namespace ik {
namespace {

Eigen::Matrix3d exp_so3(const Eigen::Vector3d& e) {
  const double t = e.norm();
  if (t == 0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(t, e / t).toRotationMatrix();
}

std::vector<Eigen::Vector3d> sample_vectors() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Vector3d> out;
  for (double size : {0.0, 1e-12, 1e-7, 1e-4, 1e-3 * 0.999, 1e-3 * 1.001, 0.3, 1.0, 2.0, 3.0, 3.14}) {
    for (int i = 0; i < 5; ++i) {
      Eigen::Vector3d d(u(rng), u(rng), u(rng));
      out.push_back(size * d.normalized());
    }
  }
  return out;
}

TEST(So3, LogInvertsExp) {
  for (const Eigen::Vector3d& e : sample_vectors()) {
    const Eigen::Vector3d back = so3_log(exp_so3(e));
    EXPECT_LT((back - e).norm(), 1e-12 + 1e-12 * e.norm()) << e.transpose();
  }
}

TEST(So3, LogOfAHalfTurnHasLengthPi) {
  const double pi = 3.14159265358979323846;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(pi, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_NEAR(so3_log(R).norm(), pi, 1e-12);
  EXPECT_TRUE(so3_right_jacobian_inverse(so3_log(R)).allFinite());
}

TEST(So3, RightJacobianInverseMatchesCentralDifferences) {
  const double h = 1e-6;
  for (const Eigen::Vector3d& e : sample_vectors()) {
    if (e.norm() > 3.1) continue;  // the log's cut at pi is within reach of the differences
    const Eigen::Matrix3d R = exp_so3(e);
    const Eigen::Matrix3d J = so3_right_jacobian_inverse(e);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d d = Eigen::Vector3d::Unit(k) * h;
      const Eigen::Vector3d numeric = (so3_log(R * exp_so3(d)) - so3_log(R * exp_so3(-d))) / (2 * h);
      EXPECT_LT((numeric - J.col(k)).norm(), 1e-7) << "e " << e.transpose() << " column " << k;
    }
  }
}

TEST(So3, HatIsTheCrossProduct) {
  const Eigen::Vector3d v(1, -2, 0.5), w(0.3, 0.7, -1.1);
  EXPECT_LT((so3_hat(v) * w - v.cross(w)).norm(), 1e-15);
}

}  // namespace
}  // namespace ik

#include "rest_residual.h"

#include "kinematics.h"

namespace ik {

void rest_residual(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                   Eigen::Ref<Eigen::VectorXd> rows) {
  const Eigen::VectorXd& reference = goals.rest_reference();
  for (int i = 0; i < goals.num_rest(); ++i) {
    const int j = 3 * goals.rest_bone(i);
    const double scale = goals.soft_scale() * goals.rest_scale(i) * kRadPerDeg;
    rows.segment<3>(3 * i) = scale * (angles.segment<3>(j) - reference.segment<3>(j));
  }
}

void rest_jacobian(const GoalSet& goals, Eigen::Ref<Eigen::MatrixXd> jac) {
  jac.setZero();
  for (int i = 0; i < goals.num_rest(); ++i) {
    const int j = 3 * goals.rest_bone(i);
    const double scale = goals.soft_scale() * goals.rest_scale(i) * kRadPerDeg;
    for (int c = 0; c < 3; ++c) jac(3 * i + c, j + c) = scale;
  }
}

}  // namespace ik

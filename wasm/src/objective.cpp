#include "objective.h"

#include <algorithm>
#include <cmath>

namespace ik {

double objective(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                 const Eigen::Ref<const Eigen::VectorXd>& target, Eigen::Ref<Eigen::VectorXd> residual) {
  kin.tips(angles, residual);
  residual -= target;
  return 0.5 * residual.squaredNorm();
}

double objective_and_gradient(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                              const Eigen::Ref<const Eigen::VectorXd>& target, Eigen::Ref<Eigen::VectorXd> residual,
                              Eigen::Ref<Eigen::MatrixXd> jac, Eigen::Ref<Eigen::VectorXd> gradient) {
  kin.jacobian(angles, residual, jac);
  residual -= target;
  gradient.noalias() = jac.transpose() * residual;
  return 0.5 * residual.squaredNorm();
}

double largest_tip_distance(const Eigen::Ref<const Eigen::VectorXd>& residual) {
  double largest2 = 0;
  for (Eigen::Index k = 0; k + 2 < residual.size(); k += 3)
    largest2 = std::max(largest2, residual.segment<3>(k).squaredNorm());
  return std::sqrt(largest2);
}

}  // namespace ik

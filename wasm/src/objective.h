// The IK objective E(A) = 1/2 ||x(A) - x_b||^2 over all end-effector tips, and its gradient.
#pragma once

#include <Eigen/Core>

#include "kinematics.h"

namespace ik {

// Residual r = x(A) - x_b (#residuals) and E = 1/2 |r|^2 at `angles` (#angles, degrees).
// `target` holds x_b (#residuals, rig units). Returns E. No allocation.
double objective(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                 const Eigen::Ref<const Eigen::VectorXd>& target, Eigen::Ref<Eigen::VectorXd> residual);

// E, the residual, the analytic Jacobian (#residuals x #angles, per degree) and the gradient
// grad E = J^T r (#angles, rig units^2 per degree). Returns E. No allocation.
double objective_and_gradient(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                              const Eigen::Ref<const Eigen::VectorXd>& target,
                              Eigen::Ref<Eigen::VectorXd> residual, Eigen::Ref<Eigen::MatrixXd> jac,
                              Eigen::Ref<Eigen::VectorXd> gradient);

}  // namespace ik

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
                              const Eigen::Ref<const Eigen::VectorXd>& target, Eigen::Ref<Eigen::VectorXd> residual,
                              Eigen::Ref<Eigen::MatrixXd> jac, Eigen::Ref<Eigen::VectorXd> gradient);

// The largest distance of an end effector's tip from its target: max over the residual's
// 3-vectors r_k = x_k - x_b,k of |r_k| (rig units). No allocation.
double largest_tip_distance(const Eigen::Ref<const Eigen::VectorXd>& residual);

// An effector whose distance from its target is at least this share of the largest one still
// counts as off target when a solver looks for a way out of a stop (saddle_escape, chain_restart).
constexpr double kOffTargetShare = 0.1;

// Is effector `e` off target in that sense, with `largest` = largest_tip_distance(residual)?
inline bool off_target(const Eigen::Ref<const Eigen::VectorXd>& residual, int e, double largest) {
  return residual.segment<3>(3 * e).norm() >= kOffTargetShare * largest;
}

}  // namespace ik

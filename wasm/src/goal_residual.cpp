#include "goal_residual.h"

#include <algorithm>
#include <cmath>

#include "objective.h"
#include "so3.h"

namespace ik {

double goal_objective(Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                      Eigen::Ref<Eigen::VectorXd> residual) {
  if (goals.plain()) return objective(kin, angles, goals.plain_target(), residual);
  kin.forward(angles);
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    const int bone = kin.rig().effectors[g.effector];
    if (g.orientation)
      residual.segment<3>(3 * b) = g.scale * so3_log(g.rotation.transpose() * kin.tip_rotation(bone));
    else
      residual.segment<3>(3 * b) = g.scale * (kin.tip(bone) - g.position);
  }
  return 0.5 * residual.squaredNorm();
}

void goal_jacobian(const Kinematics& kin, const GoalSet& goals, Eigen::Ref<Eigen::MatrixXd> jac) {
  if (goals.plain()) {
    kin.current_jacobian(jac);
    return;
  }
  jac.setZero();
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    const int bone = kin.rig().effectors[g.effector];
    const double scale = g.scale * kRadPerDeg;
    if (g.orientation) {
      const Eigen::Matrix3d R = kin.tip_rotation(bone);
      const Eigen::Matrix3d M = scale * so3_right_jacobian_inverse(so3_log(g.rotation.transpose() * R)) * R.transpose();
      for (int j : kin.effector_chain(g.effector))
        for (int a = 0; a < 3; ++a) jac.block<3, 1>(3 * b, 3 * j + a) = M * kin.joint_axis(j, a);
    } else {
      const Eigen::Vector3d p = kin.tip(bone);
      for (int j : kin.effector_chain(g.effector))
        for (int a = 0; a < 3; ++a)
          jac.block<3, 1>(3 * b, 3 * j + a) = scale * kin.joint_axis(j, a).cross(p - kin.joint_origin(j));
    }
  }
}

double largest_tip_distance(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  if (goals.plain()) return largest_tip_distance(residual);
  double largest = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (!goals.block(b).orientation)
      largest = std::max(largest, residual.segment<3>(3 * b).norm() / goals.block(b).scale);
  return largest;
}

double largest_orientation_error_deg(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  double largest = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (goals.block(b).orientation)
      largest = std::max(largest, residual.segment<3>(3 * b).norm() / goals.block(b).scale);
  return largest / kRadPerDeg;
}

double position_error(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  double sum = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (!goals.block(b).orientation) sum += residual.segment<3>(3 * b).squaredNorm();
  return 0.5 * sum;
}

double largest_goal_distance(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  if (goals.plain()) return largest_tip_distance(residual);
  double largest = 0;
  for (int b = 0; b < goals.num_blocks(); ++b) largest = std::max(largest, residual.segment<3>(3 * b).norm());
  return largest;
}

bool goal_off_target(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual, int e, double largest) {
  if (goals.plain()) return off_target(residual, e, largest);
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (goals.block(b).effector == e && residual.segment<3>(3 * b).norm() >= kOffTargetShare * largest) return true;
  return false;
}

void tip_hessian_weights(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual,
                         Eigen::Ref<Eigen::VectorXd> weights) {
  if (goals.plain()) {
    weights = residual;
    return;
  }
  weights.setZero();
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    if (!g.orientation) weights.segment<3>(3 * g.effector) = g.scale * residual.segment<3>(3 * b);
  }
}

}  // namespace ik

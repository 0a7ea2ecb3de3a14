#include "pose_goals.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace ik::bench {

Eigen::Matrix3d rotation_of(const double* q) {
  return Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
}

Goals pose_goals(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& target,
                 const Eigen::Ref<const Eigen::VectorXd>& quaternions) {
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  for (int e = 0; e < kin.num_effectors(); ++e) {
    EffectorGoal& g = goals.effectors[e];
    g.position = true;
    g.position_target = target.segment<3>(3 * e);
    g.orientation = true;
    g.orientation_target = rotation_of(quaternions.data() + 4 * e);
  }
  return goals;
}

double largest_rotation_error_deg(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                                  const Eigen::Ref<const Eigen::VectorXd>& quaternions) {
  kin.forward(angles);
  double worst = 0;
  for (int e = 0; e < kin.num_effectors(); ++e) {
    const Eigen::Matrix3d R =
        rotation_of(quaternions.data() + 4 * e).transpose() * kin.tip_rotation(kin.rig().effectors[e]);
    const Eigen::Quaterniond d(R);  // 2 atan2(|v|, |w|): accurate near 0 as well
    worst = std::max(worst, 2 * std::atan2(d.vec().norm(), std::abs(d.w())) / kRadPerDeg);
  }
  return worst;
}

double largest_twist_component(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                               const Eigen::Ref<const Eigen::VectorXd>& targets,
                               const Eigen::Ref<const Eigen::VectorXd>& quaternions) {
  kin.forward(angles);
  double worst = 0;
  for (int e = 0; e < kin.num_effectors(); ++e) {
    const int bone = kin.rig().effectors[e];
    worst = std::max(worst, (targets.segment<3>(3 * e) - kin.tip(bone)).cwiseAbs().maxCoeff());
    const Eigen::AngleAxisd turn(rotation_of(quaternions.data() + 4 * e) * kin.tip_rotation(bone).transpose());
    worst = std::max(worst, (turn.angle() * turn.axis()).cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace ik::bench

// --goals pose of the native bench (bench-node/pose_goals.ts): every end effector's target is its
// tip frame's whole pose, the position x(A_k) and the rotation of its bone frame at A_k
// (Kinematics::tip_rotation), given as quaternions [x, y, z, w], 4 per effector in the rig's
// effector order. Native builds only.
#pragma once

#include <Eigen/Core>

#include "goals.h"
#include "kinematics.h"

namespace ik::bench {

// Goals with, per end effector, its position `target` (3 per effector, rig units) and its
// orientation `quaternions` (4 per effector, [x, y, z, w], any nonzero length), weight 1.
Goals pose_goals(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& target,
                 const Eigen::Ref<const Eigen::VectorXd>& quaternions);

// The rotation of quaternion [x, y, z, w] at `q` (normalised).
Eigen::Matrix3d rotation_of(const double* q);

// Poses `kin` at `angles` (degrees) and returns the largest angle, in DEGREES, between an end
// effector's frame (tip_rotation) and its target orientation in `quaternions` (as above).
double largest_rotation_error_deg(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                                  const Eigen::Ref<const Eigen::VectorXd>& quaternions);

// The largest component of the twists that take the tips at `angles` onto their poses (KDL's and
// TRAC-IK's success test: each within the tolerance): per effector the position's difference x, y,
// z (rig units; `targets`, 3 per effector) and the world rotation vector, radians, that turns the
// frame onto its target (`quaternions`, x, y, z, w per effector). Poses `kin` at `angles`.
double largest_twist_component(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                               const Eigen::Ref<const Eigen::VectorXd>& targets,
                               const Eigen::Ref<const Eigen::VectorXd>& quaternions);

}  // namespace ik::bench

// Rotations as rotation vectors: the log map of SO(3) and the inverse of its right Jacobian.
//
// A rotation vector e = theta * axis (RADIANS) stands for exp([e]) = R. Perturbing R on the right,
// R exp([b] d), changes log(R) by J_r^-1(log R) b d to first order, with
//   J_r^-1(e) = I + [e]/2 + (1/theta^2 - cot(theta/2) / (2 theta)) [e]^2.
// The coefficient of [e]^2 tends to 1/12 at theta = 0 (a series is used there) and to 1/pi^2 at
// theta = pi: J_r^-1 stays finite on the whole ball |e| <= pi.
#pragma once

#include <Eigen/Core>

namespace ik {

// log(R) for a rotation matrix R: the rotation vector e with |e| in [0, pi], radians. At exactly
// pi the axis's sign follows the quaternion of R (both signs describe R). No allocation.
Eigen::Vector3d so3_log(const Eigen::Matrix3d& R);

// J_r^-1(e) for a rotation vector e (radians, |e| <= pi). No allocation.
Eigen::Matrix3d so3_right_jacobian_inverse(const Eigen::Vector3d& e);

// [v]: the cross-product matrix, [v] w = v x w.
Eigen::Matrix3d so3_hat(const Eigen::Vector3d& v);

}  // namespace ik

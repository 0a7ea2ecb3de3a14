// The free angles at a point: the angles a descent step may move. An angle is blocked when it is
// fixed (lower >= upper) or sits on a limit that the gradient pushes it past (on its lower limit
// with g > 0, on its upper limit with g < 0: -g points out of the box there).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ik {

// Whether an angle at `angle` within [lower, upper] (degrees) sits on a limit that a move of sign
// `move` pushes past: on its lower limit with move < 0, on its upper limit with move > 0 (a descent
// direction -g moves it by -g).
inline bool pushed_past_limit(double angle, double lower, double upper, double move) {
  return (angle <= lower && move < 0) || (angle >= upper && move > 0);
}

struct FreeAngles {
  int count = 0;             // how many angles are free
  double gradient_norm = 0;  // |gradient| over them, rig units^2 per degree
};

// From `angles`, `lower` and `upper` (#angles each, degrees) and the gradient `gradient` (#angles,
// rig units^2 per degree): writes the free angles' indices, ascending, to free[0..count) (free
// holds #angles) and 1 (free) or 0 (blocked) per angle to `mask` (#angles). No allocation.
FreeAngles find_free_angles(const Eigen::VectorXd& angles, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                            const Eigen::VectorXd& gradient, std::vector<int>& free, Eigen::VectorXd& mask);

}  // namespace ik

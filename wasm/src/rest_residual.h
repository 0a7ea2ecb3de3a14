// The rest rows of a GoalSet (goals.h set_rest()): a soft pull of each angle of the bones on a
// goal's chain towards a reference pose (0 degrees: the rest pose; or the solve's start angles).
// Row 3i + c, for rest bone b = rest_bone(i) and angle j = 3b + c:
//   rest_scale(i) * (pi / 180) * (a_j - ref_j)            rig units
// (times GoalSet::soft_scale(), which the solver lowers on its way to the target)
// with rest_scale(i) = rest_weight * stiffness_b * L, L the goals' length scale (rig units per
// radian), so that 1/2 |rows|^2 is in rig units^2 like E, and a deviation of 1 radian on a bone
// of stiffness 1 weighs as much as a tip rest_weight * L away from its target. Stiffness k > 1
// makes a bone k^2 times as costly to turn.
#pragma once

#include <Eigen/Core>

#include "goals.h"

namespace ik {

// Writes the rest rows (3 * goals.num_rest(), rig units) for `angles` (#angles, degrees).
// No allocation.
void rest_residual(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                   Eigen::Ref<Eigen::VectorXd> rows);

// Writes their Jacobian into `jac` (3 * goals.num_rest() x #angles, rig units per degree):
// soft_scale() * rest_scale(i) * pi / 180 on angle j of row 3i + c, 0 elsewhere. No allocation.
void rest_jacobian(const GoalSet& goals, Eigen::Ref<Eigen::MatrixXd> jac);

}  // namespace ik

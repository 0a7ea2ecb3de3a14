// The Jacobian of paper mode, as the original program computed it: the central difference with
// step h clamped to the limits (finite_difference_jacobian.h), divided by h instead of by the
// spread it spans. Away from the limits the spread is 2h, so its columns are twice the
// derivative; on a limit the difference is one-sided over h and has the derivative's scale.
#pragma once

#include <Eigen/Core>

#include "kinematics.h"

namespace ik {

// Writes the original's d tips / d angles (#residuals x #angles, rig units per degree) at
// `angles` (#angles, degrees) with step `h_deg` (degrees) to `jac`. `scratch` is #angles of
// workspace, `tips_plus` and `tips_minus` #residuals. Leaves `kin` posed at `angles`.
// No allocation.
void paper_jacobian(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles, double h_deg,
                    Eigen::Ref<Eigen::VectorXd> scratch, Eigen::Ref<Eigen::VectorXd> tips_plus,
                    Eigen::Ref<Eigen::VectorXd> tips_minus, Eigen::Ref<Eigen::MatrixXd> jac);

}  // namespace ik

// Central finite-difference Jacobian of the end-effector tips, as the original program used it.
#pragma once

#include <Eigen/Core>

#include "kinematics.h"

namespace ik {

// Writes d tips / d angles (#residuals x #angles, rig units per DEGREE) at `angles` (degrees)
// by central differences with step `h_deg` degrees. With `clamp_to_limits`, each perturbed
// angle is clamped into its limits, as the original did (h = 1e-7 degrees there), and the
// difference divides by the clamped spread, so it estimates the true derivative. (The original
// divided by h, not 2h: paper mode rescales these columns to reproduce that.) `scratch` is #angles of workspace,
// `tips_plus` and `tips_minus` are #residuals. Leaves the rig posed at `angles`. No allocation.
void finite_difference_jacobian(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles, double h_deg,
                                bool clamp_to_limits, Eigen::Ref<Eigen::VectorXd> scratch,
                                Eigen::Ref<Eigen::VectorXd> tips_plus, Eigen::Ref<Eigen::VectorXd> tips_minus,
                                Eigen::Ref<Eigen::MatrixXd> jac);

}  // namespace ik

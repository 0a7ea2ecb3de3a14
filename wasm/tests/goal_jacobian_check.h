// The goal Jacobian against central differences, shared by the native tests that check it.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>

#include "goal_residual.h"

namespace ik::test {

// Central differences of goal_objective()'s residual at `a` (step h: degrees for an angle, rig
// units for a floating root's translation) against goal_jacobian(): the largest difference over
// the largest numeric entry (at least 1e-12). Expects the analytic Jacobian to be finite.
inline double goal_jacobian_error(Kinematics& kin, const GoalSet& goals, Eigen::VectorXd a, double h) {
  const int m = goals.rows(), n = kin.num_angles();
  Eigen::MatrixXd analytic(m, n), numeric(m, n);
  Eigen::VectorXd plus(m), minus(m);
  goal_objective(kin, goals, a, plus);
  goal_jacobian(kin, goals, analytic);
  for (int j = 0; j < n; ++j) {
    const double keep = a[j];
    a[j] = keep + h;
    goal_objective(kin, goals, a, plus);
    a[j] = keep - h;
    goal_objective(kin, goals, a, minus);
    a[j] = keep;
    numeric.col(j) = (plus - minus) / (2 * h);
  }
  EXPECT_TRUE(analytic.allFinite());
  const double scale = std::max(numeric.cwiseAbs().maxCoeff(), 1e-12);
  return (analytic - numeric).cwiseAbs().maxCoeff() / scale;
}

}  // namespace ik::test

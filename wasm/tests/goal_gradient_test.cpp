// goal_gradient (goal_residual.h): the gradient J^T r of E over the hard rows without forming J,
// which the Solver takes at the answer of a tracked frame. It must be goal_jacobian's J^T r
// (positions, orientations, weights, a floating root, fixed angles with Columns::movable) and
// E's central differences.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "goal_residual.h"
#include "kinematics.h"
#include "small_rigs.h"

namespace ik {
namespace {

// test::two_arms, floating, the second arm's upper bone unable to twist (its a0 fixed at 0).
Rig arms_with_a_fixed_twist() {
  Rig rig = test::two_arms(true);
  rig.bones[3].min_deg[0] = rig.bones[3].max_deg[0] = 0;
  return rig;
}

TEST(GoalGradient, IsJTransposeRAndMatchesCentralDifferencesOfE) {
  Kinematics kin(arms_with_a_fixed_twist());
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-40, 40);
  const int fixed = 3 * 3;  // upper.R's a0
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd a(kin.num_angles());
    for (int j = 0; j < a.size(); ++j) a[j] = u(rng);
    a[fixed] = 0;
    a.tail<3>() = Eigen::Vector3d(0.1 * trial, -0.3, 0.2);
    kin.forward(a);
    // Both hands with a position and a frame, of different weights: not plain goals.
    Goals goals;
    goals.effectors.resize(2);
    for (int k = 0; k < 2; ++k) {
      const int bone = kin.rig().effectors[k];
      goals.effectors[k].position_target = kin.tip(bone) + Eigen::Vector3d(0.2, -0.1 * k, 0.3);
      goals.effectors[k].position_weight = 1 + k;
      goals.effectors[k].orientation = true;
      goals.effectors[k].orientation_weight = 0.5;
      goals.effectors[k].orientation_target =
          kin.tip_rotation(bone) *
          Eigen::AngleAxisd(0.3 + 0.2 * k, Eigen::Vector3d(1, 2 - k, 3).normalized()).toRotationMatrix();
    }
    GoalSet set;
    ASSERT_EQ(set.set(kin, goals), "");
    ASSERT_FALSE(set.plain());
    Eigen::VectorXd r(set.rows()), g(kin.num_angles());
    const double E = goal_objective(kin, set, a, r);
    ASSERT_GT(E, 0);
    Eigen::MatrixXd J(set.rows(), kin.num_angles());
    goal_jacobian(kin, set, J, Kinematics::Columns::movable);
    goal_gradient(kin, set, r, g, Kinematics::Columns::movable);
    const Eigen::VectorXd expected = J.transpose() * r;
    EXPECT_LT((g - expected).cwiseAbs().maxCoeff(), 1e-13 * (1 + expected.cwiseAbs().maxCoeff())) << "trial " << trial;
    EXPECT_EQ(g[fixed], 0) << "a fixed angle has no column";
    // Central differences of E (per degree; per rig unit for the root's translation).
    Eigen::VectorXd plus(set.rows()), minus(set.rows());
    for (int j = 0; j < a.size(); ++j) {
      if (j == fixed) continue;
      const double h = 1e-5;
      Eigen::VectorXd ap = a, am = a;
      ap[j] += h;
      am[j] -= h;
      const double fd = (goal_objective(kin, set, ap, plus) - goal_objective(kin, set, am, minus)) / (2 * h);
      EXPECT_NEAR(g[j], fd, 1e-6 * (1 + std::abs(fd))) << "angle " << j << ", trial " << trial;
    }
  }
}

}  // namespace
}  // namespace ik

// What the solvers read from a goal residual (goal_residual.h): tip distances from the position
// rows only, orientation errors in degrees, "off target" per block, and the tip Hessian's weights
// that make J^T J + C the exact Hessian of E for weighted position goals.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "a7_fixtures.h"
#include "goal_residual.h"
#include "small_rigs.h"
#include "solvers/tip_hessian.h"

namespace ik {
namespace {

TEST(GoalResidual, DistancesAndAnglesComeFromTheirOwnRows) {
  Kinematics kin(test::two_bones());
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(kin.num_angles());
  kin.forward(a);
  const int bone = kin.rig().effectors[0];
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  goals.effectors[0].position_target = kin.tip(bone) + Eigen::Vector3d(0.3, 0, 0);
  goals.effectors[0].position_weight = 2;  // relative: divided by the largest, 4
  goals.effectors[0].orientation = true;
  goals.effectors[0].orientation_weight = 4;
  goals.effectors[0].orientation_target =
      kin.tip_rotation(bone) * Eigen::AngleAxisd(10 * kRadPerDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  goals.length_scale = 5;
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  Eigen::VectorXd r(set.rows());
  const double E = goal_objective(kin, set, a, r);
  EXPECT_NEAR(largest_tip_distance(set, r), 0.3, 1e-12);
  EXPECT_NEAR(largest_orientation_error_deg(set, r), 10, 1e-9);
  EXPECT_NEAR(position_error(set, r), 0.5 * 0.15 * 0.15, 1e-12);
  EXPECT_NEAR(E, 0.5 * (0.15 * 0.15 + std::pow(5 * 10 * kRadPerDeg, 2)), 1e-12);
  EXPECT_NEAR(largest_goal_distance(set, r), 5 * 10 * kRadPerDeg, 1e-12);
  EXPECT_TRUE(goal_off_target(set, r, 0, largest_goal_distance(set, r)));
}

// Hess E by central differences of grad E = J^T r (step h degrees).
Eigen::MatrixXd hessian_difference(Kinematics& kin, const GoalSet& set, const Eigen::VectorXd& a, double h) {
  const int n = kin.num_angles();
  Eigen::MatrixXd H(n, n), J(set.rows(), n);
  Eigen::VectorXd r(set.rows()), ap = a;
  for (int j = 0; j < n; ++j) {
    ap[j] = a[j] + h;
    goal_objective(kin, set, ap, r);
    goal_jacobian(kin, set, J);
    H.col(j) = J.transpose() * r;
    ap[j] = a[j] - h;
    goal_objective(kin, set, ap, r);
    goal_jacobian(kin, set, J);
    H.col(j) -= J.transpose() * r;
    H.col(j) /= 2 * h;
    ap[j] = a[j];
  }
  return H;
}

TEST(GoalResidual, TipHessianWeightsGiveTheExactHessianOfWeightedPositions) {
  for (const test::TestRig& r : test::rigs_like("ikea-lamp")) {
    Kinematics kin(r.rig);
    // Two effectors: weights are relative, one goal's alone is the plain objective.
    std::vector<int> effectors = kin.rig().effectors;
    if (effectors.size() == 1) effectors.push_back(kin.num_bones() / 2);
    kin.set_effectors(effectors);
    std::mt19937_64 rng(4);
    const Eigen::VectorXd a = test::random_angles(kin, rng);
    Eigen::VectorXd target(kin.num_residuals());
    kin.tips(test::random_angles(kin, rng), target);
    Goals goals;
    goals.effectors.resize(kin.num_effectors());
    for (int e = 0; e < kin.num_effectors(); ++e) {
      goals.effectors[e].position_target = target.segment<3>(3 * e);
      goals.effectors[e].position_weight = 1.5 + e;
    }
    GoalSet set;
    ASSERT_EQ(set.set(kin, goals), "");
    ASSERT_FALSE(set.plain());
    const int n = kin.num_angles();
    Eigen::VectorXd res(set.rows()), weights(kin.num_residuals());
    Eigen::MatrixXd J(set.rows(), n);
    goal_objective(kin, set, a, res);
    goal_jacobian(kin, set, J);
    tip_hessian_weights(set, res, weights);
    Eigen::MatrixXd H = J.transpose() * J;
    add_weighted_tip_hessian(kin, weights, H);
    const Eigen::MatrixXd fd = hessian_difference(kin, set, a, 1e-3);
    EXPECT_LE((H - fd).cwiseAbs().maxCoeff(), 1e-6 * fd.cwiseAbs().maxCoeff()) << r.label();
  }
}

TEST(GoalResidual, OrientationRowsGetNoTipHessianWeight) {
  Kinematics kin(test::two_bones());
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  goals.effectors[0].position = false;
  goals.effectors[0].orientation = true;
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  Eigen::VectorXd r = Eigen::VectorXd::Ones(set.rows()), weights(kin.num_residuals());
  tip_hessian_weights(set, r, weights);
  EXPECT_EQ(weights, Eigen::VectorXd::Zero(kin.num_residuals()));
  EXPECT_EQ(largest_tip_distance(set, r), 0);
}

}  // namespace
}  // namespace ik

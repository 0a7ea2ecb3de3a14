// The analytic Jacobian of mixed goals (goal_residual.h): position and orientation rows with
// weights, against central differences of the residual on every test rig at random poses.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <random>

#include "a7_fixtures.h"
#include "goal_jacobian_check.h"
#include "goal_residual.h"

namespace ik {
namespace {

Eigen::Matrix3d random_rotation(std::mt19937_64& rng, double max_angle) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
  return Eigen::AngleAxisd(max_angle * (0.5 + 0.5 * u(rng)), axis).toRotationMatrix();
}

// Effector e: position and orientation (e % 3 == 0), orientation only (1), position only (2),
// weights other than 1; targets near the pose at `angles` (orientation errors up to 2.5 rad).
Goals mixed_goals(Kinematics& kin, const Eigen::VectorXd& angles, std::mt19937_64& rng) {
  kin.forward(angles);
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  std::uniform_real_distribution<double> u(-1, 1);
  for (int e = 0; e < kin.num_effectors(); ++e) {
    EffectorGoal& g = goals.effectors[e];
    const int bone = kin.rig().effectors[e];
    g.position = e % 3 != 1;
    g.orientation = e % 3 != 2;
    g.position_weight = 1.5;
    g.orientation_weight = 0.7;
    g.position_target = kin.tip(bone) + 0.3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    g.orientation_target = kin.tip_rotation(bone) * random_rotation(rng, 2.5);
  }
  return goals;
}

TEST(OrientationJacobian, MatchesCentralDifferencesOnEveryRig) {
  const double h = 1e-3;  // degrees
  double worst_overall = 0;
  for (const test::TestRig& r : test::test_rigs()) {
    SCOPED_TRACE(r.label());
    Kinematics kin(r.rig);
    std::mt19937_64 rng(11);
    for (int sample = 0; sample < 3; ++sample) {
      Eigen::VectorXd a = test::random_angles(kin, rng);
      GoalSet goals;
      ASSERT_EQ(goals.set(kin, mixed_goals(kin, a, rng)), "");
      ASSERT_TRUE(goals.has_orientation());
      const double worst = test::goal_jacobian_error(kin, goals, a, h);
      worst_overall = std::max(worst_overall, worst);
      EXPECT_LT(worst, 1e-6) << "sample " << sample;
    }
  }
  std::printf("worst relative error of the goal Jacobian: %.3g\n", worst_overall);
}

TEST(OrientationJacobian, PlainGoalsGiveTheKinematicsJacobianExactly) {
  for (const test::TestRig& r : test::rigs_like("ikea-lamp")) {
    Kinematics kin(r.rig);
    std::mt19937_64 rng(5);
    const Eigen::VectorXd a = test::random_angles(kin, rng);
    Eigen::VectorXd target(kin.num_residuals()), r1(kin.num_residuals()), r2(kin.num_residuals());
    kin.tips(test::random_angles(kin, rng), target);
    GoalSet goals;
    goals.set_positions(kin, target);
    Eigen::MatrixXd J1(kin.num_residuals(), kin.num_angles()), J2 = J1;
    const double E1 = goal_objective(kin, goals, a, r1);
    goal_jacobian(kin, goals, J1);
    kin.jacobian(a, r2, J2);
    r2 -= target;
    EXPECT_EQ(r1, r2);
    EXPECT_EQ(E1, 0.5 * r2.squaredNorm());
    EXPECT_EQ(J1, J2);
  }
}

}  // namespace
}  // namespace ik

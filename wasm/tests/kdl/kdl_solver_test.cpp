// The native bench's `kdl` method (native/kdl/kdl_solver.h): reaches reachable targets, respects
// the limits, honours the time budget, and its restarts follow the core's sequence.
#include <gtest/gtest.h>

#include <random>

#include "../../native/kdl/kdl_solver.h"
#include "../a7_fixtures.h"
#include "../small_rigs.h"
#include "kinematics.h"

namespace ik::test {
namespace {

// Targets the rig reaches: its tips at random angles inside the limits.
Eigen::VectorXd reachable_targets(Kinematics& kin, std::mt19937_64& rng) {
  Eigen::VectorXd tips(kin.num_residuals());
  kin.tips(random_angles(kin, rng), tips);
  return tips;
}

TEST(KdlSolver, ReachesReachableTargetsWithinTheLimits) {
  const Rig rig = straight_chain(4, {3});
  Kinematics kin(rig);
  kdl::KdlSolver solver(rig, SolverOptions());
  std::mt19937_64 rng(3);
  const Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());
  for (int k = 0; k < 20; ++k) {
    const Eigen::VectorXd target = reachable_targets(kin, rng);
    const kdl::KdlSummary& s = solver.solve(start, target);
    EXPECT_EQ(s.stop_reason, "converged_E") << k;
    EXPECT_LT(s.E, SolverOptions().error_tolerance);
    EXPECT_TRUE(s.reached);
    EXPECT_LE(s.angles.maxCoeff(), 90 + 1e-9);
    EXPECT_GE(s.angles.minCoeff(), -90 - 1e-9);
    Eigen::VectorXd tips(kin.num_residuals());
    kin.tips(s.angles, tips);  // our kinematics agrees that the solution is on target
    EXPECT_NEAR(0.5 * (tips - target).squaredNorm(), s.E, 1e-12);
  }
}

TEST(KdlSolver, TwoEffectorsWithATipTolerance) {
  Rig rig = straight_chain(4, {1, 3});
  Kinematics kin(rig);
  SolverOptions options;
  options.tip_tolerance = 1e-3;
  kdl::KdlSolver solver(rig, options);
  std::mt19937_64 rng(5);
  for (int k = 0; k < 10; ++k) {
    const kdl::KdlSummary& s = solver.solve(Eigen::VectorXd::Zero(kin.num_angles()), reachable_targets(kin, rng));
    EXPECT_EQ(s.stop_reason, "converged_E") << k;
    EXPECT_LT(s.tip_distance, 1e-3);
  }
}

TEST(KdlSolver, UnreachableTargetEndsOffTargetWithoutRestarts) {
  const Rig rig = straight_chain(2, {1});
  SolverOptions options;
  options.restarts = 0;
  kdl::KdlSolver solver(rig, options);
  const kdl::KdlSummary& s = solver.solve(Eigen::VectorXd::Zero(6), Eigen::Vector3d(10, 0, 0));
  EXPECT_FALSE(s.reached);
  EXPECT_EQ(s.restarts, 0);
  EXPECT_NEAR(s.tip_distance, 8, 1e-6);  // the straight chain is the closest point
}

TEST(KdlSolver, StopsAtTheIterationCapAndRejectsBadInput) {
  const Rig rig = straight_chain(3, {2});
  SolverOptions options;
  options.max_iterations = 1;
  kdl::KdlSolver solver(rig, options);
  EXPECT_EQ(solver.solve(Eigen::VectorXd::Zero(9), Eigen::Vector3d(0, 2, 1)).stop_reason, "max_iterations");
  EXPECT_EQ(solver.solve(Eigen::VectorXd::Zero(8), Eigen::Vector3d(0, 2, 1)).stop_reason, "invalid_input");
}

}  // namespace
}  // namespace ik::test

// Gauss-Newton outside paper mode takes its pseudo-inverse from the eigen-decomposition of J J^T
// up to 48 residuals (16 end effectors) and from the SVD of J above that. Both paths must give the
// Gauss-Newton step: from near a solution of a zero-residual problem, E falls quadratically. Far
// from it, no angle moves more than gn_max_step_deg in one step.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>
#include <random>

#include "solvers/solver_registry.h"

namespace ik {
namespace {

// A root bone with `branches` two-bone chains fanned out about z from its tip; effectors at the
// branch ends. Limits +-90 degrees.
Rig fan(int branches) {
  Rig rig;
  auto bone = [](int parent, const Eigen::Matrix4d& rest) {
    Bone b;
    b.parent = parent;
    b.length = 0.5;
    b.rest = rest;
    b.min_deg = Eigen::Vector3d::Constant(-90);
    b.max_deg = Eigen::Vector3d::Constant(90);
    return b;
  };
  rig.bones.push_back(bone(-1, Eigen::Matrix4d::Identity()));
  for (int k = 0; k < branches; ++k) {
    Eigen::Matrix4d rest = Eigen::Matrix4d::Identity();
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(2 * EIGEN_PI * k / branches, Eigen::Vector3d::UnitX()).toRotationMatrix() *
        Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    rest.topLeftCorner<3, 3>() = turn;
    rest.block<3, 1>(0, 3) = Eigen::Vector3d(0.5, 0, 0);
    rig.bones.push_back(bone(0, rest));
    rest.block<3, 1>(0, 3) += turn * Eigen::Vector3d(0.5, 0, 0);
    rig.bones.push_back(bone(static_cast<int>(rig.bones.size()) - 1, rest));
    rig.effectors.push_back(static_cast<int>(rig.bones.size()) - 1);
  }
  return rig;
}

class GaussNewtonSizes : public ::testing::TestWithParam<int> {};

TEST_P(GaussNewtonSizes, ConvergesQuadraticallyNearASolution) {
  Kinematics kin(fan(GetParam()));
  ASSERT_EQ(kin.num_residuals(), 3 * GetParam());
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd goal(kin.num_angles()), start(kin.num_angles()), target(kin.num_residuals());
  for (int i = 0; i < goal.size(); ++i) goal[i] = 40 * u(rng);
  for (int i = 0; i < goal.size(); ++i) start[i] = goal[i] + 0.5 * u(rng);
  kin.tips(goal, target);

  SolverOptions options;
  options.restarts = 0;
  options.error_tolerance = std::numeric_limits<double>::denorm_min();  // only an exact hit is on target
  options.gradient_tolerance = 0;
  options.time_budget_s = 0;
  options.max_iterations = 6;
  options.gn_singular_cutoff = 1e-8;  // keep every direction: the wide fan has weak ones
  auto gn = make_solver("gn", kin, options);
  gn->solve(start, target);
  const auto history = gn->error_history();
  ASSERT_GE(history.size(), 5);
  EXPECT_GT(history[0], 1e-4);
  // Quadratic: each step squares the error's scale (E_{k+1} <= C E_k^2); a first-order method
  // would only shrink it by a constant factor.
  EXPECT_LT(history[3], 1e-12);
  EXPECT_LT(history[2], 100 * history[1] * history[1] / history[0]);
}

// 8 effectors (24 residuals): the eigen-decomposition of J J^T; 20 (60 residuals): the SVD of J.
INSTANTIATE_TEST_SUITE_P(BothPaths, GaussNewtonSizes, ::testing::Values(8, 20));

// The largest change of one angle in gn's first step from rest towards a far target, degrees.
double first_step_size(double max_step_deg) {
  Kinematics kin(fan(2));
  Eigen::VectorXd goal = Eigen::VectorXd::Constant(kin.num_angles(), 80), target(kin.num_residuals());
  kin.tips(goal, target);
  SolverOptions options;
  options.restarts = 0;
  options.gn_max_step_deg = max_step_deg;
  auto gn = make_solver("gn", kin, options);
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  EXPECT_EQ(gn->start(rest, target), StopReason::running);
  EXPECT_TRUE(gn->step());
  return (gn->angles() - rest).cwiseAbs().maxCoeff();
}

TEST(GaussNewtonStep, MovesNoAngleFurtherThanTheCap) {
  EXPECT_GT(first_step_size(1e6), 20);  // uncapped, the first step is long
  const double capped = first_step_size(20);
  EXPECT_LE(capped, 20 + 1e-9);
  EXPECT_GT(capped, 0);
}

}  // namespace
}  // namespace ik

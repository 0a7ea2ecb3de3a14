// A solve that starts on a stationary point above the error tolerance: one bone along +x, target
// straight behind it at (-1, 0, 0). At rest grad E = J^T r = 0 (r is along the bone), yet the
// target is reachable by turning 180 degrees. E is at a maximum there, so a step along negative
// curvature leaves it (escape_saddles, on by default); so do restarts (every method).
#include <gtest/gtest.h>

#include <string>

#include "../small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

class StationaryStart : public ::testing::TestWithParam<std::string> {};

TEST_P(StationaryStart, AnEscapeOrARestartLeavesAStationaryStartAndWithNeitherTheSolveStopsThere) {
  Kinematics kin(test::one_bone());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3);
  const Eigen::Vector3d target(-1, 0, 0);

  SolverOptions neither;
  neither.restarts = 0;
  neither.escape_saddles = false;
  neither.chain_restarts = 0;
  auto plain = make_solver(GetParam(), kin, neither);
  EXPECT_EQ(plain->solve(rest, target).stop_reason, StopReason::converged_grad);
  EXPECT_EQ(plain->summary().iterations, 0);
  EXPECT_GT(plain->summary().E, 1.9);
  EXPECT_FALSE(plain->summary().reached);

  SolverOptions escaping;
  escaping.restarts = 0;
  auto escaper = make_solver(GetParam(), kin, escaping);
  const SolverSummary& e = escaper->solve(rest, target);
  EXPECT_EQ(e.stop_reason, StopReason::converged_E);
  EXPECT_TRUE(e.reached);
  EXPECT_GE(e.escapes, 1);
  EXPECT_EQ(e.restarts, 0);

  SolverOptions restarting;
  restarting.escape_saddles = false;
  auto restarter = make_solver(GetParam(), kin, restarting);
  const SolverSummary& r = restarter->solve(rest, target);
  EXPECT_EQ(r.stop_reason, StopReason::converged_E);
  EXPECT_GE(r.restarts, 1);
  EXPECT_EQ(r.escapes, 0);
  EXPECT_LT(r.E, SolverOptions{}.error_tolerance);

  SolverOptions paper;
  paper.paper_mode = true;  // the original had neither
  auto original = make_solver(GetParam(), kin, paper);
  EXPECT_EQ(original->solve(rest, target).restarts, 0);
  EXPECT_EQ(original->summary().escapes, 0);
  EXPECT_EQ(original->summary().stop_reason, StopReason::converged_grad);
}

// The gradient tolerance is absolute: a start whose |g| is under it yet far from 0 is not a
// stationary point. With restarts left the run goes on descending from there (no restart); without
// restarts the gradient test ends the solve at once, as the protocol has it.
TEST_P(StationaryStart, AGradientUnderTheToleranceButNotNearZeroKeepsDescendingWhenRestartsAreOn) {
  Kinematics kin(test::one_bone());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3);
  const Eigen::Vector3d target(0.9, 0.3, 0);  // reachable (|target| < 1), |g| at rest well above 0
  Eigen::VectorXd residual(3);
  Eigen::MatrixXd jacobian(3, 3);
  kin.forward(rest);
  kin.current_jacobian(jacobian);
  const double start_gradient = (jacobian.transpose() * (kin.tip(0) - target)).norm();
  ASSERT_GT(start_gradient, 0);

  SolverOptions options;
  options.gradient_tolerance = 2 * start_gradient;  // the test fires at the start, |g| = half of it
  options.error_tolerance = 1e-10;
  options.restarts = 0;
  options.chain_restarts = 0;
  auto plain = make_solver(GetParam(), kin, options);
  EXPECT_EQ(plain->solve(rest, target).stop_reason, StopReason::converged_grad);
  EXPECT_EQ(plain->summary().iterations, 0);

  options.restarts = 5;
  auto going_on = make_solver(GetParam(), kin, options);
  ASSERT_EQ(going_on->start(rest, target), StopReason::running);
  EXPECT_EQ(going_on->summary().restarts, 0);
  going_on->step();  // a descent step from the start (a restart may follow it once |g| is near 0)
  ASSERT_GE(going_on->error_history().size(), 2);
  EXPECT_LT(going_on->error_history()[1], going_on->summary().initial_E);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, StationaryStart, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace ik

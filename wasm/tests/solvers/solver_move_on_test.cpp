// How a run stopped off target moves on (solver_move_on.cpp): restarts first while any are left,
// a stalled run restarts too, and when the budget ends the solve with restarts left the stop
// reason says so rather than claiming a stationary point.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "../small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

class MoveOn : public ::testing::TestWithParam<std::string> {};

// One bone along +x with its target straight behind it: a stationary start off target.
TEST_P(MoveOn, RestartsComeBeforeEscapesWhileAnyAreLeft) {
  Kinematics kin(test::one_bone());
  SolverOptions options;
  options.time_budget_s = 0;
  auto solver = make_solver(GetParam(), kin, options);
  const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(3), Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(s.stop_reason, StopReason::converged_E);
  EXPECT_GE(s.restarts, 1);
  EXPECT_EQ(s.escapes, 0);
  EXPECT_EQ(s.chain_restarts, 0);
  EXPECT_GE(s.iterations, s.restarts);  // a restart counts as an iteration
}

TEST_P(MoveOn, TheBudgetNotTheProblemEndsASolveWithRestartsLeft) {
  Kinematics kin(test::one_bone());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3);
  const Eigen::Vector3d behind(-1, 0, 0);
  SolverOptions options;
  options.time_budget_s = 0;
  options.max_iterations = 0;  // no iteration, hence no restart, is allowed
  auto solver = make_solver(GetParam(), kin, options);
  EXPECT_EQ(solver->solve(rest, behind).stop_reason, StopReason::max_iterations);
  options.restarts = 0;  // chain restarts are still left
  solver->set_options(options);
  EXPECT_EQ(solver->solve(rest, behind).stop_reason, StopReason::max_iterations);
  options.chain_restarts = 0;  // nothing left: the start is a stationary point
  solver->set_options(options);
  EXPECT_EQ(solver->solve(rest, behind).stop_reason, StopReason::converged_grad);
}

// A target beyond the chain's reach: every run creeps towards the closest point, E falling by
// ever less. With a short stall_iterations the runs restart long before they stop.
TEST_P(MoveOn, AStalledRunRestarts) {
  Kinematics kin(test::straight_chain(4, {3}));
  const Eigen::VectorXd start = (Eigen::VectorXd(12) << 0, 40, 0, 0, 30, 0, 0, -50, 0, 0, 20, 0).finished();
  const Eigen::Vector3d far(0, 9, 0);
  SolverOptions options;
  options.time_budget_s = 0;
  options.error_tolerance = std::numeric_limits<double>::denorm_min();  // only an exact hit is on target
  options.gradient_tolerance = 0;
  options.max_iterations = 60;
  options.escape_saddles = false;
  options.chain_restarts = 0;
  auto solver = make_solver(GetParam(), kin, options);
  int restarts[2];
  for (int stall : {3, 1000}) {
    options.stall_iterations = stall;
    solver->set_options(options);
    const SolverSummary& s = solver->solve(start, far);
    EXPECT_EQ(s.stop_reason, StopReason::max_iterations);
    restarts[stall == 3 ? 0 : 1] = s.restarts;
  }
  EXPECT_GT(restarts[0], restarts[1]);
  EXPECT_GE(restarts[0], 5);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, MoveOn, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace ik

// A solve its budget cuts short, called again from its answer towards the same goals, goes on with
// the same run (Solver::go_on): the method's state (lm's damping, bfgs's inverse Hessian, gd's
// step), the soft rows' scale and the goals given up carry over, so that a slow machine's frames,
// one step each, add up to the solve a fast machine makes in one frame. For every method: a
// chain's tip brought to a target in one solve, and in solves of one iteration each, ends at the
// same angles after as many iterations.
#include <gtest/gtest.h>

#include <string>

#include "../small_rigs.h"
#include "registered_methods.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

SolverOptions options(int max_iterations) {
  SolverOptions o;
  o.tip_tolerance = 1e-7;
  o.gradient_tolerance = 1e-12;
  o.restarts = 0;
  o.time_budget_s = 0;
  o.max_iterations = max_iterations;
  return o;
}

class CutRun : public ::testing::TestWithParam<std::string> {};

TEST_P(CutRun, SolvesOfOneIterationEachEndWhereOneSolveEnds) {
  Kinematics kin(test::straight_chain(4, {3}));
  Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());
  start[1] = 20, start[5] = -30, start[7] = 25, start[10] = 15;  // bent: no singular start
  const Eigen::Vector3d target(1.5, 2.0, 0.5);

  auto whole = make_solver(GetParam(), kin, options(100000));
  const SolverSummary& one = whole->solve(start, target);
  ASSERT_TRUE(one.reached) << stop_reason_name(one.stop_reason);
  const Eigen::VectorXd answer = one.angles;
  const int iterations = one.iterations;

  auto cut = make_solver(GetParam(), kin, options(1));
  Eigen::VectorXd angles = start;
  int total = 0, calls = 0;
  for (; calls < 100000; ++calls) {
    const SolverSummary& s = cut->solve(angles, target);
    total += s.iterations;
    angles = s.angles;
    if (s.stop_reason != StopReason::max_iterations) {
      EXPECT_TRUE(s.reached) << stop_reason_name(s.stop_reason);
      break;
    }
  }
  EXPECT_EQ(total, iterations);
  EXPECT_LT((angles - answer).cwiseAbs().maxCoeff(), 1e-9) << "after " << calls << " calls";
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, CutRun, ::testing::ValuesIn(test::kMethods));

}  // namespace
}  // namespace ik

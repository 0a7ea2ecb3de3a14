// What start() refuses (solve_input.h), in order, with messages that say what is wrong.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "../allocation_counter.h"
#include "../small_rigs.h"
#include "solvers/solve_input.h"

namespace ik {
namespace {

constexpr int kNoLimit = 1 << 30;

TEST(SolveInput, AcceptsAGoodSolveWithoutAllocating) {
  Kinematics kin(test::two_bones());
  const SolverOptions options;
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(6), target = Eigen::VectorXd::Ones(3);
  const long before = test::heap_allocations();
  const std::string problem = check_solve_input(kin, options, "lm", kNoLimit, angles, target);
  EXPECT_EQ(test::heap_allocations() - before, 0);
  EXPECT_EQ(problem, "");
}

TEST(SolveInput, NamesTheFirstProblem) {
  Kinematics kin(test::two_bones());
  SolverOptions options;
  Eigen::VectorXd angles = Eigen::VectorXd::Zero(6), target = Eigen::VectorXd::Ones(3);
  const Eigen::VectorXd short_angles = Eigen::VectorXd::Zero(5), long_target = Eigen::VectorXd::Ones(6);
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, short_angles, target),
            "angles has 5 values, expected 6 (3 per bone)");
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, angles, long_target),
            "target has 6 values, expected 3 (3 per end effector)");
  angles[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, angles, target), "angles[4] is not a finite number");
  target[2] = std::numeric_limits<double>::infinity();
  angles[4] = 0;
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, angles, target), "target[2] is not a finite number");
  // A bad option comes first.
  options.error_tolerance = -1;
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, short_angles, target),
            "option error_tolerance must be a number > 0 (0 can never be met: on target means E < it, and E is "
            "never below 0)");
}

TEST(SolveInput, RefusesRigsOverTheMethodsSizeLimit) {
  Kinematics kin(test::two_bones());
  SolverOptions options;
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(6), target = Eigen::VectorXd::Ones(3);
  EXPECT_EQ(check_solve_input(kin, options, "newton", 6, angles, target), "");
  EXPECT_EQ(check_solve_input(kin, options, "newton", 3, angles, target),
            "newton takes rigs of at most 3 angles (1 bones); this one has 6: use lm or gd");
  options.paper_mode = true;
  EXPECT_EQ(check_solve_input(kin, options, "gd", 3, angles, target),
            "gd in paper mode takes rigs of at most 3 angles (1 bones); this one has 6: turn paper mode off");
}

}  // namespace
}  // namespace ik

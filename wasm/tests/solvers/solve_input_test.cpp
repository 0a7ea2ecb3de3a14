// What start() refuses (solve_input.h), in order, with messages that say what is wrong.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "../allocation_counter.h"
#include "../small_rigs.h"
#include "size_limits.h"
#include "solvers/solve_input.h"

namespace ik {
namespace {

constexpr int kNoLimit = 1 << 30;

TEST(SolveInput, AcceptsAGoodSolveWithoutAllocating) {
  Kinematics kin(test::two_bones());
  const SolverOptions options;
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(6), target = Eigen::VectorXd::Ones(3);
  const long before = test::heap_allocations();
  const std::string problem = check_solve_input(kin, options, "lm", kNoLimit, 3, angles, target);
  EXPECT_EQ(test::heap_allocations() - before, 0);
  EXPECT_EQ(problem, "");
}

TEST(SolveInput, NamesTheFirstProblem) {
  Kinematics kin(test::two_bones());
  SolverOptions options;
  Eigen::VectorXd angles = Eigen::VectorXd::Zero(6), target = Eigen::VectorXd::Ones(3);
  const Eigen::VectorXd short_angles = Eigen::VectorXd::Zero(5), long_target = Eigen::VectorXd::Ones(6);
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, 3, short_angles, target),
            "angles has 5 values, expected 6 (3 per bone)");
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, 3, angles, long_target),
            "target has 6 values, expected 3 (3 per end effector)");
  angles[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, 3, angles, target),
            "angles[4] is NaN, not a finite number");
  target[2] = std::numeric_limits<double>::infinity();
  angles[4] = 0;
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, 3, angles, target),
            "target[2] is Infinity, not a finite number");
  // A bad option comes first.
  options.error_tolerance = -1;
  EXPECT_EQ(check_solve_input(kin, options, "lm", kNoLimit, 3, short_angles, target),
            "option error_tolerance must be a number > 0 (0 can never be met: on target means E < it, and E is "
            "never below 0)");
}

TEST(SolveInput, RefusesRigsOverTheMethodsSizeLimit) {
  Kinematics kin(test::two_bones());
  SolverOptions options;
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(6), target = Eigen::VectorXd::Ones(3);
  EXPECT_EQ(check_solve_input(kin, options, "newton", 6, 3, angles, target), "");
  EXPECT_EQ(check_solve_input(kin, options, "newton", 3, 3, angles, target),
            "newton takes rigs of at most 3 angles (1 bones); this one has 6: use lm or gd");
  options.paper_mode = true;
  EXPECT_EQ(check_solve_input(kin, options, "gd", 3, 3, angles, target),
            "gd in paper mode takes rigs of at most 3 angles (1 bones); this one has 6: turn paper mode off");
}

TEST(SolveInput, DenseMethodsTakeFewerAnglesWithMoreRows) {
  EXPECT_EQ(dense_angle_limit(3), kMaxDenseAngles);
  EXPECT_EQ(dense_angle_limit(kDenseRows), kMaxDenseAngles);
  int previous = kMaxDenseAngles;
  for (int rows : {51, 99, 195, 300}) {  // 16 effectors and 1, 17, 49 poles; a rest pull
    const int limit = dense_angle_limit(rows);
    EXPECT_LT(limit, previous) << rows;
    EXPECT_EQ(limit % 3, 0) << rows;
    EXPECT_GT(limit, 30) << rows;
    previous = limit;
  }
  EXPECT_EQ(dense_angle_limit(1000), 3);  // the rows alone cost more than the budget
  Kinematics kin(test::two_bones());
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(6), target = Eigen::VectorXd::Ones(3);
  EXPECT_EQ(check_solve_input(kin, SolverOptions{}, "newton", 3, 200, angles, target),
            "newton takes rigs of at most 3 angles (1 bones) with goals of 200 residual rows (poles and a rest "
            "pull add rows); this one has 6: use lm or gd");
}

}  // namespace
}  // namespace ik

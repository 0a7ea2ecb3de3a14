// The clip-on-the-limit active set (active_set.h) on a toy system: the angles share one
// residual, "move their sum by b", solved with the least-norm step (each angle in the set moves by
// the remainder over their count). Fixing an angle on a limit hands its share to the others.
#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "../allocation_counter.h"
#include "solvers/active_set.h"

namespace ik {
namespace {

struct SharedSum {
  double remainder = 0;  // what the angles in the set must still add up to, degrees
  double share = 0;      // each one's step from the last solve
  int solves = 0;
};

// Runs the active set on the toy system with `b` to add, and returns the status.
ActiveSet::Status run_shared_sum(ActiveSet& set, const Eigen::VectorXd& angles, const Eigen::VectorXd& lower,
                                 const Eigen::VectorXd& upper, const std::vector<int>& free, double b,
                                 ActiveSet::Fix fix, SharedSum& system, const Deadline& deadline = Deadline()) {
  system.remainder = b;
  const auto solve = [&] {
    ++system.solves;
    const double count = set.mask().sum();
    system.share = count > 0 ? system.remainder / count : 0;
    return true;
  };
  const auto proposed = [&](int) { return system.share; };
  const auto take_out = [&](int, double step) { system.remainder -= step; };
  return set.run(angles, lower, upper, free, static_cast<int>(free.size()), fix, deadline, solve, proposed, take_out);
}

TEST(ActiveSet, AFixedAngleHandsItsShareToTheOthers) {
  ActiveSet set;
  set.resize(3);
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(3);
  const Eigen::VectorXd lo = (Eigen::VectorXd(3) << -5, -100, -100).finished();
  const Eigen::VectorXd hi = (Eigen::VectorXd(3) << 5, 100, 100).finished();
  SharedSum system;
  EXPECT_EQ(run_shared_sum(set, a, lo, hi, {0, 1, 2}, 30, ActiveSet::Fix::past_limit, system), ActiveSet::Status::done);
  // Pass 1: 10 each, angle 0 fixed at its limit 5; pass 2: the other two share 25 and stay inside.
  EXPECT_EQ(system.solves, 2);
  EXPECT_DOUBLE_EQ(set.step()[0], 5);
  EXPECT_DOUBLE_EQ(set.step()[1], 12.5);
  EXPECT_DOUBLE_EQ(set.step()[2], 12.5);
  EXPECT_EQ(set.mask(), (Eigen::VectorXd(3) << 0, 1, 1).finished());
}

TEST(ActiveSet, AnglesThatAreNotFreeNeitherMoveNorShare) {
  ActiveSet set;
  set.resize(4);
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(4);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(4, -100), hi = Eigen::VectorXd::Constant(4, 100);
  SharedSum system;
  run_shared_sum(set, a, lo, hi, {1, 3}, 10, ActiveSet::Fix::past_limit, system);
  EXPECT_EQ(set.step(), (Eigen::VectorXd(4) << 0, 5, 0, 5).finished());
  EXPECT_EQ(set.mask(), (Eigen::VectorXd(4) << 0, 1, 0, 1).finished());
}

TEST(ActiveSet, OnLimitOnlyHoldsAnglesOnALimitAndLetsTheOthersPass) {
  ActiveSet set;
  set.resize(3);
  // Angle 0 sits on its upper limit, angle 1 inside; both would pass their upper limit.
  const Eigen::VectorXd a = (Eigen::VectorXd(3) << 5, 0, 0).finished();
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(3, -5);
  const Eigen::VectorXd hi = (Eigen::VectorXd(3) << 5, 5, 100).finished();
  SharedSum held;
  run_shared_sum(set, a, lo, hi, {0, 1, 2}, 30, ActiveSet::Fix::on_limit_only, held);
  EXPECT_DOUBLE_EQ(set.step()[0], 0);   // held on its limit
  EXPECT_DOUBLE_EQ(set.step()[1], 15);  // past its limit: left for the line search to project
  EXPECT_DOUBLE_EQ(set.step()[2], 15);
  SharedSum fixed;
  run_shared_sum(set, a, lo, hi, {0, 1, 2}, 30, ActiveSet::Fix::past_limit, fixed);
  EXPECT_DOUBLE_EQ(set.step()[0], 0);
  EXPECT_DOUBLE_EQ(set.step()[1], 5);  // fixed on its limit
  EXPECT_DOUBLE_EQ(set.step()[2], 25);
}

TEST(ActiveSet, StopsAfterItsPassesAndWhenTheSolveFails) {
  ActiveSet set;
  const int n = 8;
  set.resize(n);
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(n, -1), hi = Eigen::VectorXd::Constant(n, 1);
  std::vector<int> free(n);
  for (int i = 0; i < n; ++i) free[i] = i;
  // Pass k proposes a step past the limit for angle k only: every pass fixes one more angle.
  int solves = 0;
  const auto solve = [&] {
    ++solves;
    return true;
  };
  const auto proposed = [&](int i) { return i == solves - 1 ? 10.0 : 0.0; };
  int taken_out = 0;
  const auto take_out = [&](int, double) { ++taken_out; };
  EXPECT_EQ(set.run(a, lo, hi, free, n, ActiveSet::Fix::past_limit, Deadline(), solve, proposed, take_out),
            ActiveSet::Status::done);
  EXPECT_EQ(solves, ActiveSet::kPasses);
  EXPECT_EQ(taken_out, ActiveSet::kPasses);
  EXPECT_EQ(set.mask().sum(), n - ActiveSet::kPasses);

  solves = 0;
  const auto failing = [&] { return ++solves < 2; };
  EXPECT_EQ(set.run(a, lo, hi, free, n, ActiveSet::Fix::past_limit, Deadline(), failing, proposed, take_out),
            ActiveSet::Status::solve_failed);
  EXPECT_EQ(solves, 2);
}

TEST(ActiveSet, GivesUpOnAPassedDeadlineEvery64Angles) {
  const int n = 64;
  ActiveSet set;
  set.resize(n);
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(n, -100), hi = Eigen::VectorXd::Constant(n, 100);
  std::vector<int> free(n);
  for (int i = 0; i < n; ++i) free[i] = i;
  const Deadline passed(Deadline::Clock::now() - std::chrono::seconds(1));
  SharedSum system;
  EXPECT_EQ(run_shared_sum(set, a, lo, hi, free, 1, ActiveSet::Fix::past_limit, system, passed),
            ActiveSet::Status::out_of_time);
  // Fewer angles than 64 are never interrupted.
  free.resize(63);
  EXPECT_EQ(run_shared_sum(set, a, lo, hi, free, 1, ActiveSet::Fix::past_limit, system, passed),
            ActiveSet::Status::done);
}

TEST(ActiveSet, RunAllocatesNothing) {
  ActiveSet set;
  set.resize(3);
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(3);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(3, -5), hi = Eigen::VectorXd::Constant(3, 5);
  const std::vector<int> free = {0, 1, 2};
  SharedSum system;
  const long before = test::heap_allocations();
  run_shared_sum(set, a, lo, hi, free, 100, ActiveSet::Fix::past_limit, system);
  EXPECT_EQ(test::heap_allocations() - before, 0);
  EXPECT_EQ(set.step(), Eigen::VectorXd::Constant(3, 5));
}

}  // namespace
}  // namespace ik

// Whole restarts (restarts.h): the stall test, and start points that are deterministic per seed,
// inside the limits and counted.
#include <gtest/gtest.h>

#include <limits>

#include "../allocation_counter.h"
#include "solvers/quasi_random.h"
#include "solvers/restarts.h"

namespace ik {
namespace {

TEST(Restarts, ARunStallsWhenItsBestEFallsByLessThanTenPercentForStallIterations) {
  Restarts r;
  r.begin_solve(3, 1);
  EXPECT_FALSE(r.stalls(1.0, 3));   // the run's first E is its best
  EXPECT_FALSE(r.stalls(0.95, 3));  // 5% lower does not count as progress
  EXPECT_FALSE(r.stalls(0.92, 3));
  EXPECT_TRUE(r.stalls(0.91, 3));  // 3 steps since the best
  // A new run starts counting again; a 10% fall is progress.
  r.begin_run();
  EXPECT_FALSE(r.stalls(1.0, 2));
  EXPECT_FALSE(r.stalls(0.89, 2));
  EXPECT_FALSE(r.stalls(0.79, 2));
  EXPECT_FALSE(r.stalls(0.78, 2));
  EXPECT_TRUE(r.stalls(0.78, 2));
}

TEST(Restarts, StartsAreInsideTheLimitsCountedAndFollowTheSeed) {
  const Eigen::VectorXd lower = (Eigen::VectorXd(3) << -10, 0, 5).finished();
  const Eigen::VectorXd upper = (Eigen::VectorXd(3) << 10, 90, 5).finished();
  Restarts r;
  r.begin_solve(3, 7);
  Eigen::VectorXd first(3), second(3), again(3);
  r.next_start(lower, upper, first);
  r.next_start(lower, upper, second);
  EXPECT_EQ(r.used(), 2);
  for (const Eigen::VectorXd* a : {&first, &second}) {
    EXPECT_TRUE(((a->array() >= lower.array()) && (a->array() <= upper.array())).all());
    EXPECT_EQ((*a)[2], 5);  // a fixed angle keeps its value
  }
  EXPECT_NE(first, second);
  // The quasi-random sequence's points 1, 2, ... of the seed.
  Eigen::VectorXd unit(3), expected(3);
  QuasiRandom(3, 7).point(1, unit);
  point_in_limits(unit, lower, upper, expected);
  EXPECT_EQ(first, expected);
  // A new solve starts the count again and repeats the starts; another seed gives others.
  r.begin_solve(3, 7);
  EXPECT_EQ(r.used(), 0);
  r.next_start(lower, upper, again);
  EXPECT_EQ(again, first);
  r.begin_solve(3, 8);
  r.next_start(lower, upper, again);
  EXPECT_NE(again, first);
}

TEST(Restarts, ARestartBeginsANewRun) {
  const Eigen::VectorXd lower = Eigen::VectorXd::Constant(2, -1), upper = Eigen::VectorXd::Constant(2, 1);
  Eigen::VectorXd start(2);
  Restarts r;
  r.begin_solve(2, 1);
  EXPECT_FALSE(r.stalls(1.0, 1));
  r.next_start(lower, upper, start);
  EXPECT_FALSE(r.stalls(1.0, 1));  // the first E of the new run, not a step without progress
  EXPECT_TRUE(r.stalls(1.0, 1));
}

TEST(Restarts, AllocateOnlyWhenTheSizeOrSeedChanges) {
  const Eigen::VectorXd lower = Eigen::VectorXd::Constant(4, -1), upper = Eigen::VectorXd::Constant(4, 1);
  Eigen::VectorXd start(4);
  Restarts r;
  r.begin_solve(4, 3);
  const long before = test::heap_allocations();
  r.begin_solve(4, 3);
  r.next_start(lower, upper, start);
  r.stalls(1.0, 5);
  EXPECT_EQ(test::heap_allocations() - before, 0);
  r.begin_solve(5, 3);
  EXPECT_GT(test::heap_allocations() - before, 0);
}

// Restart points span a range up to one turn wide whole, beyond +-180 too (a Jaco2 joint's
// 47..313 degrees), and one turn of a wider or unbounded range, the one nearest -180..180.
TEST(Restarts, PointsSpanEachRangeUpToOneTurn) {
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::VectorXd lower(5), upper(5);
  lower << 47, -10, -inf, -inf, 50;
  upper << 313, 400, inf, 100, inf;
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(5, inf), hi = Eigen::VectorXd::Constant(5, -inf), unit(5), p(5);
  QuasiRandom q(5, 1);
  for (int k = 1; k <= 2000; ++k) {
    q.point(k, unit);
    point_in_limits(unit, lower, upper, p);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::VectorXd want_lo = (Eigen::VectorXd(5) << 47, -10, -180, -260, 50).finished();
  const Eigen::VectorXd want_hi = (Eigen::VectorXd(5) << 313, 350, 180, 100, 410).finished();
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(lo[i], want_lo[i], 1.0) << i;
    EXPECT_NEAR(hi[i], want_hi[i], 1.0) << i;
    EXPECT_GE(lo[i], want_lo[i]) << i;
    EXPECT_LE(hi[i], want_hi[i]) << i;
  }
}

}  // namespace
}  // namespace ik

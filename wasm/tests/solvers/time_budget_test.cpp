// A solve's time budget (time_budget.h). The calls are opened at chosen past instants, so the
// tests read the clock but depend on no duration of their own.
#include <gtest/gtest.h>

#include <chrono>
#include <limits>

#include "solvers/time_budget.h"

namespace ik {
namespace {

using Clock = TimeBudget::Clock;

Clock::time_point seconds_ago(double s) {
  return Clock::now() - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

TEST(TimeBudget, NoBudgetNeverRunsOut) {
  for (double budget : {0.0, std::numeric_limits<double>::infinity(), 1e9}) {
    TimeBudget clock;
    clock.reset(budget);
    clock.open(seconds_ago(3600));
    EXPECT_FALSE(clock.deadline().passed()) << budget;
    clock.close();
    EXPECT_FALSE(clock.used_up()) << budget;
    EXPECT_GE(clock.spent(), 3600) << budget;
  }
}

TEST(TimeBudget, ACallPastItsBudgetIsOutOfTime) {
  TimeBudget clock;
  clock.reset(1);
  EXPECT_TRUE(clock.limited());
  clock.open(seconds_ago(10));
  EXPECT_TRUE(clock.deadline().passed());
  EXPECT_FALSE(clock.used_up());  // only closed calls count as spent
  clock.close();
  EXPECT_TRUE(clock.used_up());
  EXPECT_GE(clock.spent(), 10);
  EXPECT_GE(clock.last_read(), clock.call_start());
}

TEST(TimeBudget, TheDeadlineAllowsOnlyWhatTheEarlierCallsLeft) {
  TimeBudget clock;
  clock.reset(100);
  clock.open(seconds_ago(60));
  clock.close();
  EXPECT_FALSE(clock.used_up());
  clock.open(seconds_ago(50));  // 60 + 50 > 100
  EXPECT_TRUE(clock.deadline().passed());
  clock.open(seconds_ago(20));  // 60 + 20 < 100
  EXPECT_FALSE(clock.deadline().passed());
  clock.close();
  EXPECT_GE(clock.spent(), 80);
  // A new solve has spent nothing.
  clock.reset(100);
  EXPECT_EQ(clock.spent(), 0);
  clock.open(seconds_ago(50));
  EXPECT_FALSE(clock.deadline().passed());
}

}  // namespace
}  // namespace ik

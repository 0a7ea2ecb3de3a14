// The core's check of a caller's numbers (finite_numbers.h): the first non-finite entry, named as
// JavaScript writes it, or nothing.
#include <gtest/gtest.h>

#include <limits>

#include "finite_numbers.h"

namespace ik {
namespace {

TEST(FiniteNumbers, NamesTheFirstNonFiniteEntryAsJavaScriptWritesIt) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double values[] = {0, -1e308, 2, nan, inf};
  EXPECT_EQ(non_finite_entry(values, 3, "angles"), "");
  EXPECT_EQ(non_finite_entry(values, 5, "angles"), "angles[3] is NaN, not a finite number");
  const double infinities[] = {1, inf, -inf};
  EXPECT_EQ(non_finite_entry(infinities, 3, "target"), "target[1] is Infinity, not a finite number");
  EXPECT_EQ(non_finite_entry(infinities + 2, 1, "target"), "target[0] is -Infinity, not a finite number");
  EXPECT_EQ(non_finite_entry(values, 0, "angles"), "");
}

}  // namespace
}  // namespace ik

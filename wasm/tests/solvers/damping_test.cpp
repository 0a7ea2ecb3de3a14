// Nielsen's damping update (damping.h): the gain ratio decides, mu moves by the rule's factors
// and stays within its bounds, nu doubles up to its cap.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "solvers/damping.h"

namespace ik {
namespace {

TEST(NielsenDamping, AGoodStepShrinksMuByTheGainRatio) {
  NielsenDamping d;
  d.reset(3);
  EXPECT_EQ(d.mu(), 3);
  EXPECT_EQ(d.nu(), 2);
  // rho = 1 (the model was exact): mu *= max(1/3, 1 - 1) = 1/3.
  EXPECT_TRUE(d.accept(10, 8, 2));
  EXPECT_DOUBLE_EQ(d.mu(), 1);
  // rho = 1/2: mu *= 1 - 0 = 1.
  EXPECT_TRUE(d.accept(10, 9, 2));
  EXPECT_DOUBLE_EQ(d.mu(), 1);
  // rho = 1/4: mu *= 1 - (-1/2)^3 = 9/8.
  EXPECT_TRUE(d.accept(10, 9.5, 2));
  EXPECT_DOUBLE_EQ(d.mu(), 9.0 / 8);
  EXPECT_EQ(d.nu(), 2);
}

TEST(NielsenDamping, RejectionsGrowMuByNuWhichDoublesUpToItsCap) {
  NielsenDamping d;
  d.reset(1);
  double mu = 1, nu = 2;
  for (int k = 0; k < 10; ++k) {
    EXPECT_FALSE(d.accept(1, 2, 1));  // E rose
    mu *= nu;
    nu = std::min(2 * nu, NielsenDamping::kMaxNu);
    EXPECT_DOUBLE_EQ(d.mu(), mu);
    EXPECT_EQ(d.nu(), nu);
  }
  EXPECT_EQ(d.nu(), 64);
  // An accepted step resets nu.
  EXPECT_TRUE(d.accept(10, 8, 2));
  EXPECT_EQ(d.nu(), 2);
}

TEST(NielsenDamping, RefusesStepsTheModelDidNotPredictOrThatGainTooLittle) {
  NielsenDamping d;
  d.reset(1);
  EXPECT_FALSE(d.accept(1, 0.5, 0));       // no decrease predicted
  EXPECT_FALSE(d.accept(1, 0.5, -1));      // an increase predicted
  EXPECT_FALSE(d.accept(1, 1 - 1e-5, 1));  // rho = 1e-5 < kMinGain
  EXPECT_FALSE(d.accept(1, std::numeric_limits<double>::quiet_NaN(), 1));
  EXPECT_FALSE(d.accept(1, 1, 1));        // no decrease
  EXPECT_TRUE(d.accept(1, 1 - 1e-3, 1));  // rho = 1e-3
}

TEST(NielsenDamping, MuStaysWithinItsBounds) {
  NielsenDamping d;
  d.reset(1);
  for (int k = 0; k < 100; ++k) d.accept(10, 8, 2);  // mu /= 3 each time
  EXPECT_EQ(d.mu(), NielsenDamping::kMinMu);
  d.reset(1e15);
  for (int k = 0; k < 10; ++k) d.accept(1, 2, 1);
  EXPECT_EQ(d.mu(), NielsenDamping::kMaxMu);
}

TEST(NielsenDamping, ShiftAndIndefiniteGrowth) {
  NielsenDamping d;
  d.reset(2);
  // (mu * relative_error2 + floor) * scale
  EXPECT_DOUBLE_EQ(d.shift(0.25, 0.5, 4), (2 * 0.25 + 0.5) * 4);
  d.grow_for_indefinite();
  EXPECT_EQ(d.mu(), 8);
  EXPECT_EQ(d.nu(), 2);  // an indefinite matrix is no rejected trial
  d.reset(1e-12);
  d.grow_for_indefinite();  // from a tiny mu: at least 4e-6
  EXPECT_DOUBLE_EQ(d.mu(), 4e-6);
  d.reset(1e16);
  d.grow_for_indefinite();
  EXPECT_EQ(d.mu(), NielsenDamping::kMaxMu);
}

}  // namespace
}  // namespace ik

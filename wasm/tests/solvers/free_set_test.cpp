// The free angles (free_set.h): fixed angles and angles that the gradient pushes past the limit
// they sit on are blocked; every other angle is free, and only free angles count in |g|.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solvers/free_set.h"

namespace ik {
namespace {

TEST(FreeSet, BlocksFixedAnglesAndAnglesPushedPastTheirLimit) {
  // 0 fixed; 1 on its lower limit, pushed out (g > 0: -g points down); 2 on its lower limit,
  // pulled in; 3 on its upper limit, pushed out (g < 0); 4 on its upper limit, pulled in;
  // 5 inside; 6 on a limit with g = 0.
  const Eigen::VectorXd lower = (Eigen::VectorXd(7) << 10, -90, -90, -90, -90, -90, -90).finished();
  const Eigen::VectorXd upper = (Eigen::VectorXd(7) << 10, 90, 90, 90, 90, 90, 90).finished();
  const Eigen::VectorXd angles = (Eigen::VectorXd(7) << 10, -90, -90, 90, 90, 0, 90).finished();
  const Eigen::VectorXd g = (Eigen::VectorXd(7) << 5, 1, -2, -3, 4, 12, 0).finished();
  std::vector<int> free(7, -1);
  Eigen::VectorXd mask(7);
  const FreeAngles found = find_free_angles(angles, lower, upper, g, free, mask);
  EXPECT_EQ(found.count, 4);
  EXPECT_EQ(std::vector<int>(free.begin(), free.begin() + found.count), (std::vector<int>{2, 4, 5, 6}));
  EXPECT_EQ(mask, (Eigen::VectorXd(7) << 0, 0, 1, 0, 1, 1, 1).finished());
  EXPECT_DOUBLE_EQ(found.gradient_norm, std::sqrt(4.0 + 16 + 144 + 0));
}

TEST(FreeSet, EveryAngleInsideItsLimitsIsFree) {
  const Eigen::VectorXd lower = Eigen::VectorXd::Constant(3, -1), upper = Eigen::VectorXd::Constant(3, 1);
  const Eigen::VectorXd angles = Eigen::VectorXd::Zero(3), g = (Eigen::VectorXd(3) << 3, 0, -4).finished();
  std::vector<int> free(3);
  Eigen::VectorXd mask(3);
  const FreeAngles found = find_free_angles(angles, lower, upper, g, free, mask);
  EXPECT_EQ(found.count, 3);
  EXPECT_EQ(free, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(mask, Eigen::VectorXd::Ones(3));
  EXPECT_DOUBLE_EQ(found.gradient_norm, 5);
}

}  // namespace
}  // namespace ik

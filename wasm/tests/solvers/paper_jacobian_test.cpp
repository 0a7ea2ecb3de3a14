// Paper mode's Jacobian (paper_jacobian.h) reproduces the original's division by h: twice the
// derivative away from the limits, the derivative itself on a limit, 0 for a fixed angle.
#include <gtest/gtest.h>

#include "../small_rigs.h"
#include "solvers/paper_jacobian.h"

namespace ik {
namespace {

struct Jacobians {
  Eigen::MatrixXd paper, exact;
};

Jacobians both(Kinematics& kin, const Eigen::VectorXd& angles, double h) {
  const int m = kin.num_residuals(), n = kin.num_angles();
  Eigen::VectorXd scratch(n), plus(m), minus(m), tips(m);
  Jacobians j{Eigen::MatrixXd(m, n), Eigen::MatrixXd(m, n)};
  paper_jacobian(kin, angles, h, scratch, plus, minus, j.paper);
  kin.jacobian(angles, tips, j.exact);
  return j;
}

TEST(PaperJacobian, IsTwiceTheDerivativeAwayFromTheLimits) {
  Kinematics kin(test::straight_chain(2, {1}));
  const Eigen::VectorXd angles = (Eigen::VectorXd(6) << 10, 20, -30, 5, -15, 40).finished();
  const Jacobians j = both(kin, angles, 1e-5);
  EXPECT_LT((j.paper - 2 * j.exact).norm(), 1e-7 * j.exact.norm());
}

TEST(PaperJacobian, IsTheDerivativeOnALimitAndZeroForAFixedAngle) {
  Rig rig = test::straight_chain(2, {1});
  rig.bones[0].min_deg[2] = rig.bones[0].max_deg[2] = 0;  // angle 2 fixed
  Kinematics kin(rig);
  // Angle 1 on its upper limit, angle 3 on its lower one.
  const Eigen::VectorXd angles = (Eigen::VectorXd(6) << 10, 90, 0, -90, -15, 40).finished();
  const Jacobians j = both(kin, angles, 1e-5);
  for (int c : {1, 3}) {
    EXPECT_GT(j.exact.col(c).norm(), 1e-4) << c;
    EXPECT_LT((j.paper.col(c) - j.exact.col(c)).norm(), 1e-4 * j.exact.col(c).norm()) << c;
  }
  for (int c : {0, 4}) EXPECT_LT((j.paper.col(c) - 2 * j.exact.col(c)).norm(), 1e-7 * j.exact.norm()) << c;
  EXPECT_EQ(j.paper.col(2).norm(), 0);
  EXPECT_GT(j.exact.col(2).norm(), 1e-4);  // the true derivative of the fixed angle is not 0
}

TEST(PaperJacobian, LeavesTheRigPosedAtTheAngles) {
  Kinematics kin(test::two_bones());
  const Eigen::VectorXd angles = (Eigen::VectorXd(6) << 10, 20, 30, 40, 50, 60).finished();
  Eigen::VectorXd scratch(6), plus(3), minus(3), tips(3), posed(3);
  Eigen::MatrixXd jac(3, 6);
  paper_jacobian(kin, angles, 1e-7, scratch, plus, minus, jac);
  kin.current_tips(posed);
  kin.tips(angles, tips);
  EXPECT_EQ(posed, tips);
}

}  // namespace
}  // namespace ik

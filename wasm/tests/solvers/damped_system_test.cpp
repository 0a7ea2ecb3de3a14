// The residual-size damped system (damped_system.h) and the rank-one downdate of its Cholesky
// factor (small_cholesky.h): taking columns out gives the solution of the system formed without
// them, whether the factor was downdated or (a downdate refused) factored afresh.
#include <gtest/gtest.h>

#include <random>

#include "../allocation_counter.h"
#include "../small_rigs.h"
#include "goal_residual.h"
#include "kinematics.h"
#include "solvers/block_pattern.h"
#include "solvers/damped_system.h"
#include "solvers/small_cholesky.h"

namespace ik {
namespace {

Eigen::MatrixXd lower_factor(const Eigen::MatrixXd& a) {
  Eigen::MatrixXd f = a;
  EXPECT_TRUE(small_cholesky(f, static_cast<int>(a.rows())));
  return f.triangularView<Eigen::Lower>();
}

TEST(SmallCholesky, ADowndateGivesTheFactorOfTheMatrixLessTheColumn) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  const int n = 12;
  Eigen::MatrixXd J(n, 30);
  for (int i = 0; i < J.size(); ++i) J.data()[i] = normal(rng);
  J.block(0, 7, 4, 1).setZero();  // a column that leaves the first rows alone (skipped pivots)
  const Eigen::MatrixXd a = J * J.transpose() + 1e-3 * Eigen::MatrixXd::Identity(n, n);
  for (int column : {0, 7, 29}) {
    Eigen::MatrixXd factor = a;
    ASSERT_TRUE(small_cholesky(factor, n));
    Eigen::VectorXd v = J.col(column);
    ASSERT_TRUE(small_cholesky_downdate(factor, n, v));
    const Eigen::MatrixXd expected = lower_factor(a - J.col(column) * J.col(column).transpose());
    EXPECT_LT((Eigen::MatrixXd(factor.triangularView<Eigen::Lower>()) - expected).norm(), 1e-12 * expected.norm())
        << "column " << column;
  }
}

TEST(SmallCholesky, ADowndateThatWouldLoseTheFactorIsRefused) {
  // [[1, 0], [0, 1]] less v v^T with v = (1 - 1e-9, 0): the first pivot falls to 4.5e-5 of itself.
  Eigen::MatrixXd factor = Eigen::MatrixXd::Identity(2, 2);
  Eigen::VectorXd v(2);
  v << 1 - 1e-9, 0;
  EXPECT_FALSE(small_cholesky_downdate(factor, 2, v));
  // Past singular: not positive definite at all.
  factor = Eigen::MatrixXd::Identity(2, 2);
  v << 0.3, 1.2;
  EXPECT_FALSE(small_cholesky_downdate(factor, 2, v));
}

// The system of two floating arms' position goals: J W J^T + lambda I over all the angles, with
// some taken out; compared with the system formed directly without them.
TEST(DampedSystem, TakingColumnsOutSolvesTheSystemWithoutThem) {
  Kinematics kin(test::two_arms(true));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> angle(-60, 60);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(kin.num_angles());
  for (int j = 0; j < 15; ++j) a[j] = angle(rng);
  kin.forward(a);
  GoalSet goals;
  Eigen::VectorXd target(6);
  target << 1, 2, 0.5, -1, 1.5, 0.3;
  goals.set_positions(kin, target);
  const int m = goals.rows(), n = kin.num_angles();
  Eigen::MatrixXd J(m, n);
  goal_jacobian(kin, goals, J);
  BlockPattern pattern;
  pattern.build(kin, goals);
  pattern.set_root_weight(0.25);
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(m, m);
  for (int j = 0; j < n; ++j) pattern.accumulate(J, j, normal);
  pattern.symmetrize(normal);
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(m, -1, 1);
  const double lambda = 1e-2;

  // Each angle out of 3 with a known move of 0.1 j degrees; the root's x as well.
  DampedSystem system;
  system.resize(m);
  Eigen::MatrixXd direct = lambda * Eigen::MatrixXd::Identity(m, m);
  Eigen::VectorXd rhs = r;
  std::vector<int> out;
  for (int j = 0; j < n; ++j) {
    if (j % 3 == 1 || j == 15) {
      out.push_back(j);
      rhs += 0.1 * j * J.col(j);
    } else {
      direct += pattern.weight(j) * J.col(j) * J.col(j).transpose();
    }
  }
  const Eigen::VectorXd expected = direct.llt().solve(rhs);
  for (bool refactor : {false, true}) {
    system.begin(normal, r);
    system.shift().setConstant(lambda);
    if (!refactor) {
      ASSERT_TRUE(system.solve());  // factored: each take_out downdates
    }
    const long allocations = test::heap_allocations();
    for (int j : out) system.take_out(pattern, J, j, 0.1 * j);
    ASSERT_TRUE(system.solve());
    EXPECT_EQ(test::heap_allocations(), allocations);
    EXPECT_LT((system.y() - expected).norm(), 1e-10 * expected.norm()) << (refactor ? "factored afresh" : "downdated");
  }
}

}  // namespace
}  // namespace ik

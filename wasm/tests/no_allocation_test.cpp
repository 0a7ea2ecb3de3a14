// Proves that forward kinematics, the Jacobian and the gradient allocate nothing after set-up.
#include <gtest/gtest.h>

#include "a7_fixtures.h"
#include "allocation_counter.h"
#include "finite_difference_jacobian.h"
#include "objective.h"

namespace ik {
namespace {

void expect_no_allocation(const Rig& rig) {
  Kinematics kin(rig);
  std::mt19937_64 rng(7);
  const Eigen::VectorXd a = test::random_angles(kin, rng);
  Eigen::VectorXd target(kin.num_residuals()), r(kin.num_residuals()), g(kin.num_angles());
  Eigen::VectorXd scratch(kin.num_angles()), plus(kin.num_residuals()), minus(kin.num_residuals());
  Eigen::MatrixXd jac(kin.num_residuals(), kin.num_angles());
  kin.tips(test::random_angles(kin, rng), target);

  const long before = test::heap_allocations();
  kin.forward(a);
  kin.tips(a, r);
  kin.jacobian(a, r, jac);
  objective(kin, a, target, r);
  objective_and_gradient(kin, a, target, r, jac, g);
  finite_difference_jacobian(kin, a, 1e-7, true, scratch, plus, minus, jac);
  kin.project(scratch);
  EXPECT_EQ(test::heap_allocations() - before, 0);

  // The counter itself works: a fresh Eigen vector is counted.
  const long probe = test::heap_allocations();
  Eigen::VectorXd fresh = a * 2.0;
  EXPECT_GT(test::heap_allocations() - probe, 0);
  EXPECT_EQ(fresh.size(), a.size());
}

TEST(NoAllocation, KinematicsJacobianAndGradient) {
  for (const test::TestRig& r : test::rigs_like("beast")) {
    SCOPED_TRACE(r.label());
    expect_no_allocation(r.rig);
  }
}

}  // namespace
}  // namespace ik

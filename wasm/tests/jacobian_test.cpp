#include <gtest/gtest.h>

#include "a7_fixtures.h"
#include "finite_difference_jacobian.h"
#include "objective.h"

namespace ik {
namespace {

// Central differences of forward kinematics without clamping, step h degrees.
Eigen::MatrixXd central_differences(Kinematics& kin, const Eigen::VectorXd& a, double h) {
  Eigen::VectorXd scratch(kin.num_angles()), plus(kin.num_residuals()), minus(kin.num_residuals());
  Eigen::MatrixXd jac(kin.num_residuals(), kin.num_angles());
  finite_difference_jacobian(kin, a, h, /*clamp_to_limits=*/false, scratch, plus, minus, jac);
  return jac;
}

void expect_jacobian_matches(Kinematics& kin, const Eigen::VectorXd& a, const std::string& what) {
  Eigen::VectorXd tips(kin.num_residuals());
  Eigen::MatrixXd jac(kin.num_residuals(), kin.num_angles());
  kin.jacobian(a, tips, jac);
  const Eigen::MatrixXd fd = central_differences(kin, a, 1e-3);
  const double scale = std::max(fd.cwiseAbs().maxCoeff(), 1e-300);
  EXPECT_LE((jac - fd).cwiseAbs().maxCoeff() / scale, 1e-6) << what;
}

TEST(Jacobian, MatchesCentralDifferencesAtRandomPoses) {
  std::mt19937_64 rng(3);
  for (const test::TestRig& r : test::test_rigs()) {
    const std::string name = r.label();
    Kinematics kin(r.rig);
    for (int s = 0; s < 50; ++s) expect_jacobian_matches(kin, test::random_angles(kin, rng), name + " random");
  }
}

TEST(Jacobian, MatchesCentralDifferencesOnTheLimits) {
  std::mt19937_64 rng(4);
  std::bernoulli_distribution coin(0.5);
  for (const test::TestRig& r : test::test_rigs()) {
    const std::string name = r.label();
    Kinematics kin(r.rig);
    for (int s = 0; s < 20; ++s) {
      Eigen::VectorXd a(kin.num_angles());
      for (int i = 0; i < a.size(); ++i) {
        const double lo = std::max(kin.lower()[i], -720.0), hi = std::min(kin.upper()[i], 720.0);
        a[i] = coin(rng) ? lo : hi;
      }
      expect_jacobian_matches(kin, a, name + " on limits");
    }
  }
}

TEST(Jacobian, MatchesCentralDifferencesAtTheXzxSingularity) {
  // Middle angle 0: the two x rotations share an axis (gimbal lock).
  std::mt19937_64 rng(5);
  for (const test::TestRig& r : test::test_rigs()) {
    const std::string name = r.label();
    Kinematics kin(r.rig);
    for (int s = 0; s < 20; ++s) {
      Eigen::VectorXd a = test::random_angles(kin, rng);
      for (int b = 0; b < kin.num_bones(); ++b) a[3 * b + 1] = 0;
      expect_jacobian_matches(kin, a, name + " middle angle 0");
      // The two x columns coincide there.
      Eigen::VectorXd tips(kin.num_residuals());
      Eigen::MatrixXd jac(kin.num_residuals(), kin.num_angles());
      kin.jacobian(a, tips, jac);
      for (int b = 0; b < kin.num_bones(); ++b)
        EXPECT_LE((jac.col(3 * b) - jac.col(3 * b + 2)).norm(), 1e-12 * (1 + jac.norm())) << name << " bone " << b;
    }
  }
}

// The paper's difference: clamped at the limits, so a bone on its bound gets a one-sided
// difference that still approximates the analytic derivative.
void expect_clamped_differences_inside_the_limits(const Rig& rig) {
  Kinematics kin(rig);
  Eigen::VectorXd a = kin.upper().cwiseMin(720.0);
  kin.project(a);
  Eigen::VectorXd scratch(kin.num_angles()), plus(kin.num_residuals()), minus(kin.num_residuals());
  Eigen::MatrixXd fd(kin.num_residuals(), kin.num_angles()), jac(kin.num_residuals(), kin.num_angles());
  finite_difference_jacobian(kin, a, 1e-7, /*clamp_to_limits=*/true, scratch, plus, minus, fd);
  Eigen::VectorXd tips(kin.num_residuals());
  kin.jacobian(a, tips, jac);
  for (int j = 0; j < kin.num_angles(); ++j) {
    if (kin.lower()[j] == kin.upper()[j]) {
      EXPECT_EQ(fd.col(j).norm(), 0.0) << "fixed angle " << j << " cannot move";
    } else {
      EXPECT_LE((fd.col(j) - jac.col(j)).cwiseAbs().maxCoeff(), 1e-6 * jac.cwiseAbs().maxCoeff()) << "angle " << j;
    }
  }
}

TEST(Jacobian, ClampedDifferencesStayInsideTheLimits) {
  for (const test::TestRig& r : test::rigs_like("ikea-lamp")) {
    SCOPED_TRACE(r.label());
    expect_clamped_differences_inside_the_limits(r.rig);
  }
}

TEST(Objective, GradientIsJacobianTransposeResidualAndMatchesDifferences) {
  std::mt19937_64 rng(6);
  for (const test::TestRig& rig : test::test_rigs()) {
    const std::string name = rig.label();
    Kinematics kin(rig.rig);
    const Eigen::VectorXd target_angles = test::random_angles(kin, rng);
    Eigen::VectorXd target(kin.num_residuals());
    kin.tips(target_angles, target);
    const Eigen::VectorXd a = test::random_angles(kin, rng);
    Eigen::VectorXd r(kin.num_residuals()), g(kin.num_angles());
    Eigen::MatrixXd jac(kin.num_residuals(), kin.num_angles());
    const double e = objective_and_gradient(kin, a, target, r, jac, g);
    EXPECT_NEAR(e, objective(kin, a, target, r), 1e-15 * (1 + e));
    for (int j = 0; j < kin.num_angles(); ++j) {
      Eigen::VectorXd ap = a, am = a;
      ap[j] += 1e-4;
      am[j] -= 1e-4;
      const double fd = (objective(kin, ap, target, r) - objective(kin, am, target, r)) / 2e-4;
      EXPECT_NEAR(g[j], fd, 1e-6 * (1 + g.cwiseAbs().maxCoeff())) << name << " angle " << j;
    }
    EXPECT_DOUBLE_EQ(objective(kin, target_angles, target, r), 0.0);
  }
}

}  // namespace
}  // namespace ik

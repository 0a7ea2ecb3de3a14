// The analytic tip Hessian against central differences of the analytic Jacobian.
#include <gtest/gtest.h>

#include "../a7_fixtures.h"
#include "solvers/tip_hessian.h"

namespace ik {
namespace {

// Column j of every tip Hessian by central differences of the analytic Jacobian (step h degrees).
Eigen::MatrixXd jacobian_difference(Kinematics& kin, const Eigen::VectorXd& a, int j, double h) {
  Eigen::VectorXd tips(kin.num_residuals()), ap = a, am = a;
  Eigen::MatrixXd plus(kin.num_residuals(), kin.num_angles()), minus(kin.num_residuals(), kin.num_angles());
  ap[j] += h;
  am[j] -= h;
  kin.jacobian(ap, tips, plus);
  kin.jacobian(am, tips, minus);
  return (plus - minus) / (2 * h);  // row 3e+c, column k: d2 tip_{e,c} / dA_j dA_k
}

TEST(TipHessian, MatchesDifferencesOfTheAnalyticJacobian) {
  std::mt19937_64 rng(21);
  for (const test::TestRig& r : test::test_rigs()) {
    const std::string name = r.label();
    Kinematics kin(r.rig);
    const int n = kin.num_angles();
    for (int sample = 0; sample < 4; ++sample) {
      const Eigen::VectorXd a = test::random_angles(kin, rng);
      kin.forward(a);
      std::vector<Eigen::MatrixXd> h(kin.num_residuals(), Eigen::MatrixXd(n, n));
      for (int e = 0; e < kin.num_effectors(); ++e) tip_hessian(kin, e, h[3 * e], h[3 * e + 1], h[3 * e + 2]);
      double scale = 0;
      for (const auto& m : h) scale = std::max(scale, m.cwiseAbs().maxCoeff());
      ASSERT_GT(scale, 0) << name;
      for (int j = 0; j < n; ++j) {
        const Eigen::MatrixXd fd = jacobian_difference(kin, a, j, 1e-3);
        for (int i = 0; i < kin.num_residuals(); ++i)
          EXPECT_LE((h[i].row(j) - fd.row(i)).cwiseAbs().maxCoeff(), 1e-7 * scale)
              << name << " tip coordinate " << i << " angle " << j;
      }
      // Symmetric, and the weighted sum is sum_i w_i H_i.
      Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(kin.num_residuals(), -1.0, 2.0);
      Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(n, n);
      for (int i = 0; i < kin.num_residuals(); ++i) {
        EXPECT_EQ((h[i] - h[i].transpose()).cwiseAbs().maxCoeff(), 0.0) << name;
        expected += w[i] * h[i];
      }
      kin.forward(a);
      const Eigen::MatrixXd base = Eigen::MatrixXd::Constant(n, n, scale);  // the function adds to it
      Eigen::MatrixXd weighted = base;
      add_weighted_tip_hessian(kin, w, weighted);
      EXPECT_LE((weighted - base - expected).cwiseAbs().maxCoeff(), 1e-12 * scale) << name;
    }
  }
}

void expect_no_curvature_off_the_chain(const Rig& rig) {
  Kinematics kin(rig);
  std::mt19937_64 rng(22);
  kin.forward(test::random_angles(kin, rng));
  const int n = kin.num_angles();
  Eigen::MatrixXd hx(n, n), hy(n, n), hz(n, n);
  tip_hessian(kin, 0, hx, hy, hz);
  std::vector<bool> on_chain(kin.num_bones(), false);
  for (int b : kin.effector_chain(0)) on_chain[b] = true;
  for (int j = 0; j < n; ++j)
    if (!on_chain[j / 3]) {
      EXPECT_EQ(hx.row(j).norm() + hy.row(j).norm() + hz.row(j).norm(), 0.0) << "angle " << j;
    }
}

TEST(TipHessian, AnglesOffTheChainHaveNoCurvature) {
  for (const test::TestRig& r : test::rigs_like("knight")) {
    SCOPED_TRACE(r.label());
    expect_no_curvature_off_the_chain(r.rig);
  }
}

}  // namespace
}  // namespace ik

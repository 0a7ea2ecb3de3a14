// Bend hints and rest rows (goals.h, pole_residual.h, rest_residual.h): their analytic Jacobian
// against central differences on every rig (including a straight limb and poles beyond reach), the
// residual's zeros, the reach row, and GoalSet::set()'s refusals naming the pole or bone.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "a7_fixtures.h"
#include "goal_jacobian_check.h"
#include "goal_residual.h"
#include "pole_residual.h"
#include "small_rigs.h"

namespace ik {
namespace {

// Position goals at the tips of `a`, a pole on every effector bone that has a parent (at its
// elbow moved by `offset` rig units in a random direction), random stiffness.
Goals soft_goals(Kinematics& kin, const Eigen::VectorXd& a, std::mt19937_64& rng, double offset) {
  kin.forward(a);
  std::uniform_real_distribution<double> u(-1, 1);
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  for (int e = 0; e < kin.num_effectors(); ++e) {
    const int bone = kin.rig().effectors[e];
    goals.effectors[e].position_target = kin.tip(bone) + 0.1 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    if (kin.rig().bones[bone].parent < 0) continue;
    PoleGoal pole;
    pole.bone = bone;
    pole.point = kin.joint_origin(bone) + offset * Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    pole.weight = 0.5 + 0.5 * (u(rng) + 1);
    goals.poles.push_back(pole);
  }
  for (int b = 0; b < kin.num_bones(); ++b) goals.stiffness.push_back(b % 4 == 0 ? 0.0 : 1 + 0.5 * (u(rng) + 1));
  return goals;
}

TEST(PoleResidual, JacobianMatchesCentralDifferencesOnEveryRig) {
  double worst = 0;
  std::vector<test::TestRig> rigs = test::test_rigs();
  rigs.push_back({"two bones", false, test::two_bones()});
  rigs.push_back({"chain of 4", false, test::straight_chain(4, {3})});
  for (const test::TestRig& r : rigs) {
    SCOPED_TRACE(r.label());
    Kinematics kin(r.rig);
    std::mt19937_64 rng(21);
    for (int sample = 0; sample < 4; ++sample) {
      // Sample 0: the rest pose, where every limb of the small rigs is straight.
      const Eigen::VectorXd a =
          sample == 0 ? Eigen::VectorXd::Zero(kin.num_angles()).eval() : test::random_angles(kin, rng);
      GoalSet goals;
      // Sample 3: poles near the elbows; sample 2: beyond every limb's length (the reach rows on).
      const double offset = sample == 3 ? 0.01 : sample == 2 ? 3 * rig_reach(kin) : 1.0;
      ASSERT_EQ(goals.set(kin, soft_goals(kin, a, rng, offset)), "");
      goals.set_rest(kin, 0.3, sample % 2 == 1, test::random_angles(kin, rng));
      ASSERT_GT(goals.num_rest(), 0);
      const double error = test::goal_jacobian_error(kin, goals, a, 1e-4);
      worst = std::max(worst, error);
      EXPECT_LT(error, 1e-6) << "sample " << sample;
    }
  }
  std::printf("worst relative error of the pole and rest Jacobian: %.3g\n", worst);
}

TEST(PoleResidual, StraightLimbHasAFiniteResidualThatBendsTowardsThePole) {
  Kinematics kin(test::two_bones());
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(kin.num_angles());  // straight along +x
  Goals goals;
  goals.effectors.resize(1);
  goals.effectors[0].position_target = Eigen::Vector3d(2, 0, 0);
  goals.poles.push_back({1, Eigen::Vector3d(1, 3, 0), 1});  // above the elbow, in +y
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  Eigen::VectorXd r(set.rows());
  Eigen::MatrixXd J(set.rows(), kin.num_angles());
  goal_objective(kin, set, a, r);
  goal_jacobian(kin, set, J);
  ASSERT_TRUE(r.allFinite());
  ASSERT_TRUE(J.allFinite());
  // Across the limb (+x): |q_hat| = 1, times w L; along it, the reach row (the pole is 3 from the
  // elbow, beyond the limb's length 2).
  EXPECT_NEAR(r.segment<2>(4).norm(), rig_reach(kin), 1e-12);
  EXPECT_GT(r[3], 0);
  // A small step down the gradient bends the limb: the elbow (the head of bone 1) leaves the
  // shoulder-wrist axis on the pole's side (+y).
  const Eigen::VectorXd g = J.transpose() * r;
  ASSERT_GT(g.norm(), 0);
  const Eigen::VectorXd b = a - 1e-3 * g;
  kin.forward(b);
  const Eigen::Vector3d u = (kin.tip(1) - kin.joint_origin(0)).normalized(),
                        d = kin.joint_origin(1) - kin.joint_origin(0);
  EXPECT_GT((d - d.dot(u) * u).y(), 1e-6);
  EXPECT_LT(test::goal_jacobian_error(kin, set, a, 1e-4), 1e-6);
}

// The swivel rows (across the shoulder-wrist axis u; the reach row lies along it) vanish however
// far the limb bends towards the pole, and are 2 s for the mirrored bend.
TEST(PoleResidual, SwivelRowsAreZeroWhenTheLimbBendsTowardsThePoleHoweverFar) {
  const Eigen::Vector3d S(0, 0, 0), T(1.5, 0, 0), P(0.2, 5, 1e-9);
  const Eigen::Vector3d u = (T - S).normalized();
  const auto across = [&u](const Eigen::Vector3d& r) { return (r - r.dot(u) * u).norm(); };
  for (double bend : {0.1, 0.4, 0.9}) {
    const Eigen::Vector3d M(0.7, bend, 0);
    EXPECT_LT(across(pole_residual(S, M, T, P, 0.05, 3)), 1e-8) << bend;
    EXPECT_NEAR(across(pole_residual(S, Eigen::Vector3d(0.7, -bend, 0), T, P, 0.05, 3)), 6, 1e-6) << bend;
  }
  // Within one limb length of the elbow, nothing at all.
  EXPECT_LT(pole_residual(S, Eigen::Vector3d(0.7, 0.4, 0), T, Eigen::Vector3d(0.7, 1.5, 0), 0.05, 3).norm(), 1e-12);
  // Folded onto itself (T = S): no axis, no row.
  EXPECT_EQ(pole_residual(S, Eigen::Vector3d(1, 0, 0), S, P, 0.05, 3), Eigen::Vector3d::Zero());
}

// Central differences of pole_residual() in S, M and T (step h rig units) against pole_partials();
// returns the largest error relative to the largest entry.
double partials_error(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                      const Eigen::Vector3d& P, double delta, double s, double h = 1e-6) {
  PolePartials d;
  pole_partials(S, M, T, P, delta, s, d);
  const Eigen::Matrix3d* analytic[3] = {&d.shoulder, &d.elbow, &d.wrist};
  double worst = 0, scale = 1e-12;
  for (int point = 0; point < 3; ++point)
    for (int c = 0; c < 3; ++c) {
      Eigen::Vector3d x[3] = {S, M, T}, y[3] = {S, M, T};
      x[point][c] += h;
      y[point][c] -= h;
      const Eigen::Vector3d numeric =
          (pole_residual(x[0], x[1], x[2], P, delta, s) - pole_residual(y[0], y[1], y[2], P, delta, s)) / (2 * h);
      worst = std::max(worst, (analytic[point]->col(c) - numeric).cwiseAbs().maxCoeff());
      scale = std::max(scale, numeric.cwiseAbs().maxCoeff());
    }
  return worst / scale;
}

// The reach row (pole_residual.h): nothing while the elbow lies within one limb length of the
// pole, whichever side it bends to; beyond, a row along the shoulder-wrist axis growing with the
// distance, at most s kappa; its partials match central differences.
TEST(PoleResidual, ReachRowPullsTheElbowOnlyFromBeyondOneLimbLength) {
  const Eigen::Vector3d S(0, 0, 0), M(0.7, 0.2, 0), T(1.5, 0, 0);
  const double limb = M.norm() + (T - M).norm(), s = 3;
  const Eigen::Vector3d u = (T - S).normalized();
  // Bent towards the pole, the pole one limb length (or less) from the elbow: r = 0.
  for (double share : {0.2, 0.99})
    EXPECT_LT(pole_residual(S, M, T, M + share * limb * Eigen::Vector3d::UnitY(), 0.05, s).norm(), 1e-12) << share;
  // Further along the bend: the swivel rows stay 0, the reach row grows (less than s kappa = 0.03).
  double last = 0;
  for (double share : {1.1, 2.0, 10.0}) {
    const Eigen::Vector3d r = pole_residual(S, M, T, M + share * limb * Eigen::Vector3d::UnitY(), 0.05, s);
    EXPECT_LT((r - r.dot(u) * u).norm(), 1e-12) << share;
    EXPECT_GT(r.dot(u), last) << share;
    EXPECT_LT(r.dot(u), 0.03) << share;
    last = r.dot(u);
  }
  // A pole beyond reach and off the bend, and one on the other side: partials against differences.
  for (const Eigen::Vector3d& P : {Eigen::Vector3d(2, 1.5, 1), Eigen::Vector3d(0.3, -2, 0.5)}) {
    ASSERT_GT((P - M).norm(), limb);
    EXPECT_LT(partials_error(S, M, T, P, 0.05, s), 1e-6) << P.transpose();
  }
}

TEST(PoleGoals, SetRefusesBadPolesNamingTheirIndexAndField) {
  Kinematics kin(test::two_bones());
  Goals goals;
  goals.effectors.resize(1);
  GoalSet set;
  const auto refusal = [&](PoleGoal pole) {
    goals.poles = {PoleGoal{1, Eigen::Vector3d(0, 1, 0), 1}, pole};
    return set.set(kin, goals);
  };
  EXPECT_EQ(refusal({1, Eigen::Vector3d(0, 1, 0), 1}), "");
  EXPECT_NE(refusal({0, Eigen::Vector3d(0, 1, 0), 1}).find("the bone of pole 1"), std::string::npos);  // no parent
  EXPECT_NE(refusal({2, Eigen::Vector3d(0, 1, 0), 1}).find("the bone of pole 1"), std::string::npos);
  EXPECT_NE(refusal({-1, Eigen::Vector3d(0, 1, 0), 1}).find("the bone of pole 1"), std::string::npos);
  EXPECT_NE(refusal({1, Eigen::Vector3d(0, NAN, 0), 1}).find("the point of pole 1"), std::string::npos);
  EXPECT_NE(refusal({1, Eigen::Vector3d(0, 1, 0), -1}).find("the weight of pole 1"), std::string::npos);
  EXPECT_NE(refusal({1, Eigen::Vector3d(0, 1, 0), INFINITY}).find("the weight of pole 1"), std::string::npos);
  // Weight 0: no pole, no rows.
  ASSERT_EQ(refusal({1, Eigen::Vector3d(0, 1, 0), 0}), "");
  EXPECT_EQ(set.num_poles(), 1);
}

TEST(PoleGoals, SetRefusesBadStiffnessNamingTheBone) {
  Kinematics kin(test::two_bones());
  Goals goals;
  goals.effectors.resize(1);
  GoalSet set;
  goals.stiffness = {1};
  EXPECT_NE(set.set(kin, goals).find("stiffness values, expected 2"), std::string::npos);
  goals.stiffness = {1, -2};
  EXPECT_NE(set.set(kin, goals).find("the stiffness of bone 1"), std::string::npos);
  goals.stiffness = {NAN, 1};
  EXPECT_NE(set.set(kin, goals).find("the stiffness of bone 0"), std::string::npos);
  goals.stiffness = {0, 3};
  ASSERT_EQ(set.set(kin, goals), "");
  EXPECT_TRUE(set.plain());  // stiffness alone adds no row
  set.set_rest(kin, 0.5, false, Eigen::VectorXd::Zero(kin.num_angles()));
  EXPECT_FALSE(set.plain());
  ASSERT_EQ(set.num_rest(), 1);  // bone 0 has stiffness 0
  EXPECT_EQ(set.rest_bone(0), 1);
  EXPECT_DOUBLE_EQ(set.rest_scale(0), 0.5 * 3 * rig_reach(kin));
}

}  // namespace
}  // namespace ik

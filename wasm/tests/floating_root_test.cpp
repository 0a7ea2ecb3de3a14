// A floating root (rig.h FloatingRoot): three more unknowns, the whole rig's translation in rig
// units within bounds. Off, nothing changes (the angles, the limits, the Jacobian). On, forward
// kinematics moves every tip by it, the analytic Jacobian (positions, orientations, poles, rest
// rows) matches central differences, and every registered method reaches a target beyond the
// chain's reach by moving the root, never past its bounds; root_unit weighs the root's move
// against the joints' in lm's step; a bad bound is refused by name.
#include <gtest/gtest.h>

#include <random>

#include "goal_jacobian_check.h"
#include "goal_residual.h"
#include "kinematics.h"
#include "small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// A pose of `kin` with random angles within +-40 degrees and, when it floats, translation t.
Eigen::VectorXd pose(const Kinematics& kin, std::mt19937_64& rng, const Eigen::Vector3d& t) {
  std::uniform_real_distribution<double> u(-40, 40);
  Eigen::VectorXd a(kin.num_angles());
  for (int j = 0; j < 3 * kin.num_bones(); ++j) a[j] = u(rng);
  if (kin.floats()) a.tail<3>() = t;
  return a;
}

TEST(FloatingRoot, OffChangesNothing) {
  Kinematics fixed(test::two_arms(false)), plain(test::two_arms(false));
  EXPECT_EQ(fixed.num_angles(), 15);
  EXPECT_EQ(fixed.root_translation(), -1);
  EXPECT_EQ(fixed.lower().size(), 15);
  std::mt19937_64 rng(3);
  const Eigen::VectorXd a = pose(fixed, rng, Eigen::Vector3d::Zero());
  Eigen::VectorXd tips(6);
  Eigen::MatrixXd J(6, 15);
  fixed.jacobian(a, tips, J);
  EXPECT_EQ(J.cols(), 15);
  EXPECT_TRUE(J.allFinite());
}

TEST(FloatingRoot, MovesEveryTipByItsTranslation) {
  Kinematics fixed(test::two_arms(false)), floating(test::two_arms(true));
  ASSERT_EQ(floating.num_angles(), 18);
  ASSERT_EQ(floating.root_translation(), 15);
  EXPECT_TRUE((floating.lower().tail<3>() == Eigen::Vector3d(-2, -1, -2)));
  EXPECT_TRUE((floating.upper().tail<3>() == Eigen::Vector3d(2, 0.5, 2)));
  std::mt19937_64 rng(5);
  const Eigen::Vector3d t(0.7, -0.3, 1.1);
  const Eigen::VectorXd a = pose(floating, rng, t);
  Eigen::VectorXd moved(6), still(6);
  floating.tips(a, moved);
  fixed.tips(a.head(15), still);
  for (int k = 0; k < 2; ++k) EXPECT_LT((moved.segment<3>(3 * k) - still.segment<3>(3 * k) - t).norm(), 1e-12);
  for (int b = 0; b < floating.num_bones(); ++b)
    EXPECT_LT((floating.tip_rotation(b) - fixed.tip_rotation(b)).norm(), 1e-15) << "a translation turns nothing";
}

TEST(FloatingRoot, JacobianMatchesCentralDifferencesForEveryKindOfRow) {
  Kinematics kin(test::two_arms(true));
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd a = pose(kin, rng, Eigen::Vector3d(0.3 * trial, -0.2, 0.1));
    kin.forward(a);
    Goals goals;
    goals.effectors.resize(2);
    goals.effectors[0].position_target = kin.tip(2) + Eigen::Vector3d(0.2, -0.1, 0.3);
    goals.effectors[0].orientation = true;
    goals.effectors[0].orientation_target =
        kin.tip_rotation(2) * Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    goals.effectors[1].position_target = kin.tip(4) + Eigen::Vector3d(-0.3, 0.2, 0);
    PoleGoal pole;
    pole.bone = 4;
    pole.point = kin.joint_origin(4) + Eigen::Vector3d(0.3, 0.8, -0.5);
    goals.poles.push_back(pole);
    GoalSet set;
    ASSERT_EQ(set.set(kin, goals), "");
    set.set_rest(kin, 0.5, true, a);
    // Plain targets (Kinematics' own Jacobian) as well as goals with every kind of row.
    Eigen::VectorXd tips(6), target(6);
    Eigen::MatrixXd J(6, kin.num_angles());
    kin.jacobian(a, tips, J);
    EXPECT_TRUE((J.block<3, 3>(0, 15) == Eigen::Matrix3d::Identity()));
    EXPECT_TRUE((J.block<3, 3>(3, 15) == Eigen::Matrix3d::Identity()));
    EXPECT_LT(test::goal_jacobian_error(kin, set, a, 1e-5), 1e-6) << "trial " << trial;
  }
}

TEST(FloatingRoot, EveryMethodReachesPastTheChainByMovingTheRootWithinItsBounds) {
  for (const std::string& method : solver_names()) {
    Kinematics kin(test::two_arms(true));
    const Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());
    Eigen::VectorXd tips(6);
    kin.tips(start, tips);
    // Both hands 1.5 units along +z: out of the arms' reach from a fixed trunk, within the root's.
    Eigen::VectorXd target = tips;
    target[2] += 1.5;
    target[5] += 1.5;
    SolverOptions options;
    options.tip_tolerance = 1e-4;
    options.time_budget_s = 2;
    auto solver = make_solver(method, kin, options);
    const SolverSummary& s = solver->solve(start, target);
    EXPECT_TRUE(s.reached) << method << ": " << stop_reason_name(s.stop_reason) << ", tip " << s.tip_distance;
    kin.tips(s.angles, tips);
    EXPECT_LT((tips - target).cwiseAbs().maxCoeff(), 1e-4) << method;
    // Now below the root's lower y bound by 2: the root stops at -1.
    target = tips;
    target[1] -= 2;
    target[4] -= 2;
    const SolverSummary& low = solver->solve(s.angles, target);
    EXPECT_GE(low.angles[16], -1) << method;
    EXPECT_FALSE(low.reached) << method;
  }
}

// root_unit weighs the root's move in lm's least-change step: both hands moved a little along +z
// (within the arms' reach) are met with the root doing the move at the default (1 rig unit per
// degree: nearly free) and mostly the joints at 0.01, both on target. Without a
// floating root the option changes nothing, bit for bit.
TEST(FloatingRoot, RootUnitWeighsTheRootsMoveAgainstTheJoints) {
  Kinematics kin(test::two_arms(true));
  std::mt19937_64 rng(7);
  const Eigen::VectorXd start = pose(kin, rng, Eigen::Vector3d::Zero());
  Eigen::VectorXd tips(6);
  kin.tips(start, tips);
  Eigen::VectorXd target = tips;
  target[2] += 0.05;
  target[5] += 0.05;
  const auto root_move = [&](double unit, double& joints_moved) {
    SolverOptions options;
    options.tip_tolerance = 1e-6;
    options.restarts = 0;
    options.root_unit = unit;
    options.lm_initial_mu = 1e-3;  // near Gauss-Newton steps: the least change, as a tracked frame takes
    auto solver = make_solver("lm", kin, options);
    const SolverSummary& s = solver->solve(start, target);
    EXPECT_TRUE(s.reached) << "root_unit " << unit;
    joints_moved = (s.angles - start).head(15).cwiseAbs().maxCoeff();
    return (s.angles - start).tail<3>().norm();
  };
  double joints_free = 0, joints_held = 0;
  const double free_move = root_move(1.0, joints_free), held_move = root_move(0.01, joints_held);
  EXPECT_GT(free_move, 0.049);            // the hands' 0.05 (measured: all of it, the joints 0.001 degrees)
  EXPECT_LT(held_move, 0.5 * free_move);  // measured 0.012, the joints up to 1.2 degrees
  EXPECT_GT(joints_held, 100 * joints_free);

  Kinematics fixed(test::two_arms(false));
  const Eigen::VectorXd a = start.head(15);
  Eigen::VectorXd fixed_target(6);
  fixed.tips(a, fixed_target);
  fixed_target[2] += 0.05;
  SolverOptions plain, weighted;
  weighted.root_unit = 0.01;
  auto first = make_solver("lm", fixed, plain);
  auto second = make_solver("lm", fixed, weighted);
  const Eigen::VectorXd x = first->solve(a, fixed_target).angles;
  EXPECT_EQ(second->solve(a, fixed_target).angles, x);
}

TEST(FloatingRoot, RefusesBadBoundsByName) {
  Rig rig = test::two_arms(true);
  rig.floating_root.min.y() = 1;  // above its max, 0.5
  EXPECT_THROW(
      {
        try {
          Kinematics kin(rig);
        } catch (const RigError& e) {
          EXPECT_STREQ(e.what(), "floating root's y bounds have min > max");
          throw;
        }
      },
      RigError);
  rig = test::two_arms(true);
  rig.floating_root.max.z() = kUnbounded;
  EXPECT_THROW(Kinematics kin(rig), RigError);
  rig.floating_root.on = false;  // off: its bounds are not read
  EXPECT_NO_THROW(Kinematics kin(rig));
}

}  // namespace
}  // namespace ik

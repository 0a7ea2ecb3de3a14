// A preferred move (Solver::set_preferred_move) in lm's first step: the pose moves along it where
// the goals leave room and the goals stay met; a move the goals forbid is taken back out; a move
// against a limit stops there; a floating root's translation moves the body under fixed hands;
// the move serves one solve only; and a move of the wrong size or with a NaN is refused, the
// solve then the same as one without.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "../small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// Tight tolerances, no restarts, at least one iteration: a tracked frame's solve.
SolverOptions frame_options() {
  SolverOptions o;
  o.time_budget_s = 0;
  o.tip_tolerance = 1e-6;
  o.gradient_tolerance = 1e-14;
  o.restarts = 0;
  o.min_iterations = 1;
  o.lm_initial_mu = 1e-3;
  return o;
}

// A straight chain of 3 bones along +x bent to `bend` (each bone's a1, degrees): the tip's goal is
// where that pose puts it, moved 1e-3 rig units (a tracked frame's small move: a solve that starts
// on its goals to round-off takes no step at all); the chain has one angle to spare in the plane
// (and the twists about the bones).
struct BentChain {
  Rig rig = test::straight_chain(3, {2});
  Kinematics kin{rig};
  Eigen::VectorXd start = Eigen::VectorXd::Zero(9);
  Eigen::VectorXd target = Eigen::VectorXd::Zero(3);
  explicit BentChain(double bend) {
    for (int b = 0; b < 3; ++b) start[3 * b + 1] = bend;
    kin.tips(start, target);
    target[1] += 1e-3;
  }
};

TEST(PreferredMove, TurnsARedundantChainWhereTheGoalLeavesRoomAndKeepsTheTipOnTarget) {
  BentChain c(20);
  const auto lm = make_solver("lm", c.kin, frame_options());
  Eigen::VectorXd move = Eigen::VectorXd::Zero(9);
  move[1] = 2;  // the first bone's bend: 2 degrees more
  ASSERT_TRUE(lm->set_preferred_move(move));
  const SolverSummary& s = lm->solve(c.start, c.target);
  ASSERT_TRUE(s.reached);
  Eigen::VectorXd tip(3);
  c.kin.tips(s.angles, tip);
  EXPECT_LT((tip - c.target).norm(), 1e-6);
  // The first bone turned its way by the part of the move that the tip's goal leaves free (the
  // least change that holds the tip turns every bone, the first one back too): measured 0.18
  // degrees against the plain solve's 0.065.
  const auto plain = make_solver("lm", c.kin, frame_options());
  const Eigen::VectorXd plain_angles = plain->solve(c.start, c.target).angles;
  const double plain_turn = plain_angles[1] - 20;
  EXPECT_GT(s.angles[1] - 20, plain_turn + 0.05);
  EXPECT_LT(s.angles[1] - 20, 2.0);
  EXPECT_GT((s.angles - plain_angles).norm(), 0.1);
  std::printf("[preferred move] first bone turned %.3f degrees with a move of 2, %.3f without\n", s.angles[1] - 20,
              plain_turn);
}

TEST(PreferredMove, AMoveTheGoalForbidsIsTakenBackOut) {
  // One bone: its tip's goal holds both swings; only the twist about the bone (a0 + a2) is free.
  Rig rig = test::straight_chain(1, {0});
  Kinematics kin(rig);
  Eigen::VectorXd start = Eigen::VectorXd::Zero(3), target(3);
  kin.tips(Eigen::Vector3d(0, 10.5, 0), target);  // a tracked frame's small move, within reach
  start[1] = 10;
  const auto lm = make_solver("lm", kin, frame_options());
  ASSERT_TRUE(lm->set_preferred_move(Eigen::Vector3d(0, 5, 0)));  // a swing: it would move the tip
  const SolverSummary& s = lm->solve(start, target);
  ASSERT_TRUE(s.reached);
  EXPECT_NEAR(s.angles[1], 10.5, 1e-3);
}

TEST(PreferredMove, StopsAtALimit) {
  BentChain c(20);
  Eigen::VectorXd start = c.start;
  start[1] = 90;  // the first bone on its upper limit, the tip's goal near where that pose puts it
  c.kin.tips(start, c.target);
  c.target[1] += 0.01;
  const auto lm = make_solver("lm", c.kin, frame_options());
  Eigen::VectorXd move = Eigen::VectorXd::Zero(9);
  move[1] = 5;
  ASSERT_TRUE(lm->set_preferred_move(move));
  const SolverSummary& s = lm->solve(start, c.target);
  ASSERT_TRUE(s.reached);
  EXPECT_LE(s.angles[1], 90);
  EXPECT_TRUE((s.angles.array() >= c.kin.lower().array()).all() && (s.angles.array() <= c.kin.upper().array()).all());
}

TEST(PreferredMove, MovesAFloatingRootUnderHandsThatStay) {
  Rig rig = test::two_arms(/*floating=*/true);
  Kinematics kin(rig);
  Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());
  start[3 * 1 + 1] = 30;  // both arms bent, so that the hands can stay while the trunk moves
  start[3 * 2 + 1] = -40;
  start[3 * 3 + 1] = -30;
  start[3 * 4 + 1] = 40;
  Eigen::VectorXd target(6);
  kin.tips(start, target);
  target[1] += 0.01;
  SolverOptions o = frame_options();
  o.root_unit = 1e-3;  // the root's move dear: the arms, not the root, hold the hands
  const auto lm = make_solver("lm", kin, o);
  Eigen::VectorXd move = Eigen::VectorXd::Zero(kin.num_angles());
  const int root = kin.root_translation();
  move[root] = 0.02;  // 2 hundredths of a rig unit along x
  ASSERT_TRUE(lm->set_preferred_move(move));
  const SolverSummary& s = lm->solve(start, target);
  ASSERT_TRUE(s.reached);
  EXPECT_GT(s.angles[root], 0.01);
  Eigen::VectorXd tips(6);
  kin.tips(s.angles, tips);
  EXPECT_LT((tips - target).norm(), 1e-5);
}

TEST(PreferredMove, ServesOneSolveOnly) {
  BentChain c(20);
  const auto lm = make_solver("lm", c.kin, frame_options());
  const auto plain = make_solver("lm", c.kin, frame_options());
  Eigen::VectorXd move = Eigen::VectorXd::Zero(9);
  move[1] = 2;
  ASSERT_TRUE(lm->set_preferred_move(move));
  const Eigen::VectorXd moved = lm->solve(c.start, c.target).angles;
  const Eigen::VectorXd plain_angles = plain->solve(c.start, c.target).angles;
  EXPECT_GT((moved - plain_angles).norm(), 0.1);
  // The next solve, from the same start, has none: it is the plain solve, bit for bit.
  EXPECT_EQ(lm->solve(c.start, c.target).angles, plain_angles);
}

TEST(PreferredMove, AMoveOfTheWrongSizeOrWithANaNIsRefused) {
  BentChain c(20);
  const auto lm = make_solver("lm", c.kin, frame_options());
  const auto plain = make_solver("lm", c.kin, frame_options());
  EXPECT_FALSE(lm->set_preferred_move(Eigen::VectorXd::Zero(8)));
  Eigen::VectorXd bad = Eigen::VectorXd::Zero(9);
  bad[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(lm->set_preferred_move(bad));
  // A refused move also drops one set before it.
  Eigen::VectorXd move = Eigen::VectorXd::Zero(9);
  move[1] = 2;
  ASSERT_TRUE(lm->set_preferred_move(move));
  EXPECT_FALSE(lm->set_preferred_move(bad));
  const SolverSummary& s = lm->solve(c.start, c.target);
  ASSERT_TRUE(s.reached);
  EXPECT_EQ(s.angles, plain->solve(c.start, c.target).angles);
}

}  // namespace
}  // namespace ik

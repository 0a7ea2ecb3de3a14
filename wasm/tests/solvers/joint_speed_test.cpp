// Bounded joint speed (joint_motion.h), every method: with max_joint_move > 0 a solve whose
// answer lies far from its start (another branch, for a target moved a little) returns the pose
// partway there, no joint (a bone's head or tip) moved more than the bound plus the target's
// move, and stops with joint_speed; solving again from that pose goes on and reaches the target.
// Without the option (0) the elbow snaps in one solve; paper mode ignores it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

constexpr double kTipTolerance = 1e-3;
constexpr double kBound = 0.2;  // rig units; the chain is 3 long

SolverOptions drag_options(double bound) {
  SolverOptions o;
  o.tip_tolerance = kTipTolerance;
  o.gradient_tolerance = 1e-3 * kTipTolerance * kRadPerDeg;
  o.restarts = 0;
  o.time_budget_s = 0;
  o.max_iterations = 100000;
  o.max_joint_move = bound;
  return o;
}

// Every bone's head and tip at `angles`, 3 numbers each.
std::vector<Eigen::Vector3d> joints(Kinematics& kin, const Eigen::VectorXd& angles) {
  kin.forward(angles);
  std::vector<Eigen::Vector3d> out;
  for (int b = 0; b < kin.num_bones(); ++b) {
    out.push_back(kin.joint_origin(b));
    out.push_back(kin.tip(b));
  }
  return out;
}

double largest_move(Kinematics& kin, const Eigen::VectorXd& from, const Eigen::VectorXd& to) {
  const std::vector<Eigen::Vector3d> a = joints(kin, from), b = joints(kin, to);
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (b[i] - a[i]).norm());
  return worst;
}

// A planar arm: a shoulder turning +-60 degrees and an elbow +-150 degrees about z (the other
// angles locked), bones of length 1 along +x. A target 1.2 from the shoulder at polar angle phi
// is met with the elbow on either side of the shoulder-target line, the shoulder at phi +- 53.1
// degrees: the first branch ends where the shoulder meets its limit (phi = 6.9), and a target
// carried on by a degree then has only the other branch, the elbow 1.6 away.
Rig planar_arm() {
  Rig rig;
  const int shoulder = test::add_bone(rig, -1, {0, 0, 0}, 1, 0, "shoulder");
  const int elbow = test::add_bone(rig, shoulder, {1, 0, 0}, 1, 0, "elbow");
  rig.bones[shoulder].min_deg.y() = -60;
  rig.bones[shoulder].max_deg.y() = 60;
  rig.bones[elbow].min_deg.y() = -150;
  rig.bones[elbow].max_deg.y() = 150;
  rig.effectors = {elbow};
  return rig;
}

Eigen::Vector3d on_circle(double phi_deg) {
  return 1.2 * Eigen::Vector3d(std::cos(phi_deg * kRadPerDeg), std::sin(phi_deg * kRadPerDeg), 0);
}

class JointSpeed : public ::testing::TestWithParam<std::string> {};

// The target carried from phi = -20 to 30 degrees in steps of 1 degree (0.021 rig units), each
// solve from where the last ended, then held at 30 until the arm is on it.
TEST_P(JointSpeed, ABranchChangeTakesSeveralSolvesEachWithinTheBound) {
  Kinematics kin(planar_arm());
  Eigen::VectorXd bent = Eigen::VectorXd::Zero(kin.num_angles());
  bent[1] = 50, bent[4] = -100;  // the branch with the shoulder above the target's line
  const auto drag = [&](double bound, double& worst, int& partway) {
    auto solver = make_solver(GetParam(), kin, drag_options(bound));
    Eigen::VectorXd angles = solver->solve(bent, on_circle(-20)).angles;
    worst = 0, partway = 0;
    bool reached = false;
    for (int step = 1; step <= 50 + 30; ++step) {
      const Eigen::Vector3d target = on_circle(std::min(-20.0 + step, 30.0));
      const SolverSummary& s = solver->solve(angles, target);
      const double move = largest_move(kin, angles, s.angles);
      worst = std::max(worst, move);
      // The target moved 0.021 in a step: the bound, and that (a transition's later solves measure
      // the target's move from the answer they head to, which was within the tip tolerance of it).
      if (bound > 0) {
        EXPECT_LE(move, bound + 0.021 + kTipTolerance) << "step " << step;
      }
      EXPECT_EQ(s.reached, s.stop_reason == StopReason::converged_E);
      if (s.stop_reason == StopReason::joint_speed) {
        ++partway;
        EXPECT_FALSE(s.out_of_reach);
      }
      angles = s.angles;
      reached = s.reached;
    }
    EXPECT_TRUE(reached) << "the arm never reached the target";
  };
  double free_worst = 0, worst = 0;
  int free_partway = 0, partway = 0;
  drag(0, free_worst, free_partway);
  EXPECT_GT(free_worst, 1.0);  // without the bound the elbow snaps to the other side
  EXPECT_EQ(free_partway, 0);
  drag(kBound, worst, partway);
  EXPECT_LT(worst, kBound + 0.03);
  EXPECT_GE(partway, 2);
}

// A target out of reach that the chain's length does not rule out (behind the arm, which its
// limits cannot turn to), dragged by 2 degrees across the line where the closest point changes
// sides: the next frame's chain restart finds the other side a little nearer, 1.7 away. On a
// frame that goes on from where the last solve ended, the joints move as far as the target moved
// and the bound more; the target's residual (1.2, out of reach) is no move.
TEST(JointSpeedOutOfReach, AChainedFrameMovesNoMoreThanItsTargetMovedAndTheBound) {
  Kinematics kin(planar_arm());
  const auto behind = [](double phi_deg) {
    return Eigen::Vector3d(1.5 * std::cos(phi_deg * kRadPerDeg), 1.5 * std::sin(phi_deg * kRadPerDeg), 0);
  };
  Eigen::VectorXd lower_side = Eigen::VectorXd::Zero(kin.num_angles());
  lower_side[1] = -60, lower_side[4] = -150;  // the tip at 225 degrees, 0.52 from the shoulder
  auto solver = make_solver("lm", kin, drag_options(kBound));
  const SolverSummary& first = solver->solve(lower_side, behind(181));
  EXPECT_FALSE(first.reached);
  const Eigen::VectorXd there = first.angles;
  kin.forward(there);
  EXPECT_LT(kin.tip(1).y(), 0);  // the closest point on this side
  const SolverSummary& next = solver->solve(there, behind(179));
  const double target_move = (behind(179) - behind(181)).norm();  // 0.052
  EXPECT_FALSE(next.reached);
  EXPECT_LE(largest_move(kin, there, next.angles), kBound + target_move + 1e-9);
  EXPECT_GT(largest_move(kin, there, next.angles), 0.1);  // it does head for the other side
}

// Paper mode is the report's algorithm: no bound.
TEST(JointSpeedPaperMode, IgnoresTheBound) {
  Kinematics kin(planar_arm());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  const Eigen::Vector3d target = on_circle(-20);
  SolverOptions paper = drag_options(kBound);
  paper.paper_mode = true;
  SolverOptions plain = paper;
  plain.max_joint_move = 0;
  auto bounded = make_solver("lm", kin, paper);
  auto unbounded = make_solver("lm", kin, plain);
  const Eigen::VectorXd a = bounded->solve(rest, target).angles;
  EXPECT_EQ(a, unbounded->solve(rest, target).angles);
  EXPECT_NE(bounded->summary().stop_reason, StopReason::joint_speed);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, JointSpeed, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace ik

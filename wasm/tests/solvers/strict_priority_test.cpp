// Strict priority (priority.h), every method: a target out of reach leaves the goals that can
// be met on target, also those whose chains share bones with it; inside one effector the
// position holds when the orientation cannot.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../small_rigs.h"
#include "goal_residual.h"
#include "objective.h"
#include "so3.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// A small upper body: hips (fixed), a spine of two bones that bend up to 40 degrees, a head, and
// two arms of upper arm, forearm and hand from the chest. Effectors: the hands and the head.
// At rest the arms stretch straight out along -x and +x.
Rig upper_body() {
  Rig rig;
  auto add = [&rig](const char* name, int parent, const Eigen::Vector3d& at, double length, double limit) {
    return test::add_bone(rig, parent, at, length, limit, name);
  };
  // Bones point along their rest frame's x axis: the spine and head point up (+y), the right arm
  // +x, the left arm -x.
  auto turn = [&rig](int bone, double degrees) {
    rig.bones[bone].rest.block<3, 3>(0, 0) = Eigen::AngleAxisd(degrees * kRadPerDeg, Eigen::Vector3d::UnitZ()).matrix();
  };
  const int hips = add("hips", -1, {0, 0, 0}, 0.3, 0);
  turn(hips, 90);
  const int spine = add("spine", hips, {0, 0.3, 0}, 0.3, 40);
  turn(spine, 90);
  const int chest = add("chest", spine, {0, 0.6, 0}, 0.3, 40);
  turn(chest, 90);
  const int head = add("head", chest, {0, 0.9, 0}, 0.25, 60);
  turn(head, 90);
  int right = chest, left = chest;
  const char* right_names[] = {"upperarm.R", "forearm.R", "hand.R"};
  const char* left_names[] = {"upperarm.L", "forearm.L", "hand.L"};
  const double lengths[] = {0.3, 0.3, 0.1};
  double x = 0.15;
  for (int k = 0; k < 3; ++k) {
    right = add(right_names[k], right, {x, 0.85, 0}, lengths[k], 150);
    left = add(left_names[k], left, {-x, 0.85, 0}, lengths[k], 150);
    turn(left, 180);
    x += lengths[k];
  }
  rig.effectors = {left, right, head};
  return rig;
}

constexpr double kTipTolerance = 1e-3;

// The effectors' tips at the rest pose (all angles 0): 3 per effector, rig units.
Eigen::VectorXd rest_tips(Kinematics& kin) {
  Eigen::VectorXd tips(kin.num_residuals());
  kin.tips(Eigen::VectorXd::Zero(kin.num_angles()), tips);
  return tips;
}

// A position goal per effector at its rest tip.
Goals rest_goals(Kinematics& kin) {
  const Eigen::VectorXd tips = rest_tips(kin);
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  for (int e = 0; e < kin.num_effectors(); ++e) goals.effectors[e].position_target = tips.segment<3>(3 * e);
  return goals;
}

// The page's drag settings: the tip test, no restarts, a gradient tolerance far below the
// gradient of an effector that far off.
SolverOptions drag_options() {
  SolverOptions o;
  o.tip_tolerance = kTipTolerance;
  o.gradient_tolerance = 1e-3 * kTipTolerance * 1.0 * kRadPerDeg;
  o.restarts = 0;
  o.time_budget_s = 0;
  o.max_iterations = 100000;  // gd and bfgs crawl through their chain restarts before giving up
  return o;
}

// drag_options() without strict priority, for the least-squares point: no chain restarts (with
// the pinned effectors pulled off target, each of the 64 restarts ran on to the same point: 30,000
// iterations of lm, 20,000 of newton, 66,000 of gd) and at most 5,000 iterations (gn creeps
// towards it, 63,000 iterations to a zero step; after 5,000 its E is within 2e-5 of the others').
SolverOptions least_squares_options() {
  SolverOptions o = drag_options();
  o.strict_priority = false;
  o.chain_restarts = 0;
  o.max_iterations = 5000;
  return o;
}

class StrictPriority : public ::testing::TestWithParam<std::string> {};

// The left hand's target 1 unit further out than the arm reaches: the spine could bend towards
// it and bring the hand a little closer, at the cost of the head and the right hand.
TEST_P(StrictPriority, AnOutOfReachTargetLeavesThePinnedEffectorsOnTarget) {
  Kinematics kin(upper_body());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  Eigen::VectorXd target = rest_tips(kin);
  target.segment<3>(0) += Eigen::Vector3d(-1.0, 0.3, 0.2);  // the left hand, away from the body

  SolverOptions weighted = least_squares_options();
  auto sum = make_solver(GetParam(), kin, weighted);
  const SolverSummary least_squares = sum->solve(rest, target);
  Eigen::VectorXd r(kin.num_residuals());
  objective(kin, least_squares.angles, target, r);
  // The scene is worth testing: without priority the pinned effectors leave their targets.
  EXPECT_GT(std::max(r.segment<3>(3).norm(), r.segment<3>(6).norm()), 10 * kTipTolerance);

  auto solver = make_solver(GetParam(), kin, drag_options());
  const SolverSummary& s = solver->solve(rest, target);
  objective(kin, s.angles, target, r);
  EXPECT_LT(r.segment<3>(3).norm(), kTipTolerance)
      << "right hand " << s.iterations << " it " << s.escapes << " esc " << s.chain_restarts << " chain";
  EXPECT_LT(r.segment<3>(6).norm(), kTipTolerance) << "head";
  EXPECT_FALSE(s.reached);
  EXPECT_TRUE(s.out_of_reach);
  EXPECT_FALSE(s.orientation_out_of_reach);
  EXPECT_EQ(s.goals_given_up, 1);
  // The left hand as close as the arm alone allows: its tip on the sphere about the shoulder,
  // towards the target (the spine is held by the others).
  kin.forward(s.angles);
  const Eigen::Vector3d shoulder = kin.joint_origin(kin.rig().effectors[0] - 4);
  const Eigen::Vector3d toward = (target.segment<3>(0) - shoulder).normalized();
  EXPECT_NEAR((kin.tip(kin.rig().effectors[0]) - shoulder).dot(toward), 0.7, 1e-2) << stop_reason_name(s.stop_reason);
  EXPECT_TRUE(s.stop_reason == StopReason::converged_grad || s.stop_reason == StopReason::zero_step)
      << stop_reason_name(s.stop_reason);
  EXPECT_EQ(s.tip_distance, r.segment<3>(0).norm());
}

// A drag that goes on past reach, each solve from where the last ended, the hand's goal marked to
// yield as the page marks the dragged target: the pinned effectors stay on target at every step
// and the hand follows as far as it can. Without the mark (lm, as the bench drags) the same holds.
TEST_P(StrictPriority, ADragPastReachKeepsThePinnedEffectorsAtEveryStep) {
  for (const bool yields : {true, false}) {
    if (!yields && GetParam() != "lm") continue;  // gd and bfgs crawl for seconds towards the least-squares point first
    Kinematics kin(upper_body());
    Eigen::VectorXd angles = Eigen::VectorXd::Zero(kin.num_angles());
    Goals goals = rest_goals(kin);
    goals.effectors[0].yields = yields;
    auto solver = make_solver(GetParam(), kin, drag_options());
    int out = 0;
    for (int step = 1; step <= 40; ++step) {
      goals.effectors[0].position_target += Eigen::Vector3d(-0.02, 0.01, 0.005);
      const SolverSummary& s = solver->solve(angles, goals);
      angles = s.angles;
      kin.forward(angles);
      SCOPED_TRACE("step " + std::to_string(step) + (yields ? ", yields" : ""));
      for (int e : {1, 2})
        EXPECT_LT((kin.tip(kin.rig().effectors[e]) - goals.effectors[e].position_target).norm(), kTipTolerance)
            << "effector " << e << ": " << stop_reason_name(s.stop_reason);
      EXPECT_EQ(s.reached,
                (kin.tip(kin.rig().effectors[0]) - goals.effectors[0].position_target).norm() < kTipTolerance);
      out += s.out_of_reach;
    }
    EXPECT_GT(out, 10);  // the last steps are out of reach
  }
}

// A goal marked to yield (the dragged one) gives way from the first step: the others are held,
// and a yielding target within reach is still reached.
TEST_P(StrictPriority, AYieldingGoalGivesWayFromTheStart) {
  Kinematics kin(upper_body());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  Goals goals = rest_goals(kin);
  goals.effectors[0].yields = true;
  goals.effectors[0].position_target += Eigen::Vector3d(-1.0, 0.3, 0.2);  // out of reach
  auto solver = make_solver(GetParam(), kin, drag_options());
  const SolverSummary& s = solver->solve(rest, goals);
  kin.forward(s.angles);
  EXPECT_LT((kin.tip(kin.rig().effectors[1]) - goals.effectors[1].position_target).norm(), kTipTolerance);
  EXPECT_LT((kin.tip(kin.rig().effectors[2]) - goals.effectors[2].position_target).norm(), kTipTolerance);
  EXPECT_TRUE(s.out_of_reach);
  EXPECT_EQ(s.goals_given_up, 1);
  // Within reach: the arm bends to it, the others stay.
  goals.effectors[0].position_target = rest_tips(kin).segment<3>(0) + Eigen::Vector3d(0.15, 0.2, 0.1);
  const SolverSummary& t = solver->solve(rest, goals);
  EXPECT_TRUE(t.reached) << stop_reason_name(t.stop_reason);
  EXPECT_FALSE(t.out_of_reach);
}

// Position first, orientation second: a hand turned further than its wrist allows keeps its
// position and says that the orientation is out of reach.
TEST_P(StrictPriority, PositionHoldsWhenTheOrientationCannot) {
  Rig rig = upper_body();
  for (int k = 0; k < 3; ++k) rig.bones[rig.effectors[1]].min_deg[k] = -20, rig.bones[rig.effectors[1]].max_deg[k] = 20;
  Kinematics kin(rig);
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  Goals goals = rest_goals(kin);
  const int hand = kin.rig().effectors[1];
  goals.effectors[1].orientation = true;
  goals.effectors[1].orientation_target =
      Eigen::AngleAxisd(88 * kRadPerDeg, Eigen::Vector3d::UnitZ()).matrix() * kin.tip_rotation(hand);
  auto solver = make_solver(GetParam(), kin, drag_options());
  const SolverSummary& s = solver->solve(rest, goals);
  kin.forward(s.angles);
  for (int e = 0; e < kin.num_effectors(); ++e)
    EXPECT_LT((kin.tip(kin.rig().effectors[e]) - goals.effectors[e].position_target).norm(), kTipTolerance) << e;
  EXPECT_FALSE(s.reached);
  EXPECT_FALSE(s.out_of_reach);
  EXPECT_TRUE(s.orientation_out_of_reach) << stop_reason_name(s.stop_reason) << " " << s.iterations << " it, given up "
                                          << s.goals_given_up << ", chain restarts " << s.chain_restarts;
  // Turned as far as the held positions let it (the straight arm stretched to the target leaves
  // the wrist little room).
  const double left = so3_log(goals.effectors[1].orientation_target.transpose() * kin.tip_rotation(hand)).norm();
  EXPECT_LT(left / kRadPerDeg, 87);
}

// strict_priority = false keeps the least-squares closest point (nothing given up; the pinned
// effectors pulled off), and paper mode never gives up goals nor calls a stop a closest point.
TEST_P(StrictPriority, OffInPaperModeAndWhenAskedOff) {
  Kinematics kin(upper_body());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  Eigen::VectorXd target = rest_tips(kin);
  target.segment<3>(0) += Eigen::Vector3d(-1.0, 0.3, 0.2);
  SolverOptions o = least_squares_options();
  auto solver = make_solver(GetParam(), kin, o);
  const SolverSummary& s = solver->solve(rest, target);
  EXPECT_EQ(s.goals_given_up, 0);
  Eigen::VectorXd r(kin.num_residuals());
  objective(kin, s.angles, target, r);
  EXPECT_GT(r.segment<3>(3).norm(), kTipTolerance);

  SolverOptions paper;
  paper.paper_mode = true;
  paper.max_iterations = 200;
  auto original = make_solver(GetParam(), kin, paper);
  EXPECT_EQ(original->solve(rest, target).goals_given_up, 0);
  EXPECT_FALSE(original->summary().out_of_reach);
  EXPECT_FALSE(original->summary().orientation_out_of_reach);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, StrictPriority, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace ik

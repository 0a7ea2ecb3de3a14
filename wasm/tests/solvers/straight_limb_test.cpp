// A straight limb whose target moves along it towards its root: the rest pose of most characters
// and the first thing a user drags. grad E vanishes there (the tip can only move across the limb),
// so without restarts every method used to stop at once. With escape_saddles (the default) each
// method leaves the straight pose along negative curvature and reaches the target, with the
// pinned effectors kept on theirs; a target past the limb's length ends at the closest point.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../allocation_counter.h"
#include "../small_rigs.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

using test::translation;

// Every angle in [-180, 180] degrees, as the importers give a joint without limits.
void limit_to_half_turns(Rig& rig) {
  for (Bone& b : rig.bones) {
    b.min_deg.setConstant(-180);
    b.max_deg.setConstant(180);
  }
}

// test::two_bones with limits of +-180 degrees: a straight limb as an imported character has it.
Rig straight_limb() {
  Rig rig = test::two_bones();
  limit_to_half_turns(rig);
  return rig;
}

// A pelvis (bone 0, length 0.2 along +x) with two straight legs of two bones each hanging from
// its tip, along -y at z = +-0.1 (rest: about z, -90 degrees), effectors on both feet.
Rig two_legs() {
  Rig rig;
  rig.bones.resize(5);
  rig.bones[0].name = "pelvis";
  rig.bones[0].length = 0.2;
  Eigen::Matrix4d down = Eigen::Matrix4d::Identity();
  down.block<3, 3>(0, 0) = Eigen::AngleAxisd(-kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (int leg = 0; leg < 2; ++leg) {
    const double z = leg == 0 ? 0.1 : -0.1;
    Bone& thigh = rig.bones[1 + 2 * leg];
    thigh.name = leg == 0 ? "thigh.L" : "thigh.R";
    thigh.parent = 0;
    thigh.rest = translation(0.2, 0, z) * down;
    thigh.length = 1;
    Bone& shin = rig.bones[2 + 2 * leg];
    shin.name = leg == 0 ? "shin.L" : "shin.R";
    shin.parent = 1 + 2 * leg;
    shin.rest = translation(0.2, -1, z) * down;
    shin.length = 1;
  }
  rig.effectors = {2, 4};
  limit_to_half_turns(rig);
  return rig;
}

// As two_legs, each leg ending in a foot bone of length 0.3 pointing forward (+x) from the ankle,
// with a character's limits: the pelvis fixed, the hip swinging -30..110 degrees (positive: the
// thigh forward), the knee bending backwards only (-150..0, no twist), the ankle turning the toe
// up by at most 30 degrees and down by 50. The effectors are the toes (the feet's tips).
Rig legs_with_feet() {
  Rig rig = two_legs();
  rig.bones[0].min_deg.setZero();
  rig.bones[0].max_deg.setZero();
  for (int leg = 0; leg < 2; ++leg) {
    const double z = leg == 0 ? 0.1 : -0.1;
    Bone& thigh = rig.bones[1 + 2 * leg];
    thigh.min_deg = Eigen::Vector3d(-40, -30, -40);
    thigh.max_deg = Eigen::Vector3d(40, 110, 40);
    Bone& shin = rig.bones[2 + 2 * leg];
    shin.min_deg = Eigen::Vector3d(0, -150, 0);
    shin.max_deg = Eigen::Vector3d(0, 0, 0);
    Bone foot;
    foot.name = leg == 0 ? "foot.L" : "foot.R";
    foot.parent = 2 + 2 * leg;
    foot.rest = translation(0.2, -2, z);
    foot.length = 0.3;
    foot.min_deg = Eigen::Vector3d(-20, -50, -20);
    foot.max_deg = Eigen::Vector3d(20, 30, 20);
    rig.bones.push_back(foot);
  }
  rig.effectors = {5, 6};
  return rig;
}

Eigen::VectorXd tips_at(Kinematics& kin, const Eigen::VectorXd& angles) {
  Eigen::VectorXd tips(kin.num_residuals());
  kin.tips(angles, tips);
  return tips;
}

SolverOptions drag_options(double tip_tolerance) {
  SolverOptions o;
  o.restarts = 0;  // as while a user drags
  o.tip_tolerance = tip_tolerance;
  o.gradient_tolerance = 1e-12;
  o.time_budget_s = 0;
  return o;
}

class StraightLimb : public ::testing::TestWithParam<std::string> {};

TEST_P(StraightLimb, ATargetMovedAlongTheLimbTowardsItsRootIsReachedWithoutRestarts) {
  Kinematics kin(straight_limb());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  const double tolerance = 1e-4;
  for (double along : {0.002, 0.05, 0.4, 0.9}) {
    SCOPED_TRACE("target moved " + std::to_string(along) + " towards the root");
    const Eigen::Vector3d target(2 - along, 0, 0);
    auto solver = make_solver(GetParam(), kin, drag_options(tolerance));
    const SolverSummary& s = solver->solve(rest, target);
    EXPECT_EQ(s.stop_reason, StopReason::converged_E);
    EXPECT_TRUE(s.reached);
    EXPECT_EQ(s.restarts, 0);
    EXPECT_GE(s.escapes, 1);
    EXPECT_LT((tips_at(kin, s.angles) - target).norm(), tolerance);
    EXPECT_NEAR(s.tip_distance, (tips_at(kin, s.angles) - target).norm(), 1e-12);
    // The knee bends by 2 acos(d / 2) for a tip at distance d from the hip; no angle needs to
    // turn much further than that (the twist angles about the bone are free and stay put).
    const double bend = 2 * std::acos((2 - along) / 2) / kRadPerDeg;
    EXPECT_LT(s.angles.cwiseAbs().maxCoeff(), bend + 1) << s.angles.transpose();
  }
}

TEST_P(StraightLimb, WithoutTheEscapeTheStraightLimbDoesNotBend) {
  Kinematics kin(straight_limb());
  SolverOptions o = drag_options(1e-4);
  o.escape_saddles = false;
  o.chain_restarts = 0;
  auto solver = make_solver(GetParam(), kin, o);
  const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(kin.num_angles()), Eigen::Vector3d(1.8, 0, 0));
  EXPECT_EQ(s.stop_reason, StopReason::converged_grad);
  EXPECT_FALSE(s.reached);
  EXPECT_EQ(s.iterations, 0);
}

TEST_P(StraightLimb, ThePinnedFootStaysOnItsTargetWhileTheOtherFootIsLifted) {
  Kinematics kin(two_legs());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  Eigen::VectorXd target = tips_at(kin, rest);  // feet at (0.2, -2, +-0.1)
  const double tolerance = 1e-4;
  auto solver = make_solver(GetParam(), kin, drag_options(tolerance));
  Eigen::VectorXd pose = rest;
  for (int step = 1; step <= 20; ++step) {  // lift the left foot 0.6 straight up, in steps
    target[1] = -2 + 0.03 * step;
    const SolverSummary& s = solver->solve(pose, target);
    ASSERT_TRUE(s.reached) << "step " << step << ": " << stop_reason_name(s.stop_reason);
    pose = s.angles;
    const Eigen::VectorXd tips = tips_at(kin, pose);
    EXPECT_LT((tips.segment<3>(3) - target.segment<3>(3)).norm(), tolerance) << "the pinned foot moved";
  }
}

TEST_P(StraightLimb, ATargetPastTheLimbsLengthEndsAtTheClosestPointAndSaysSo) {
  Kinematics kin(straight_limb());
  const Eigen::Vector3d target(1.5, 2.5, 0);  // |target| = 2.92 > 2
  SolverOptions o = drag_options(1e-4);
  o.gradient_tolerance = 1e-9;
  auto solver = make_solver(GetParam(), kin, o);
  const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(kin.num_angles()), target);
  EXPECT_FALSE(s.reached);
  EXPECT_NE(s.stop_reason, StopReason::converged_E);
  // The closest reachable point is the straight limb pointing at the target.
  EXPECT_NEAR(s.tip_distance, target.norm() - 2, 1e-3);
  const Eigen::VectorXd tip = tips_at(kin, s.angles);
  EXPECT_NEAR(tip.normalized().dot(target.normalized()), 1, 1e-6);
}

// Lifting a toe straight up: the ankle turns the toe up until its limit, and from there no small
// move raises the toe (bending the knee first lowers it): a local minimum, not a saddle. A
// restart of that leg alone reaches the target; the other foot stays on its target.
TEST_P(StraightLimb, AToeLiftedPastWhatTheAnkleAllowsIsReachedByRestartingThatLegOnly) {
  Kinematics kin(legs_with_feet());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  const Eigen::VectorXd start_tips = tips_at(kin, rest);
  const double tolerance = 1e-4;
  for (int chain_restarts : {0, 8}) {
    SolverOptions o = drag_options(tolerance);
    o.chain_restarts = chain_restarts;
    o.max_iterations = 20000;
    auto solver = make_solver(GetParam(), kin, o);
    Eigen::VectorXd pose = rest, target = start_tips;
    int missed = 0, chain_restarts_used = 0;
    for (int step = 1; step <= 20; ++step) {  // 0.6 up, 30% of the legs' height
      target[1] = start_tips[1] + 0.03 * step;
      const SolverSummary& s = solver->solve(pose, target);
      pose = s.angles;
      missed += s.reached ? 0 : 1;
      chain_restarts_used += s.chain_restarts;
      EXPECT_LT((tips_at(kin, pose).segment<3>(3) - target.segment<3>(3)).norm(), tolerance) << "the pinned foot moved";
    }
    if (chain_restarts == 0) {
      EXPECT_GT(missed, 0) << "the lift should need more than small moves";
    } else {
      EXPECT_EQ(missed, 0);
      EXPECT_GT(chain_restarts_used, 0);
    }
  }
}

// A target within the limb's length that its limits keep out of reach: every frame of a held
// drag solves from where the last one ended. Solves cut short by their budget go on with the
// chain restarts the previous one left; once all are spent, holding costs no more restarts.
TEST_P(StraightLimb, AHeldTargetGoesOnWithTheChainRestartsTheLastFrameLeft) {
  Rig rig = straight_limb();
  rig.bones[0].min_deg = Eigen::Vector3d(0, -10, 0);
  rig.bones[0].max_deg = Eigen::Vector3d(0, 10, 0);
  rig.bones[1].min_deg = Eigen::Vector3d(0, 0, 0);
  rig.bones[1].max_deg = Eigen::Vector3d(0, 20, 0);
  Kinematics kin(rig);
  const Eigen::Vector3d target(0.2, 1.5, 0);  // |target| < 2, but the limb turns 30 degrees at most
  SolverOptions whole = drag_options(1e-4);
  auto reference = make_solver(GetParam(), kin, whole);
  const SolverSummary& all = reference->solve(Eigen::VectorXd::Zero(kin.num_angles()), target);
  ASSERT_FALSE(all.reached);
  ASSERT_EQ(all.chain_restarts, whole.chain_restarts);

  SolverOptions frame = whole;
  frame.max_iterations = 25;  // a frame's budget: a few chain restarts each
  auto solver = make_solver(GetParam(), kin, frame);
  Eigen::VectorXd pose = Eigen::VectorXd::Zero(kin.num_angles());
  int spent = 0, frames = 0;
  StopReason reason = StopReason::running;
  for (; frames < 1000 && reason != StopReason::converged_grad; ++frames) {
    const SolverSummary& s = solver->solve(pose, target);
    pose = s.angles;
    spent += s.chain_restarts;
    reason = s.stop_reason;
  }
  EXPECT_EQ(reason, StopReason::converged_grad);
  EXPECT_GT(frames, 2);
  EXPECT_EQ(spent, whole.chain_restarts);
  EXPECT_EQ(solver->solve(pose, target).chain_restarts, 0);  // holding on: nothing left to try
  // The same start and target from scratch: the same solve as the first.
  auto again = make_solver(GetParam(), kin, whole);
  EXPECT_EQ(again->solve(Eigen::VectorXd::Zero(kin.num_angles()), target).angles, all.angles);
}

TEST_P(StraightLimb, TheEscapeAllocatesNothing) {
  Kinematics kin(straight_limb());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kin.num_angles());
  const Eigen::Vector3d target(1.7, 0, 0);
  auto solver = make_solver(GetParam(), kin, drag_options(1e-4));
  solver->solve(rest, target);  // sizes the workspace
  const long before = test::heap_allocations();
  solver->start(rest, target);
  while (solver->step()) {
  }
  EXPECT_EQ(test::heap_allocations() - before, 0);
  EXPECT_GE(solver->summary().escapes, 1);
  EXPECT_TRUE(solver->summary().reached);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, StraightLimb, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace ik

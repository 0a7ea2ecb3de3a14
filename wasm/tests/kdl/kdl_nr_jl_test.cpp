// The native bench's `kdl_nr_jl` method (native/kdl/kdl_nr_jl.h): KDL's ChainIkSolverPos_NR_JL
// called one iteration at a time from its last result, as TRAC-IK's harness calls it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "../../native/kdl/kdl_nr_jl.h"
#include "../a7_fixtures.h"
#include "../small_rigs.h"
#include "kinematics.h"

namespace ik::test {
namespace {

// The pose of the rig's one effector at `angles`: its tip and its bone frame.
struct Pose {
  Eigen::VectorXd tip;
  std::vector<Eigen::Matrix3d> frame;
};
Pose pose_at(Kinematics& kin, const Eigen::VectorXd& angles) {
  kin.forward(angles);
  const int bone = kin.rig().effectors[0];
  return {kin.tip(bone), {kin.tip_rotation(bone)}};
}

// Our forward kinematics of `angles` meets `target` by KDL's test: every position component within
// `tol`, and the frame within it per component (its angle within sqrt(3) tol).
void expect_on_pose(Kinematics& kin, const Eigen::VectorXd& angles, const Pose& target, double tol, int k) {
  const Pose at = pose_at(kin, angles);
  EXPECT_LE((at.tip - target.tip).cwiseAbs().maxCoeff(), tol) << k;
  EXPECT_LE(Eigen::AngleAxisd(target.frame[0] * at.frame[0].transpose()).angle(), std::sqrt(3.0) * tol) << k;
}

TEST(KdlNrJl, ReachesPosesNearItsStartWithinKdlsTolerance) {
  const Rig rig = straight_chain(3, {2});
  Kinematics kin(rig);
  SolverOptions options;
  options.tip_tolerance = 1e-6;
  kdl::KdlNrJl solver(rig, options);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> near(-10, 10);
  for (int k = 0; k < 10; ++k) {
    // Away from the limits, which NR_JL clamps the joints to (a clamped run may stall there).
    Eigen::VectorXd start = 0.5 * random_angles(kin, rng), goal = start;
    for (int i = 0; i < goal.size(); ++i) goal[i] = std::clamp(goal[i] + near(rng), kin.lower()[i], kin.upper()[i]);
    const Pose target = pose_at(kin, goal);
    const kdl::KdlSummary& s = solver.solve(start, target.tip, target.frame);
    ASSERT_EQ(s.stop_reason, "converged_E") << k;
    EXPECT_TRUE(s.reached);
    EXPECT_GT(s.iterations, 1);  // one Newton-Raphson step per call: a 10 degree move takes several
    // Our forward kinematics of the returned angles agrees with KDL's verdict.
    expect_on_pose(kin, s.angles, target, 1e-6, k);
    EXPECT_NEAR(s.tip_distance, (pose_at(kin, s.angles).tip - target.tip).norm(), 1e-12);
    EXPECT_TRUE(
        ((s.angles.array() >= kin.lower().array() - 1e-9) && (s.angles.array() <= kin.upper().array() + 1e-9)).all());
  }
}

TEST(KdlNrJl, OneAngleJointsAFullTurnAndAnUnlimitedOne) {
  // An arm as the project's robot arm: a waist turning a full circle about x, three hinges about z,
  // an unlimited roll about x at the tool; every other angle fixed (0 or 10 degrees).
  Rig rig;
  for (int i = 0; i < 5; ++i) add_bone(rig, i - 1, Eigen::Vector3d(i, 0.2 * i, 0), 1, 0);
  rig.bones[0].min_deg[0] = -180, rig.bones[0].max_deg[0] = 180;
  for (int i = 1; i <= 3; ++i) rig.bones[i].min_deg[1] = -100, rig.bones[i].max_deg[1] = 100;
  rig.bones[2].min_deg[0] = rig.bones[2].max_deg[0] = 10;
  rig.bones[4].min_deg[2] = -INFINITY, rig.bones[4].max_deg[2] = INFINITY;
  rig.effectors = {4};
  Kinematics kin(rig);
  SolverOptions options;
  options.tip_tolerance = 1e-6;
  kdl::KdlNrJl solver(rig, options);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> near(-10, 10);
  int reached = 0;
  for (int k = 0; k < 10; ++k) {
    Eigen::VectorXd start = Eigen::VectorXd::Zero(kin.num_angles());
    start[0] = 170, start[4] = 30, start[7] = -40, start[10] = 50, start[14] = 400;
    kin.project(start);
    Eigen::VectorXd goal = start;
    for (int i : {0, 4, 7, 10, 14}) goal[i] += near(rng);
    const Pose target = pose_at(kin, goal);
    const kdl::KdlSummary& s = solver.solve(start, target.tip, target.frame);
    if (!s.reached) continue;
    ++reached;
    expect_on_pose(kin, s.angles, target, 1e-6, k);
    EXPECT_GE(s.angles[0], -180);  // the waist comes back within its turn
    EXPECT_LT(s.angles[0], 180);
    EXPECT_EQ(s.angles[6], 10);  // a fixed angle keeps its value
  }
  EXPECT_GE(reached, 8);
}

TEST(KdlNrJl, StopsAtTheIterationCapOffTarget) {
  const Rig rig = straight_chain(2, {1});
  Kinematics kin(rig);
  SolverOptions options;
  options.max_iterations = 3;
  options.time_budget_s = 0;
  kdl::KdlNrJl solver(rig, options);
  const Pose far = pose_at(kin, Eigen::VectorXd::Constant(kin.num_angles(), 60).cwiseMin(kin.upper()));
  const kdl::KdlSummary& s = solver.solve(Eigen::VectorXd::Zero(kin.num_angles()), far.tip, far.frame);
  EXPECT_EQ(s.stop_reason, "max_iterations");
  EXPECT_EQ(s.iterations, 3);
  EXPECT_FALSE(s.reached);
}

TEST(KdlNrJl, RefusesPositionsAloneAndRigsOfManyEffectors) {
  const Rig rig = straight_chain(2, {1});
  Kinematics kin(rig);
  kdl::KdlNrJl solver(rig, SolverOptions());
  const kdl::KdlSummary& s = solver.solve(Eigen::VectorXd::Zero(kin.num_angles()), Eigen::Vector3d(1, 0, 0), {});
  EXPECT_EQ(s.stop_reason, "invalid_input");
  EXPECT_NE(s.message.find("whole poses"), std::string::npos);
  EXPECT_THROW(kdl::KdlNrJl(straight_chain(4, {1, 3}), SolverOptions()), std::invalid_argument);
}

}  // namespace
}  // namespace ik::test

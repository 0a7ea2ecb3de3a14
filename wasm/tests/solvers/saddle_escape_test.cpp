// SaddleEscape (saddle_escape.h) used across workspace changes: the Solver resizes it whenever
// the goals' rows change (a pole or an orientation goal added between two frames), and a find()
// after that must start from a clean set of chosen angles. And a limb straight on its limit: the
// sign the limit stops is not searched.
#include <gtest/gtest.h>

#include "../small_rigs.h"
#include "goal_residual.h"
#include "goals.h"
#include "solvers/saddle_escape.h"

namespace ik {
namespace {

// A straight two-bone limb (limits of +-180 degrees) whose target lies along it, 0.2 nearer its
// root: a stationary point of E with negative curvature (the bend), posed in `kin`.
struct StraightLimbSaddle {
  explicit StraightLimbSaddle(const Rig& rig) : kin(rig) {
    angles = Eigen::VectorXd::Zero(kin.num_angles());
    goals.set_positions(kin, Eigen::Vector3d(1.8, 0, 0));
    r.resize(goals.rows());
    E = goal_objective(kin, goals, angles, r);
    J.resize(goals.rows(), kin.num_angles());
    goal_jacobian(kin, goals, J, Kinematics::Columns::movable);
  }
  Kinematics kin;
  GoalSet goals;
  Eigen::VectorXd angles, r;
  Eigen::MatrixXd J;
  double E = 0;
};

Rig straight_limb() {
  Rig rig = test::two_bones();
  for (Bone& b : rig.bones) {
    b.min_deg.setConstant(-180);
    b.max_deg.setConstant(180);
  }
  return rig;
}

TEST(SaddleEscape, FindsTheSameBendAfterItsWorkspaceWasResized) {
  StraightLimbSaddle s(straight_limb());
  SaddleEscape escape;
  escape.resize(s.kin, s.goals.rows());
  s.kin.forward(s.angles);  // find() left it at a trial point
  Eigen::VectorXd first(s.kin.num_angles()), again(s.kin.num_angles()), residual(s.goals.rows());
  const EscapeResult found = escape.find(s.kin, s.goals, s.angles, s.r, s.E, s.J, first, residual);
  ASSERT_TRUE(found.found);
  EXPECT_LT(found.E, s.E);
  // The Solver's resize when the next frame's goals change. Before the fix the chosen angles of
  // the last find() were unmarked through the cleared index: a write before the start of the
  // angles' table (the avatar's heap was corrupted; here the sanitizer suite's asserts stop it).
  escape.resize(s.kin, s.goals.rows());
  s.kin.forward(s.angles);  // find() left it at a trial point
  const EscapeResult after = escape.find(s.kin, s.goals, s.angles, s.r, s.E, s.J, again, residual);
  ASSERT_TRUE(after.found);
  EXPECT_EQ(after.E, found.E);
  EXPECT_EQ(again, first);
}

// The same limb bending in one plane (the z angles only), its elbow like a knee: it bends one way,
// [0, 150] degrees, and stands straight on that limit. The bend's eigenvector turns the elbow and
// the shoulder; its other sign pushes the elbow past the limit, and what the bounds leave of that
// turns the straight limb whole, along which E only rises: that sign is not searched (it took 29
// evaluations, every halving of its step). The escape bends the elbow the way it goes.
TEST(SaddleEscape, DoesNotSearchTheSignItsBoundsTurnUphill) {
  Rig rig = straight_limb();
  for (Bone& b : rig.bones) {
    b.min_deg = Eigen::Vector3d(0, -180, 0);
    b.max_deg = Eigen::Vector3d(0, 180, 0);
  }
  rig.bones[1].min_deg[1] = 0;
  rig.bones[1].max_deg[1] = 150;
  StraightLimbSaddle s(rig);
  SaddleEscape escape;
  escape.resize(s.kin, s.goals.rows());
  Eigen::VectorXd trial(s.kin.num_angles()), residual(s.goals.rows());
  const EscapeResult found = escape.find(s.kin, s.goals, s.angles, s.r, s.E, s.J, trial, residual);
  ASSERT_TRUE(found.found);
  EXPECT_LT(found.E, s.E);
  EXPECT_GT(trial[4], 0);  // the elbow's z: bent the way it goes
  EXPECT_LE(found.evaluations, 3);
}

}  // namespace
}  // namespace ik

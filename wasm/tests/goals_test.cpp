// GoalSet (goals.h): the block layout, plain goals, weights of 0 and what set() refuses.
#include <gtest/gtest.h>

#include "goals.h"
#include "small_rigs.h"

namespace ik {
namespace {

Rig two_effector_rig() {
  Rig rig;
  Bone root;
  root.length = 1;
  Bone left = root, right = root;
  left.parent = right.parent = 0;
  right.rest.block<3, 1>(0, 3) = Eigen::Vector3d(0, 1, 0);
  rig.bones = {root, left, right};
  rig.effectors = {1, 2};
  return rig;
}

TEST(Goals, PositionGoalsOfWeightOneArePlainWithOneBlockPerEffector) {
  Kinematics kin(two_effector_rig());
  Goals goals;
  goals.effectors.resize(2);
  goals.effectors[0].position_target = Eigen::Vector3d(1, 2, 3);
  goals.effectors[1].position_target = Eigen::Vector3d(4, 5, 6);
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  EXPECT_TRUE(set.plain());
  EXPECT_EQ(set.rows(), 6);
  EXPECT_EQ(set.plain_target(), (Eigen::VectorXd(6) << 1, 2, 3, 4, 5, 6).finished());
  GoalSet from_target;
  from_target.set_positions(kin, set.plain_target());
  EXPECT_TRUE(from_target == set);
}

TEST(Goals, BlocksArePositionThenOrientationPerEffector) {
  Kinematics kin(two_effector_rig());
  Goals goals;
  goals.effectors.resize(2);
  goals.effectors[0].orientation = true;
  goals.effectors[0].orientation_weight = 2;
  goals.effectors[1].position = false;
  goals.effectors[1].orientation = true;
  goals.length_scale = 3;
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  EXPECT_FALSE(set.plain());
  EXPECT_TRUE(set.has_orientation());
  ASSERT_EQ(set.num_blocks(), 3);
  EXPECT_EQ(set.layout(), (std::vector<int>{0, 1, 3}));
  EXPECT_DOUBLE_EQ(set.block(0).scale, 0.5);  // w_p / the largest weight (2)
  EXPECT_DOUBLE_EQ(set.block(1).scale, 3);    // w_o / the largest weight, times L
  EXPECT_EQ(set.position_block(0), 0);
  EXPECT_EQ(set.position_block(1), -1);
}

TEST(Goals, TheDefaultLengthScaleIsTheRigsReach) {
  Kinematics kin(two_effector_rig());
  Goals goals;
  goals.effectors.resize(2);
  goals.effectors[1].orientation = true;
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  EXPECT_DOUBLE_EQ(rig_reach(kin), 2);
  EXPECT_DOUBLE_EQ(set.block(2).scale, 2);
}

TEST(Goals, AGoalOfWeightZeroIsNoGoal) {
  Kinematics kin(two_effector_rig());
  Goals goals;
  goals.effectors.resize(2);
  goals.effectors[1].orientation = true;
  goals.effectors[1].orientation_weight = 0;
  GoalSet set;
  ASSERT_EQ(set.set(kin, goals), "");
  EXPECT_TRUE(set.plain());
  EXPECT_EQ(set.rows(), 6);
}

TEST(Goals, RefusesWrongInput) {
  Kinematics kin(two_effector_rig());
  GoalSet set;
  Goals goals;
  EXPECT_NE(set.set(kin, goals).find("expected 2"), std::string::npos);
  goals.effectors.resize(2);
  goals.effectors[0].orientation = true;
  goals.effectors[0].orientation_target(0, 0) = 2;
  EXPECT_NE(set.set(kin, goals).find("not a rotation"), std::string::npos);
  goals.effectors[0].orientation_target.setIdentity();
  goals.effectors[1].position_weight = -1;
  EXPECT_NE(set.set(kin, goals).find("weight"), std::string::npos);
  goals.effectors[1].position_weight = 1;
  goals.effectors[1].position_target.x() = std::nan("");
  EXPECT_NE(set.set(kin, goals).find("not finite"), std::string::npos);
  for (EffectorGoal& g : goals.effectors) g.position = g.orientation = false;
  EXPECT_NE(set.set(kin, goals).find("no goal"), std::string::npos);
}

}  // namespace
}  // namespace ik

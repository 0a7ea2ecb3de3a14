#include <gtest/gtest.h>

#include <algorithm>

#include "a7_fixtures.h"
#include "small_rigs.h"

namespace ik {
namespace {

TEST(ForwardKinematics, MatchesReferenceComposition) {
  std::mt19937_64 rng(1);
  for (const test::TestRig& r : test::test_rigs()) {
    const Rig& rig = r.rig;
    Kinematics kin(rig);
    Eigen::VectorXd tips(kin.num_residuals());
    for (int s = 0; s < 200; ++s) {
      const Eigen::VectorXd a = test::random_angles(kin, rng);
      kin.tips(a, tips);
      const Eigen::VectorXd ref = test::reference_tips(rig, a);
      const double scale = std::max(1.0, ref.cwiseAbs().maxCoeff());
      EXPECT_LE((tips - ref).cwiseAbs().maxCoeff(), 1e-12 * scale) << r.label() << " sample " << s;
    }
  }
}

// forward() at the angles of its last call keeps that pose; any other angles, even one differing
// in the last angle only (a floating root's translation), or a +0 turned -0, pose the rig anew.
TEST(ForwardKinematics, PosesAnewUnlessTheAnglesAreTheLastOnes) {
  std::mt19937_64 rng(3);
  std::vector<test::TestRig> rigs = test::test_rigs();
  rigs.push_back({"two arms, floating", false, test::two_arms(true)});
  for (const test::TestRig& r : rigs) {
    Kinematics kin(r.rig);
    Eigen::VectorXd tips(kin.num_residuals());
    // The reference has no floating root: its translation moves every tip (one root here).
    const auto reference = [&](const Eigen::VectorXd& angles) {
      Eigen::VectorXd ref = test::reference_tips(r.rig, angles);
      if (kin.floats())
        for (int k = 0; k < kin.num_effectors(); ++k) ref.segment<3>(3 * k) += angles.tail<3>();
      return ref;
    };
    const Eigen::VectorXd a = test::random_angles(kin, rng);
    const Eigen::VectorXd b = [&] {
      Eigen::VectorXd v = a;
      v[v.size() - 1] = a[a.size() - 1] == 0 ? 0.5 : 0;
      return v;
    }();
    kin.tips(a, tips);
    const Eigen::VectorXd at_a = tips;
    for (const Eigen::VectorXd* angles : {&a, &b, &a, &a}) {
      kin.tips(*angles, tips);
      const Eigen::VectorXd ref = reference(*angles);
      EXPECT_LE((tips - ref).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, ref.cwiseAbs().maxCoeff())) << r.label();
    }
    EXPECT_EQ(tips, at_a) << r.label();
    Eigen::VectorXd zero = Eigen::VectorXd::Zero(kin.num_angles());
    kin.tips(zero, tips);
    zero[0] = -0.0;
    kin.tips(zero, tips);
    EXPECT_LE((tips - reference(zero)).cwiseAbs().maxCoeff(), 1e-12) << r.label();
  }
}

TEST(ForwardKinematics, ZeroAnglesPutTipsAtRest) {
  for (const test::TestRig& r : test::test_rigs()) {
    const Rig& rig = r.rig;
    Kinematics kin(rig);
    kin.forward(Eigen::VectorXd::Zero(kin.num_angles()));
    for (int i = 0; i < kin.num_bones(); ++i) {
      const Eigen::Vector3d rest_tip = (rig.bones[i].rest * Eigen::Vector4d(rig.bones[i].length, 0, 0, 1)).head<3>();
      EXPECT_LT((kin.tip(i) - rest_tip).norm(), 1e-12) << r.label() << " bone " << i;
      EXPECT_TRUE(kin.pose(i).matrix().isApprox(Eigen::Matrix4d::Identity(), 1e-12)) << r.label() << " bone " << i;
    }
  }
}

TEST(ForwardKinematics, ProjectClampsIntoLimits) {
  for (const test::TestRig& r : test::test_rigs()) {
    Kinematics kin(r.rig);
    for (double value : {500.0, -500.0}) {
      Eigen::VectorXd a = Eigen::VectorXd::Constant(kin.num_angles(), value);
      kin.project(a);
      for (int i = 0; i < a.size(); ++i) {
        const Bone& bone = r.rig.bones[i / 3];
        EXPECT_EQ(a[i], std::clamp(value, bone.min_deg[i % 3], bone.max_deg[i % 3])) << r.label() << " angle " << i;
      }
    }
  }
}

using ForwardKinematicsA7 = test::NeedsA7;

TEST_F(ForwardKinematicsA7, ProjectClampsTheLampIntoItsLimits) {
  Kinematics kin(test::load_a7("ikea-lamp"));
  Eigen::VectorXd a = Eigen::VectorXd::Constant(kin.num_angles(), 500.0);
  kin.project(a);
  EXPECT_DOUBLE_EQ(a[3], 90.0);   // bone 1 x in [-90, 90]
  EXPECT_DOUBLE_EQ(a[7], 120.0);  // bone 2 z in [-60, 120]
  EXPECT_DOUBLE_EQ(a[0], 0.0);    // fixed root
}

TEST(ForwardKinematics, HandlesChildrenListedBeforeParentsAndSeveralRoots) {
  Rig rig;
  Bone child;
  child.parent = 2;
  child.length = 1;
  child.rest.block<3, 1>(0, 3) = Eigen::Vector3d(2, 0, 0);
  Bone root_a;
  root_a.length = 2;
  Bone root_b;
  root_b.length = 0.5;
  root_b.rest.block<3, 1>(0, 3) = Eigen::Vector3d(0, 3, 0);
  Bone mid;
  mid.parent = 1;
  mid.length = 0;
  mid.rest.block<3, 1>(0, 3) = Eigen::Vector3d(2, 0, 0);
  rig.bones = {child, root_a, mid, root_b};
  rig.effectors = {0, 3};
  Kinematics kin(rig);
  std::mt19937_64 rng(2);
  Eigen::VectorXd tips(kin.num_residuals());
  for (int s = 0; s < 20; ++s) {
    const Eigen::VectorXd a = test::random_angles(kin, rng);
    kin.tips(a, tips);
    EXPECT_LE((tips - test::reference_tips(rig, a)).cwiseAbs().maxCoeff(), 1e-12);
  }
}

}  // namespace
}  // namespace ik

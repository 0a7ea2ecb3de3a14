// Our rigs as KDL trees (native/kdl/kdl_rig.h): KDL's forward kinematics equals ours on every
// test rig at random poses, and the degree <-> radian mapping round-trips.
#include <gtest/gtest.h>

#include <cstdio>
#include <kdl/treefksolverpos_recursive.hpp>
#include <random>

#include "../../native/kdl/kdl_rig.h"
#include "../a7_fixtures.h"
#include "../small_rigs.h"
#include "kinematics.h"

namespace ik::test {
namespace {

// Largest coordinate difference between KDL's tips and ours over `poses` random poses.
double worst_tip_difference(const Rig& rig, int poses) {
  Kinematics kin(rig);
  const kdl::KdlRig k = kdl::make_kdl_rig(rig);
  KDL::TreeFkSolverPos_recursive fk(k.tree);
  std::mt19937_64 rng(7);
  Eigen::VectorXd ours(kin.num_residuals());
  KDL::JntArray q;
  double worst = 0;
  for (int pose = 0; pose < poses; ++pose) {
    const Eigen::VectorXd angles = random_angles(kin, rng);
    kin.tips(angles, ours);
    kdl::angles_to_joints(k, angles, q);
    for (int e = 0; e < kin.num_effectors(); ++e) {
      KDL::Frame f;
      EXPECT_GE(fk.JntToCart(q, f, k.tip_segments[e]), 0);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(f.p(c) - ours[3 * e + c]));
    }
  }
  return worst;
}

TEST(KdlForwardKinematics, EqualsOursOnEveryTestRig) {
  for (const TestRig& t : test_rigs()) {
    const double worst = worst_tip_difference(t.rig, 200);
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty(t.label() + " worst", text);  // --gtest_output=xml shows it
    EXPECT_LE(worst, 1e-12) << t.label();
  }
}

TEST(KdlForwardKinematics, FixedAnglesBecomeFixedSegments) {
  Rig rig = straight_chain(3, {2});
  rig.bones[1].min_deg[1] = rig.bones[1].max_deg[1] = 30;  // fixed at 30 degrees
  const kdl::KdlRig k = kdl::make_kdl_rig(rig);
  EXPECT_EQ(k.num_joints(), 8);
  EXPECT_EQ(k.joint_of_angle[4], -1);
  EXPECT_LE(worst_tip_difference(rig, 50), 1e-12);
}

TEST(KdlForwardKinematics, AnglesRoundTripThroughJoints) {
  const Rig rig = straight_chain(2, {1});
  const kdl::KdlRig k = kdl::make_kdl_rig(rig);
  const Eigen::VectorXd angles = (Eigen::VectorXd(6) << 10, -20, 30, 45, 0, -89).finished();
  KDL::JntArray q;
  kdl::angles_to_joints(k, angles, q);
  EXPECT_NEAR(q(0), 10 * kRadPerDeg, 1e-15);
  EXPECT_NEAR(k.q_max(5), 90 * kRadPerDeg, 1e-15);
  Eigen::VectorXd back(6);
  kdl::joints_to_angles(k, q, back);
  EXPECT_LE((back - angles).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace ik::test

// Our rig as an Orocos KDL tree (native builds with KDL only): each bone becomes a fixed segment
// for its rest transform relative to its parent's frame, then three revolute joints RotX, RotZ,
// RotX (an angle whose limits fix it, min == max, becomes a fixed segment with that rotation baked
// in), and each end effector a fixed segment whose tip is the bone's tip (length, 0, 0).
// KDL numbers the joints of its own copy of the tree (a copy renumbers them depth first), so the
// joint of an angle is looked up by its segment name in the final tree.
// The frame after a bone's third joint is kinematics.h's frame of that bone, so KDL's tips are ours.
#pragma once

#include <Eigen/Core>
#include <kdl/jntarray.hpp>
#include <kdl/tree.hpp>
#include <string>
#include <vector>

#include "../../src/rig.h"

namespace ik::kdl {

struct KdlRig {
  KDL::Tree tree;
  std::vector<std::string> tip_segments;  // per end effector (in Rig::effectors order): its segment's name
  std::vector<int> joint_of_angle;        // per angle: KDL joint index (q_nr), -1 for a fixed angle
  Eigen::VectorXd fixed_deg;              // per angle: the value of a fixed angle (degrees), else 0
  KDL::JntArray q_min, q_max;             // per KDL joint: limits in radians (+-infinity if unbounded)
  int num_angles() const { return static_cast<int>(joint_of_angle.size()); }
  int num_joints() const { return static_cast<int>(tree.getNrOfJoints()); }
};

// Builds the tree of `rig` (validated first; throws RigError). Segment names: "b<i>.rest",
// "b<i>.x0", "b<i>.z1", "b<i>.x2" for bone i and "e<k>.tip" for effector k. Limits come from the
// rig's degrees, converted to radians.
KdlRig make_kdl_rig(const Rig& rig);

// Angles (#angles, degrees) -> KDL joint values (#joints, radians); fixed angles are dropped.
void angles_to_joints(const KdlRig& k, const Eigen::Ref<const Eigen::VectorXd>& angles_deg, KDL::JntArray& q);

// KDL joint values (#joints, radians) -> angles (#angles, degrees); fixed angles take their value.
void joints_to_angles(const KdlRig& k, const KDL::JntArray& q, Eigen::Ref<Eigen::VectorXd> angles_deg);

}  // namespace ik::kdl

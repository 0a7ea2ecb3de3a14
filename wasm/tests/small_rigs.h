// Small rigs built in code, shared by the native tests that need no A7 file.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "rig.h"

namespace ik::test {

// A rigid transform that only translates by (x, y, z), rig units.
inline Eigen::Matrix4d translation(double x, double y, double z) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 3) = Eigen::Vector3d(x, y, z);
  return m;
}

// Appends a bone to `rig` whose rest transform translates to `at` (rig units, no turn), of
// `length` along its rest x axis, every angle within +-`limit` degrees. Returns its index.
inline int add_bone(Rig& rig, int parent, const Eigen::Vector3d& at, double length, double limit,
                    const char* name = "") {
  Bone b;
  b.name = name;
  b.parent = parent;
  b.rest.block<3, 1>(0, 3) = at;
  b.length = length;
  b.min_deg.setConstant(-limit);
  b.max_deg.setConstant(limit);
  rig.bones.push_back(b);
  return static_cast<int>(rig.bones.size()) - 1;
}

// One bone of length 1 along +x from the origin, without limits; its tip (1, 0, 0) is the effector.
inline Rig one_bone() {
  Rig rig;
  rig.bones.resize(1);
  rig.bones[0].length = 1;
  rig.effectors = {0};
  return rig;
}

// Two bones "upper" and "lower" of length 1 along +x from the origin, without limits; the
// effector is the second bone's tip, (2, 0, 0) at rest.
inline Rig two_bones() {
  Rig rig;
  rig.bones.resize(2);
  rig.bones[0].name = "upper";
  rig.bones[0].length = 1;
  rig.bones[1].name = "lower";
  rig.bones[1].parent = 0;
  rig.bones[1].rest = translation(1, 0, 0);
  rig.bones[1].length = 1;
  rig.effectors = {1};
  return rig;
}

// A trunk with two two-bone arms (limits +-120 degrees), effectors at both hands, and a floating
// root within [-2, 2] x [-1, 0.5] x [-2, 2] when `floating`.
inline Rig two_arms(bool floating) {
  Rig rig;
  const int trunk = test::add_bone(rig, -1, Eigen::Vector3d(0, 0, 0), 1, 120, "trunk");
  const int upper_l = test::add_bone(rig, trunk, Eigen::Vector3d(1, 0.2, 0), 1, 120, "upper.L");
  const int hand_l = test::add_bone(rig, upper_l, Eigen::Vector3d(2, 0.2, 0), 1, 120, "hand.L");
  const int upper_r = test::add_bone(rig, trunk, Eigen::Vector3d(1, -0.2, 0), 1, 120, "upper.R");
  const int hand_r = test::add_bone(rig, upper_r, Eigen::Vector3d(2, -0.2, 0), 1, 120, "hand.R");
  rig.effectors = {hand_l, hand_r};
  rig.floating_root.on = floating;
  rig.floating_root.min = Eigen::Vector3d(-2, -1, -2);
  rig.floating_root.max = Eigen::Vector3d(2, 0.5, 2);
  return rig;
}

// A straight chain of `bones` bones of length 1 along +x, each limited to +-90 degrees per
// angle, with the given end effectors (bone indices).
inline Rig straight_chain(int bones, std::vector<int> effectors) {
  Rig rig;
  rig.bones.resize(bones);
  for (int i = 0; i < bones; ++i) {
    Bone& b = rig.bones[i];
    b.parent = i - 1;
    b.rest = translation(i, 0, 0);  // rest transforms are in rig space
    b.length = 1;
    b.min_deg = Eigen::Vector3d::Constant(-90);
    b.max_deg = Eigen::Vector3d::Constant(90);
  }
  rig.effectors = std::move(effectors);
  return rig;
}

}  // namespace ik::test

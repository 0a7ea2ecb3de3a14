#include "kdl_rig.h"

#include <Eigen/Geometry>
#include <kdl/segment.hpp>

#include "../../src/kinematics.h"

namespace ik::kdl {

namespace {

// A rigid 4x4 transform as a KDL frame.
KDL::Frame to_frame(const Eigen::Matrix4d& m) {
  const KDL::Rotation r(m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2));
  return KDL::Frame(r, KDL::Vector(m(0, 3), m(1, 3), m(2, 3)));
}

// Rotation about X (axis 0) or Z (axis 2) by `deg` degrees.
KDL::Rotation rotation(int axis, double deg) {
  const double rad = deg * kRadPerDeg;
  return axis == 0 ? KDL::Rotation::RotX(rad) : KDL::Rotation::RotZ(rad);
}

// The inverse of a rigid transform, as kinematics.cpp takes it (R^T, -R^T t).
Eigen::Matrix4d rigid_inverse(const Eigen::Matrix4d& m) {
  Eigen::Isometry3d t;
  t.matrix() = m;
  t.makeAffine();
  return t.inverse(Eigen::Isometry).matrix();
}

void add(KDL::Tree& tree, const KDL::Segment& segment, const std::string& hook) {
  if (!tree.addSegment(segment, hook)) throw RigError("KDL tree: cannot add segment " + segment.getName());
}

// The KDL joint number (q_nr) of segment `name` in `tree`.
int joint_number(const KDL::Tree& tree, const std::string& name) {
  return static_cast<int>(GetTreeElementQNr(tree.getSegments().find(name)->second));
}

}  // namespace

KdlRig make_kdl_rig(const Rig& rig) {
  validate_rig(rig);
  const int n = static_cast<int>(rig.bones.size());
  KDL::Tree built("root");
  std::vector<std::string> joint_segment(3 * n);  // per angle: its segment, empty when fixed
  KdlRig k;
  k.fixed_deg = Eigen::VectorXd::Zero(3 * n);
  const char* suffix[3] = {".x0", ".z1", ".x2"};
  const int axis[3] = {0, 2, 0};
  for (int i : parents_first(rig)) {
    const Bone& b = rig.bones[i];
    const int p = b.parent;
    const Eigen::Matrix4d from_parent = p == -1 ? b.rest : Eigen::Matrix4d(rigid_inverse(rig.bones[p].rest) * b.rest);
    const std::string name = "b" + std::to_string(i);
    add(built, KDL::Segment(name + ".rest", KDL::Joint(KDL::Joint::Fixed), to_frame(from_parent)),
        p == -1 ? "root" : "b" + std::to_string(p) + ".x2");
    std::string hook = name + ".rest";
    for (int a = 0; a < 3; ++a) {
      const std::string seg = name + suffix[a];
      if (b.min_deg[a] == b.max_deg[a]) {
        k.fixed_deg[3 * i + a] = b.min_deg[a];
        add(built, KDL::Segment(seg, KDL::Joint(KDL::Joint::Fixed), KDL::Frame(rotation(axis[a], b.min_deg[a]))), hook);
      } else {
        joint_segment[3 * i + a] = seg;
        add(built, KDL::Segment(seg, KDL::Joint(axis[a] == 0 ? KDL::Joint::RotX : KDL::Joint::RotZ)), hook);
      }
      hook = seg;
    }
  }
  for (size_t e = 0; e < rig.effectors.size(); ++e) {
    const int bone = rig.effectors[e];
    const std::string seg = "e" + std::to_string(e) + ".tip";
    add(built, KDL::Segment(seg, KDL::Joint(KDL::Joint::Fixed), KDL::Frame(KDL::Vector(rig.bones[bone].length, 0, 0))),
        "b" + std::to_string(bone) + ".x2");
    k.tip_segments.push_back(seg);
  }
  // Copying a KDL tree numbers its joints again, depth first; every KDL solver keeps a copy. So the
  // numbering is read from a copy, and a copy of that copy must number the same.
  k.tree = KDL::Tree(built);
  const KDL::Tree again(k.tree);
  const int joints = k.num_joints();
  k.joint_of_angle.assign(3 * n, -1);
  k.q_min.resize(joints);
  k.q_max.resize(joints);
  for (int index = 0; index < 3 * n; ++index) {
    if (joint_segment[index].empty()) continue;
    const int j = joint_number(k.tree, joint_segment[index]);
    if (j != joint_number(again, joint_segment[index]))
      throw RigError("KDL tree: joint numbering changes with a copy at " + joint_segment[index]);
    const Bone& b = rig.bones[index / 3];
    k.joint_of_angle[index] = j;
    k.q_min(j) = b.min_deg[index % 3] * kRadPerDeg;
    k.q_max(j) = b.max_deg[index % 3] * kRadPerDeg;
  }
  return k;
}

void angles_to_joints(const KdlRig& k, const Eigen::Ref<const Eigen::VectorXd>& angles_deg, KDL::JntArray& q) {
  if (q.rows() != static_cast<unsigned>(k.num_joints())) q.resize(k.num_joints());
  for (int a = 0; a < k.num_angles(); ++a)
    if (k.joint_of_angle[a] >= 0) q(k.joint_of_angle[a]) = angles_deg[a] * kRadPerDeg;
}

void joints_to_angles(const KdlRig& k, const KDL::JntArray& q, Eigen::Ref<Eigen::VectorXd> angles_deg) {
  for (int a = 0; a < k.num_angles(); ++a)
    angles_deg[a] = k.joint_of_angle[a] >= 0 ? q(k.joint_of_angle[a]) / kRadPerDeg : k.fixed_deg[a];
}

}  // namespace ik::kdl

#include "rig.h"

#include <Eigen/LU>

#include <cmath>
#include <sstream>

namespace ik {

std::string bone_label(const Rig& rig, int index) {
  std::ostringstream out;
  out << "bone " << index;
  if (index >= 0 && index < static_cast<int>(rig.bones.size()) && !rig.bones[index].name.empty())
    out << " \"" << rig.bones[index].name << "\"";
  return out.str();
}

namespace {

[[noreturn]] void fail(const Rig& rig, int bone, const std::string& what) {
  throw RigError(bone_label(rig, bone) + ": " + what);
}

void check_rest(const Rig& rig, int i) {
  const Eigen::Matrix4d& m = rig.bones[i].rest;
  if (!m.allFinite()) fail(rig, i, "rest_T has a non-finite entry");
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-9)
    fail(rig, i, "rest_T bottom row is not (0, 0, 0, 1)");
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6)
    fail(rig, i, "rest_T is not rigid (its rotation part is not orthonormal)");
  if (r.determinant() < 0) fail(rig, i, "rest_T is not rigid (it mirrors: determinant < 0)");
}

void check_limits(const Rig& rig, int i) {
  const Bone& b = rig.bones[i];
  static const char* kAxis[3] = {"xzx_min/xzx_max[0]", "xzx_min/xzx_max[1]", "xzx_min/xzx_max[2]"};
  for (int k = 0; k < 3; ++k) {
    if (std::isnan(b.min_deg[k]) || std::isnan(b.max_deg[k]))
      fail(rig, i, std::string(kAxis[k]) + " is NaN");
    if (b.min_deg[k] > b.max_deg[k]) {
      std::ostringstream out;
      out << "limit " << kAxis[k] << " has min " << b.min_deg[k] << " > max " << b.max_deg[k];
      fail(rig, i, out.str());
    }
  }
}

}  // namespace

void validate_rig(const Rig& rig) {
  const int n = static_cast<int>(rig.bones.size());
  if (n == 0) throw RigError("rig has no bones");
  for (int i = 0; i < n; ++i) {
    const Bone& b = rig.bones[i];
    if (b.parent < -1 || b.parent >= n) {
      std::ostringstream out;
      out << "parent " << b.parent << " is out of range (the rig has " << n << " bones)";
      fail(rig, i, out.str());
    }
    if (b.parent == i) fail(rig, i, "parent is the bone itself");
    if (!std::isfinite(b.length)) fail(rig, i, "length is not finite");
    if (b.length < 0) fail(rig, i, "length is negative");
    check_rest(rig, i);
    check_limits(rig, i);
  }
  // Cycle check: walking up from any bone must reach a root within n steps.
  for (int i = 0; i < n; ++i) {
    int at = i;
    for (int steps = 0; at != -1; ++steps) {
      if (steps > n) fail(rig, i, "parent chain has a cycle");
      at = rig.bones[at].parent;
    }
  }
  if (rig.effectors.empty()) throw RigError("rig has no end effectors");
  for (size_t k = 0; k < rig.effectors.size(); ++k) {
    const int e = rig.effectors[k];
    if (e < 0 || e >= n) {
      std::ostringstream out;
      out << "end effector " << k << " is bone " << e << ", which is not a bone of the rig (0.."
          << n - 1 << ")";
      throw RigError(out.str());
    }
    for (size_t j = 0; j < k; ++j)
      if (rig.effectors[j] == e) fail(rig, e, "is listed twice as an end effector");
  }
}

}  // namespace ik

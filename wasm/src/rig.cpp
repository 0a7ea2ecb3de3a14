#include "rig.h"

#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "size_limits.h"

namespace ik {

std::string bone_label(const Rig& rig, int index) {
  std::ostringstream out;
  out << "bone " << index;
  const std::string plain = out.str();
  if (index >= 0 && index < static_cast<int>(rig.bones.size())) {
    const std::string& name = rig.bones[index].name;
    if (!name.empty() && name != plain) out << " \"" << name << "\"";
  }
  return out.str();
}

namespace {

static_assert(kMaxCoordinate == 1e9, "the messages below say 1e9");

[[noreturn]] void fail(const Rig& rig, int bone, const std::string& what) {
  throw RigError(bone_label(rig, bone) + ": " + what);
}

void check_rest(const Rig& rig, int i) {
  const Eigen::Matrix4d& m = rig.bones[i].rest;
  if (!m.allFinite()) fail(rig, i, "rest_T has a non-finite entry");
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-9) fail(rig, i, "rest_T bottom row is not (0, 0, 0, 1)");
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6)
    fail(rig, i, "rest_T is not rigid (its rotation part is not orthonormal)");
  if (r.determinant() < 0) fail(rig, i, "rest_T is not rigid (it mirrors: determinant < 0)");
  for (int k = 0; k < 3; ++k)
    if (std::abs(m(k, 3)) > kMaxCoordinate) {
      std::ostringstream out;
      out << "rest_T translation[" << k << "] is " << m(k, 3)
          << ", past +-1e9 rig units (the largest coordinate the core takes)";
      fail(rig, i, out.str());
    }
}

void check_limits(const Rig& rig, int i) {
  const Bone& b = rig.bones[i];
  static const char* kAxis[3] = {"xzx_min/xzx_max[0]", "xzx_min/xzx_max[1]", "xzx_min/xzx_max[2]"};
  for (int k = 0; k < 3; ++k) {
    if (std::isnan(b.min_deg[k]) || std::isnan(b.max_deg[k])) fail(rig, i, std::string(kAxis[k]) + " is NaN");
    // Past +-kMaxLimitDeg a limit means "none" (A7 files write -1e10); a lower limit above it, or
    // an upper one below its negative, leaves no usable angle.
    if (b.min_deg[k] > kMaxLimitDeg || b.max_deg[k] < -kMaxLimitDeg) {
      std::ostringstream out;
      out << "limit " << kAxis[k] << " is [" << b.min_deg[k] << ", " << b.max_deg[k]
          << "] degrees, which leaves no angle within +-" << kMaxLimitDeg << " degrees";
      fail(rig, i, out.str());
    }
    if (b.min_deg[k] > b.max_deg[k]) {
      std::ostringstream out;
      out << "limit " << kAxis[k] << " has min " << b.min_deg[k] << " > max " << b.max_deg[k];
      fail(rig, i, out.str());
    }
  }
}

void check_floating_root(const FloatingRoot& root) {
  if (!root.on) return;
  const char* axis[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const std::string name = std::string("floating root's ") + axis[k] + " bounds";
    if (!std::isfinite(root.min[k]) || !std::isfinite(root.max[k])) throw RigError(name + " are not finite");
    if (std::abs(root.min[k]) > kMaxCoordinate || std::abs(root.max[k]) > kMaxCoordinate)
      throw RigError(name + " lie past 1e9 rig units (the largest size the core takes)");
    if (root.min[k] > root.max[k]) throw RigError(name + " have min > max");
  }
}

}  // namespace

void validate_rig(const Rig& rig) {
  if (rig.bones.size() > static_cast<size_t>(kMaxBones))
    throw RigError("rig has " + std::to_string(rig.bones.size()) + " bones; the core takes at most " +
                   std::to_string(kMaxBones));
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
    if (b.length > kMaxCoordinate) {
      std::ostringstream out;
      out << "length is " << b.length << ", more than 1e9 rig units (the largest size the core takes)";
      fail(rig, i, out.str());
    }
    check_rest(rig, i);
    check_limits(rig, i);
  }
  parents_first(rig);  // throws on a cycle
  check_floating_root(rig.floating_root);
  validate_effectors(rig, rig.effectors);
}

void validate_effectors(const Rig& rig, const std::vector<int>& effectors) {
  const int n = static_cast<int>(rig.bones.size());
  if (effectors.empty()) throw RigError("rig has no end effectors");
  if (effectors.size() > static_cast<size_t>(kMaxEffectors))
    throw RigError(std::to_string(effectors.size()) + " end effectors; the core takes at most " +
                   std::to_string(kMaxEffectors));
  const long long columns = 3LL * n + (rig.floating_root.on ? 3 : 0);
  const long long entries = 3LL * static_cast<long long>(effectors.size()) * columns;
  if (entries > kMaxMatrixEntries)
    throw RigError(std::to_string(effectors.size()) + " end effectors on " + std::to_string(n) +
                   " bones make a Jacobian of " + std::to_string(entries) + " numbers; the core takes at most " +
                   std::to_string(kMaxMatrixEntries) + " (fewer end effectors or bones)");
  for (size_t k = 0; k < effectors.size(); ++k) {
    const int e = effectors[k];
    if (e < 0 || e >= n) {
      std::ostringstream out;
      out << "end effector " << k << " is bone " << e << ", which is not a bone of the rig (0.." << n - 1 << ")";
      throw RigError(out.str());
    }
    for (size_t j = 0; j < k; ++j)
      if (effectors[j] == e) fail(rig, e, "is listed twice as an end effector");
  }
}

std::vector<int> parents_first(const Rig& rig) {
  const int n = static_cast<int>(rig.bones.size());
  // Children lists in one array (counting sort by parent), then a breadth-first walk from the roots.
  std::vector<int> first(n + 2, 0), children(n);
  for (const Bone& b : rig.bones) ++first[b.parent + 2];
  for (int p = 0; p <= n; ++p) first[p + 1] += first[p];  // first[p + 1]: start of parent p's children
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (int i = 0; i < n; ++i) children[fill[rig.bones[i].parent + 1]++] = i;
  std::vector<int> order;
  order.reserve(n);
  for (int c = first[0]; c < first[1]; ++c) order.push_back(children[c]);  // the roots
  for (size_t at = 0; at < order.size(); ++at)
    for (int c = first[order[at] + 1]; c < first[order[at] + 2]; ++c) order.push_back(children[c]);
  if (static_cast<int>(order.size()) < n) {
    std::vector<char> seen(n, 0);
    for (int i : order) seen[i] = 1;
    for (int i = 0; i < n; ++i)
      if (!seen[i]) fail(rig, i, "parent chain has a cycle");
  }
  return order;
}

}  // namespace ik

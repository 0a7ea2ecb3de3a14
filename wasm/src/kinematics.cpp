#include "kinematics.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ik {

namespace {

Eigen::Matrix3d rot_x(double c, double s) {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, c, -s, 0, s, c;
  return m;
}

Eigen::Matrix3d rot_z(double c, double s) {
  Eigen::Matrix3d m;
  m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

}  // namespace

Kinematics::Kinematics(Rig rig) : rig_(std::move(rig)) {
  validate_rig(rig_);
  precompute();
}

void Kinematics::set_effectors(const std::vector<int>& effectors) {
  for (size_t k = 0; k < effectors.size(); ++k) {
    const int e = effectors[k];
    if (e < 0 || e >= num_bones())
      throw RigError("end effector " + std::to_string(k) + " is bone " + std::to_string(e) +
                     ", which is not a bone of the rig (0.." + std::to_string(num_bones() - 1) + ")");
    for (size_t j = 0; j < k; ++j)
      if (effectors[j] == e) throw RigError(bone_label(rig_, e) + ": is listed twice as an end effector");
  }
  if (effectors.empty()) throw RigError("rig has no end effectors");
  rig_.effectors = effectors;
}

void Kinematics::precompute() {
  const int n = num_bones();
  rest_.resize(n);
  rest_inv_.resize(n);
  from_parent_.resize(n);
  frame_.assign(n, Eigen::Isometry3d::Identity());
  axes_.assign(n, Eigen::Matrix3d::Identity());
  lower_.resize(3 * n);
  upper_.resize(3 * n);
  chains_.assign(n, {});
  for (int i = 0; i < n; ++i) {
    const Bone& b = rig_.bones[i];
    rest_[i].matrix() = b.rest;
    rest_[i].makeAffine();
    rest_inv_[i] = rest_[i].inverse(Eigen::Isometry);
    lower_.segment<3>(3 * i) = b.min_deg;
    upper_.segment<3>(3 * i) = b.max_deg;
  }
  for (int i = 0; i < n; ++i) {
    const int p = rig_.bones[i].parent;
    from_parent_[i] = (p == -1) ? rest_[i] : rest_inv_[p] * rest_[i];
    for (int at = i; at != -1; at = rig_.bones[at].parent) chains_[i].insert(chains_[i].begin(), at);
  }
  // Parents before children: sort by depth (chain length), stable in index.
  order_.resize(n);
  for (int i = 0; i < n; ++i) order_[i] = i;
  std::stable_sort(order_.begin(), order_.end(),
                   [&](int a, int b) { return chains_[a].size() < chains_[b].size(); });
}

void Kinematics::forward(const Eigen::Ref<const Eigen::VectorXd>& angles) {
  for (int i : order_) {
    const int p = rig_.bones[i].parent;
    // Joint frame before rotation: F = T_parent * rest_i, with T_parent = frame_p * rest_p^-1.
    const Eigen::Isometry3d joint = (p == -1) ? from_parent_[i] : frame_[p] * from_parent_[i];
    const double a0 = angles[3 * i] * kRadPerDeg;
    const double a1 = angles[3 * i + 1] * kRadPerDeg;
    const double a2 = angles[3 * i + 2] * kRadPerDeg;
    const Eigen::Matrix3d r0 = joint.linear() * rot_x(std::cos(a0), std::sin(a0));
    const Eigen::Matrix3d r01 = r0 * rot_z(std::cos(a1), std::sin(a1));
    axes_[i].col(0) = joint.linear().col(0);
    axes_[i].col(1) = r0.col(2);
    axes_[i].col(2) = r01.col(0);
    frame_[i].linear() = r01 * rot_x(std::cos(a2), std::sin(a2));
    frame_[i].translation() = joint.translation();
  }
}

void Kinematics::current_tips(Eigen::Ref<Eigen::VectorXd> tips) const {
  for (int k = 0; k < num_effectors(); ++k) tips.segment<3>(3 * k) = tip(rig_.effectors[k]);
}

void Kinematics::current_jacobian(Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  for (int k = 0; k < num_effectors(); ++k) {
    const Eigen::Vector3d p = tip(rig_.effectors[k]);
    for (int j : chains_[rig_.effectors[k]]) {
      const Eigen::Vector3d r = p - frame_[j].translation();
      for (int a = 0; a < 3; ++a)
        jac.block<3, 1>(3 * k, 3 * j + a) = kRadPerDeg * axes_[j].col(a).cross(r);
    }
  }
}

void Kinematics::tips(const Eigen::Ref<const Eigen::VectorXd>& angles, Eigen::Ref<Eigen::VectorXd> tips) {
  forward(angles);
  current_tips(tips);
}

void Kinematics::jacobian(const Eigen::Ref<const Eigen::VectorXd>& angles, Eigen::Ref<Eigen::VectorXd> tips,
                          Eigen::Ref<Eigen::MatrixXd> jac) {
  forward(angles);
  current_tips(tips);
  current_jacobian(jac);
}

void Kinematics::project(Eigen::Ref<Eigen::VectorXd> angles) const {
  angles = angles.cwiseMax(lower_).cwiseMin(upper_);
}

}  // namespace ik

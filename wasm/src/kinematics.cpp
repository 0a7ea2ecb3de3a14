#include "kinematics.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace ik {

namespace {

// m <- m * R, where R rotates by `angle_rad` in the plane of axes (i, j): Rx is (1, 2), Rz is (0, 1).
// Touches only the two columns that change.
inline void rotate_columns(Eigen::Matrix3d& m, int i, int j, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  const Eigen::Vector3d a = m.col(i), b = m.col(j);
  m.col(i) = c * a + s * b;
  m.col(j) = c * b - s * a;
}

}  // namespace

Kinematics::Kinematics(Rig rig) : rig_(std::move(rig)) {
  validate_rig(rig_);
  precompute();
}

void Kinematics::set_effectors(const std::vector<int>& effectors) {
  validate_effectors(rig_, effectors);
  rig_.effectors = effectors;
  precompute_chains();
}

void Kinematics::precompute() {
  const int n = num_bones();
  rest_.resize(n);
  rest_inv_.resize(n);
  from_parent_.resize(n);
  frame_.assign(n, Eigen::Isometry3d::Identity());
  posed_.resize(num_angles());
  posed_valid_ = false;
  axes_.assign(n, Eigen::Matrix3d::Identity());
  lower_.resize(num_angles());
  upper_.resize(num_angles());
  if (floats()) {
    lower_.tail<3>() = rig_.floating_root.min;
    upper_.tail<3>() = rig_.floating_root.max;
  }
  for (int i = 0; i < n; ++i) {
    const Bone& b = rig_.bones[i];
    rest_[i].matrix() = b.rest;
    rest_[i].makeAffine();
    rest_inv_[i] = rest_[i].inverse(Eigen::Isometry);
    lower_.segment<3>(3 * i) = b.min_deg;
    upper_.segment<3>(3 * i) = b.max_deg;
  }
  zero_locked_.assign(n, 0);
  movable_.assign(n, 0);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const double lo = lower_[3 * i + k], hi = upper_[3 * i + k];
      if (lo == 0 && hi == 0) zero_locked_[i] |= 1 << k;
      if (lo < hi) movable_[i] |= 1 << k;
    }
  for (int i = 0; i < n; ++i) {
    const int p = rig_.bones[i].parent;
    from_parent_[i] = (p == -1) ? rest_[i] : rest_inv_[p] * rest_[i];
  }
  order_ = parents_first(rig_);
  precompute_chains();
}

void Kinematics::precompute_chains() {
  chains_.assign(num_effectors(), {});
  for (int k = 0; k < num_effectors(); ++k) {
    std::vector<int>& chain = chains_[k];
    for (int at = rig_.effectors[k]; at != -1; at = rig_.bones[at].parent) chain.push_back(at);
    std::reverse(chain.begin(), chain.end());
  }
}

void Kinematics::forward(const Eigen::Ref<const Eigen::VectorXd>& angles) {
  const std::size_t bytes = sizeof(double) * static_cast<std::size_t>(posed_.size());
  if (posed_valid_ && angles.size() == posed_.size() && std::memcmp(angles.data(), posed_.data(), bytes) == 0) return;
  for (int i : order_) {
    const int p = rig_.bones[i].parent;
    // Joint frame before rotation: F = T_parent * rest_i, with T_parent = frame_p * rest_p^-1.
    Eigen::Isometry3d joint = (p == -1) ? from_parent_[i] : frame_[p] * from_parent_[i];
    if (p == -1 && floats()) joint.translation() += angles.segment<3>(3 * num_bones());
    Eigen::Matrix3d r = joint.linear();
    // An angle locked at 0 whose value is +-0 turns nothing: its rotation is skipped (NaN and
    // any other value still rotate).
    const int locked = zero_locked_[i];
    const double a0 = angles[3 * i], a1 = angles[3 * i + 1], a2 = angles[3 * i + 2];
    axes_[i].col(0) = r.col(0);  // first x axis, before any rotation
    if (!(locked & 1) || a0 != 0) rotate_columns(r, 1, 2, a0 * kRadPerDeg);
    axes_[i].col(1) = r.col(2);  // z axis after Rx(a0)
    if (!(locked & 2) || a1 != 0) rotate_columns(r, 0, 1, a1 * kRadPerDeg);
    axes_[i].col(2) = r.col(0);  // second x axis after Rx(a0) Rz(a1)
    if (!(locked & 4) || a2 != 0) rotate_columns(r, 1, 2, a2 * kRadPerDeg);
    frame_[i].linear() = r;
    frame_[i].translation() = joint.translation();
  }
  posed_valid_ = angles.size() == posed_.size();
  if (posed_valid_) posed_ = angles;
}

void Kinematics::current_tips(Eigen::Ref<Eigen::VectorXd> tips) const {
  for (int k = 0; k < num_effectors(); ++k) tips.segment<3>(3 * k) = tip(rig_.effectors[k]);
}

void Kinematics::current_jacobian(Eigen::Ref<Eigen::MatrixXd> jac, Columns columns) const {
  jac.setZero();
  for (int k = 0; k < num_effectors(); ++k) {
    const Eigen::Vector3d p = tip(rig_.effectors[k]);
    for (int j : chains_[k]) {
      const Eigen::Vector3d r = p - frame_[j].translation();
      const int filled = columns_of(j, columns);
      for (int a = 0; a < 3; ++a)
        if (filled & (1 << a)) jac.block<3, 1>(3 * k, 3 * j + a) = kRadPerDeg * axes_[j].col(a).cross(r);
    }
    if (floats()) jac.block<3, 3>(3 * k, root_translation()).setIdentity();
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

#include "block_pattern.h"

namespace ik {

namespace {

Eigen::Block<const Eigen::MatrixXd, 3, 1> block(const Eigen::MatrixXd& J, int k, int j) {
  return J.block<3, 1>(3 * k, j);
}

}  // namespace

void BlockPattern::build(const Kinematics& kin, const GoalSet& goals) {
  // Counted per bone, then filled block by block; an angle takes its bone's list.
  blocks_ = goals.rows() / 3;
  std::vector<int> per_bone(kin.num_bones() + 1, 0), moving;
  for (int k = 0; k < blocks_; ++k) {
    goals.moving_bones(kin, k, moving);
    for (int b : moving) ++per_bone[b + 1];
  }
  for (int b = 0; b < kin.num_bones(); ++b) per_bone[b + 1] += per_bone[b];
  std::vector<int> bone_blocks(per_bone.back()), fill(per_bone.begin(), per_bone.end() - 1);
  for (int k = 0; k < blocks_; ++k) {
    goals.moving_bones(kin, k, moving);
    for (int b : moving) bone_blocks[fill[b]++] = k;
  }
  const int n = kin.num_angles();
  root_start_ = 3 * kin.num_bones();
  start_.assign(n + 1, 0);
  blocks_of_.clear();
  for (int j = 0; j < n; ++j) {
    start_[j] = static_cast<int>(blocks_of_.size());
    if (j >= 3 * kin.num_bones()) {  // a floating root's translation moves every block
      for (int k = 0; k < blocks_; ++k) blocks_of_.push_back(k);
      continue;
    }
    blocks_of_.insert(blocks_of_.end(), bone_blocks.begin() + per_bone[j / 3],
                      bone_blocks.begin() + per_bone[j / 3 + 1]);
  }
  start_[n] = static_cast<int>(blocks_of_.size());
}

void BlockPattern::accumulate(const Eigen::MatrixXd& J, int j, Eigen::MatrixXd& normal) const {
  const double w = weight(j);
  for (int p = start_[j]; p < start_[j + 1]; ++p) {
    const int e = blocks_of_[p];
    const Eigen::Vector3d je = w * block(J, e, j);
    for (int q = p; q < start_[j + 1]; ++q) {
      const int f = blocks_of_[q];
      normal.block<3, 3>(3 * e, 3 * f).noalias() += je * block(J, f, j).transpose();
    }
  }
}

void BlockPattern::symmetrize(Eigen::MatrixXd& normal) const {
  for (int e = 0; e < blocks_; ++e)
    for (int f = e + 1; f < blocks_; ++f)
      normal.block<3, 3>(3 * f, 3 * e) = normal.block<3, 3>(3 * e, 3 * f).transpose();
}

void BlockPattern::take_out(const Eigen::MatrixXd& J, int i, double d, Eigen::VectorXd& rhs,
                            Eigen::MatrixXd& reduced) const {
  const double w = weight(i);
  for (int p = start_[i]; p < start_[i + 1]; ++p) {
    const int e = blocks_of_[p];
    rhs.segment<3>(3 * e) += d * block(J, e, i);
    const Eigen::Vector3d je = w * block(J, e, i);
    for (int q = start_[i]; q < start_[i + 1]; ++q) {
      const int f = blocks_of_[q];
      reduced.block<3, 3>(3 * e, 3 * f).noalias() -= je * block(J, f, i).transpose();
    }
  }
}

double BlockPattern::dot(const Eigen::MatrixXd& J, int i, const Eigen::VectorXd& y) const {
  double sum = 0;
  for (int p = start_[i]; p < start_[i + 1]; ++p)
    sum += block(J, blocks_of_[p], i).dot(y.segment<3>(3 * blocks_of_[p]));
  return sum;
}

void BlockPattern::add(const Eigen::MatrixXd& J, int i, double d, Eigen::VectorXd& out) const {
  for (int p = start_[i]; p < start_[i + 1]; ++p) out.segment<3>(3 * blocks_of_[p]) += d * block(J, blocks_of_[p], i);
}

}  // namespace ik

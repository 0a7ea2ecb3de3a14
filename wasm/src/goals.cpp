#include "goals.h"

#include <algorithm>
#include <cmath>

namespace ik {

namespace {

bool finite3(const Eigen::Vector3d& v) { return v.allFinite(); }

bool is_rotation(const Eigen::Matrix3d& R) {
  return R.allFinite() && (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
         std::abs(R.determinant() - 1) < 1e-6;
}

bool valid_weight(double w) { return std::isfinite(w) && w >= 0; }

}  // namespace

double rig_reach(const Kinematics& kin) {
  double reach = 0;
  for (int e = 0; e < kin.num_effectors(); ++e) {
    double length = 0;
    for (int b : kin.effector_chain(e)) length += kin.rig().bones[b].length;
    reach = std::max(reach, length);
  }
  return reach > 0 ? reach : 1;
}

void GoalSet::add(const Block& block) {
  if (!block.orientation) position_block_[block.effector] = num_blocks();
  has_orientation_ = has_orientation_ || block.orientation;
  layout_.push_back(2 * block.effector + (block.orientation ? 1 : 0));
  blocks_.push_back(block);
}

void GoalSet::set_positions(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& target) {
  plain_ = true;
  has_orientation_ = false;
  target_ = target;
  blocks_.clear();
  layout_.clear();
  position_block_.assign(kin.num_effectors(), -1);
  if (target.size() != kin.num_residuals()) return;  // check_solve_input reports it
  for (int e = 0; e < kin.num_effectors(); ++e) {
    Block b;
    b.effector = e;
    b.position = target.segment<3>(3 * e);
    add(b);
  }
}

std::string GoalSet::set(const Kinematics& kin, const Goals& goals) {
  const int m = kin.num_effectors();
  plain_ = true;
  has_orientation_ = false;
  blocks_.clear();
  layout_.clear();
  position_block_.assign(m, -1);
  target_.resize(0);
  if (static_cast<int>(goals.effectors.size()) != m)
    return "goals has " + std::to_string(goals.effectors.size()) + " entries, expected " + std::to_string(m) +
           " (one per end effector)";
  if (!std::isfinite(goals.length_scale) || goals.length_scale < 0)
    return "the goals' length scale must be a finite number >= 0";
  const double length = goals.length_scale > 0 ? goals.length_scale : rig_reach(kin);
  for (int e = 0; e < m; ++e) {
    const EffectorGoal& g = goals.effectors[e];
    // The message's subject, built only when there is a problem (a start allocates nothing).
    const auto which = [e](const char* what) {
      return std::string("the ") + what + " of the goal of end effector " + std::to_string(e);
    };
    if (g.position && !valid_weight(g.position_weight))
      return which("position weight") + " must be a finite number >= 0";
    if (g.position && !finite3(g.position_target)) return which("position target") + " is not finite";
    if (g.orientation && !valid_weight(g.orientation_weight))
      return which("orientation weight") + " must be a finite number >= 0";
    if (g.orientation && !is_rotation(g.orientation_target)) return which("orientation target") + " is not a rotation";
    if (g.position && g.position_weight > 0) {
      Block b;
      b.effector = e;
      b.scale = g.position_weight;
      b.position = g.position_target;
      add(b);
    }
    if (g.orientation && g.orientation_weight > 0) {
      Block b;
      b.effector = e;
      b.orientation = true;
      b.scale = g.orientation_weight * length;
      b.rotation = g.orientation_target;
      add(b);
    }
    plain_ = plain_ && g.position && g.position_weight == 1;
  }
  if (blocks_.empty()) return "no goal: every end effector's goals are off or of weight 0";
  plain_ = plain_ && !has_orientation_;
  if (plain_) {
    target_.resize(3 * m);
    for (int e = 0; e < m; ++e) target_.segment<3>(3 * e) = goals.effectors[e].position_target;
  }
  return {};
}

bool GoalSet::operator==(const GoalSet& other) const {
  if (plain_ != other.plain_ || layout_ != other.layout_) return false;
  if (plain_) return target_.size() == other.target_.size() && target_ == other.target_;
  for (int b = 0; b < num_blocks(); ++b) {
    const Block &x = blocks_[b], &y = other.blocks_[b];
    if (x.scale != y.scale || x.position != y.position || x.rotation != y.rotation) return false;
  }
  return true;
}

}  // namespace ik

#include "goals.h"

#include <algorithm>
#include <cmath>

#include "size_limits.h"

namespace ik {

namespace {

static_assert(kMaxCoordinate == 1e9 && kMaxSoftWeight == 1000, "the messages below say 1e9 and 1000");

// What is wrong with a point (rig units), or nullptr: every coordinate finite, within +-kMaxCoordinate.
const char* point_problem(const Eigen::Vector3d& v) {
  if (!v.allFinite()) return " is not finite";
  if (v.cwiseAbs().maxCoeff() > kMaxCoordinate)
    return " has a coordinate past +-1e9 rig units (the largest coordinate the core takes)";
  return nullptr;
}

bool is_rotation(const Eigen::Matrix3d& R) {
  return R.allFinite() && (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
         std::abs(R.determinant() - 1) < 1e-6;
}

bool valid_weight(double w) { return std::isfinite(w) && w >= 0; }
bool valid_soft_weight(double w) { return w >= 0 && w <= kMaxSoftWeight; }
const char* const kSoftWeightRule = " must be a number in 0..1000 (a soft pull's largest weight)";

// The largest weight of `goals`' position and orientation goals (0 if none is on): the goals'
// weights are relative, each block's weight is divided by it.
double largest_goal_weight(const Goals& goals) {
  double largest = 0;
  for (const EffectorGoal& g : goals.effectors) {
    if (g.position) largest = std::max(largest, g.position_weight);
    if (g.orientation) largest = std::max(largest, g.orientation_weight);
  }
  return largest;
}

// Layout codes of the soft blocks (hard blocks use 2 e + kind >= 0).
int pole_code(int bone) { return -1 - 2 * bone; }
int rest_code(int bone) { return -2 - 2 * bone; }

// The share of the shorter of a limb's two segments below which a bend counts as "straight"
// (pole_residual.h's delta): 5% bends a 2 x 1 limb about 6 degrees at the knee.
constexpr double kBendFloorShare = 0.05;

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

void GoalSet::mark_chain(const Kinematics& kin, int bone) {
  for (int b = bone; b >= 0; b = kin.rig().bones[b].parent) on_chain_[b] = 1;
}

void GoalSet::set_positions(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& target) {
  plain_ = true;
  has_orientation_ = false;
  has_yielding_ = false;
  soft_scale_ = 1;
  length_ = rig_reach(kin);
  target_ = target;
  blocks_.clear();
  layout_.clear();
  poles_.clear();
  stiffness_.clear();
  rest_bones_.clear();
  rest_scale_.clear();
  on_chain_.assign(kin.num_bones(), 0);
  position_block_.assign(kin.num_effectors(), -1);
  if (target.size() != kin.num_residuals()) return;  // check_solve_input reports it
  for (int e = 0; e < kin.num_effectors(); ++e) {
    Block b;
    b.effector = e;
    b.position = target.segment<3>(3 * e);
    add(b);
    mark_chain(kin, kin.rig().effectors[e]);
  }
}

void GoalSet::set_rest(const Kinematics& kin, double weight, bool from_start,
                       const Eigen::Ref<const Eigen::VectorXd>& start) {
  rest_bones_.clear();
  rest_scale_.clear();
  layout_.resize(blocks_.size() + poles_.size());
  const int n = kin.num_angles();
  if (!(std::isfinite(weight) && weight > 0) || start.size() != n ||
      static_cast<int>(on_chain_.size()) != kin.num_bones())
    return;
  for (int b = 0; b < kin.num_bones(); ++b) {
    const double stiffness = stiffness_.empty() ? 1.0 : stiffness_[b];
    if (!on_chain_[b] || !(stiffness > 0)) continue;
    rest_bones_.push_back(b);
    rest_scale_.push_back(weight * stiffness * length_);
    layout_.push_back(rest_code(b));
  }
  if (from_start) {
    rest_reference_ = start;
    kin.project(rest_reference_);
  } else {
    rest_reference_.setZero(n);
  }
}

void GoalSet::moving_bones(const Kinematics& kin, int k, std::vector<int>& bones) const {
  bones.clear();
  if (k < num_blocks()) {
    bones = kin.effector_chain(blocks_[k].effector);
    return;
  }
  k -= num_blocks();
  if (k < num_poles()) {
    for (int b = poles_[k].bone; b >= 0; b = kin.rig().bones[b].parent) bones.insert(bones.begin(), b);
    return;
  }
  bones.push_back(rest_bones_[k - num_poles()]);
}

std::string GoalSet::set(const Kinematics& kin, const Goals& goals) {
  const int m = kin.num_effectors();
  clear(kin);
  // target_ keeps its size (read only when plain_): a second start allocates nothing.
  if (static_cast<int>(goals.effectors.size()) != m)
    return "goals has " + std::to_string(goals.effectors.size()) + " entries, expected " + std::to_string(m) +
           " (one per end effector)";
  if (!(goals.length_scale >= 0 && goals.length_scale <= kMaxCoordinate))
    return "the goals' length scale must be a number in 0..1e9 (rig units per radian; 0: the rig's reach)";
  length_ = goals.length_scale > 0 ? goals.length_scale : rig_reach(kin);
  std::string problem = effector_goal_problem(goals);
  if (!problem.empty()) return problem;
  add_effector_blocks(kin, goals);
  if (blocks_.empty()) return "no goal: every end effector's goals are off or of weight 0";
  int yielding = 0;
  for (const Block& b : blocks_) yielding += b.yields;
  has_yielding_ = yielding > 0 && yielding < num_blocks();
  problem = add_poles(kin, goals);
  if (!problem.empty()) return problem;
  problem = set_stiffness(kin, goals);
  if (!problem.empty()) return problem;
  plain_ = plain_ && !has_orientation_;
  if (plain_) {
    target_.resize(3 * m);
    for (int e = 0; e < m; ++e) target_.segment<3>(3 * e) = goals.effectors[e].position_target;
  }
  return {};
}

void GoalSet::clear(const Kinematics& kin) {
  plain_ = true;
  has_orientation_ = false;
  has_yielding_ = false;
  soft_scale_ = 1;
  blocks_.clear();
  layout_.clear();
  poles_.clear();
  stiffness_.clear();
  rest_bones_.clear();
  rest_scale_.clear();
  on_chain_.assign(kin.num_bones(), 0);
  position_block_.assign(kin.num_effectors(), -1);
}

std::string GoalSet::effector_goal_problem(const Goals& goals) const {
  for (size_t e = 0; e < goals.effectors.size(); ++e) {
    const EffectorGoal& g = goals.effectors[e];
    // The message's subject, built only when there is a problem (a start allocates nothing).
    const auto which = [e](const char* what) {
      return std::string("the ") + what + " of the goal of end effector " + std::to_string(e);
    };
    if (g.position && !valid_weight(g.position_weight))
      return which("position weight") + " must be a finite number >= 0";
    if (g.position && point_problem(g.position_target))
      return which("position target") + point_problem(g.position_target);
    if (g.orientation && !valid_weight(g.orientation_weight))
      return which("orientation weight") + " must be a finite number >= 0";
    if (g.orientation && !is_rotation(g.orientation_target)) return which("orientation target") + " is not a rotation";
  }
  return {};
}

void GoalSet::add_effector_blocks(const Kinematics& kin, const Goals& goals) {
  // Relative weights: the largest becomes 1, so that neither huge nor tiny weights (all alike)
  // move the E test's scale or the steps' conditioning.
  const double largest = largest_goal_weight(goals);
  for (int e = 0; e < static_cast<int>(goals.effectors.size()) && largest > 0; ++e) {
    const EffectorGoal& g = goals.effectors[e];
    const double position_weight = g.position_weight / largest, orientation_weight = g.orientation_weight / largest;
    if (g.position && position_weight > 0) {
      Block b;
      b.effector = e;
      b.scale = position_weight;
      b.position = g.position_target;
      b.yields = g.yields;
      add(b);
    }
    if (g.orientation && orientation_weight > 0) {
      Block b;
      b.effector = e;
      b.orientation = true;
      b.scale = orientation_weight * length_;
      b.rotation = g.orientation_target;
      b.yields = g.yields;
      add(b);
    }
    plain_ = plain_ && g.position && position_weight == 1 && !g.yields;
    if (!blocks_.empty() && blocks_.back().effector == e) mark_chain(kin, kin.rig().effectors[e]);
  }
}

std::string GoalSet::add_poles(const Kinematics& kin, const Goals& goals) {
  const int bones = kin.num_bones();
  if (goals.poles.size() > static_cast<size_t>(kMaxPoles))
    return "goals has " + std::to_string(goals.poles.size()) + " poles, more than " + std::to_string(kMaxPoles) +
           " (one per two-bone limb is what a body needs)";
  for (size_t i = 0; i < goals.poles.size(); ++i) {
    const PoleGoal& p = goals.poles[i];
    const auto which = [i](const char* what) { return std::string("the ") + what + " of pole " + std::to_string(i); };
    if (p.bone < 0 || p.bone >= bones)
      return which("bone") + " is " + std::to_string(p.bone) + ", not a bone index in 0.." + std::to_string(bones - 1);
    const int parent = kin.rig().bones[p.bone].parent;
    if (parent < 0)
      return which("bone") + " (" + std::to_string(p.bone) +
             ") has no parent: a bend hint needs the second bone of a two-bone limb";
    if (point_problem(p.point)) return which("point") + point_problem(p.point);
    if (!valid_soft_weight(p.weight)) return which("weight") + kSoftWeightRule;
    if (p.weight == 0) continue;
    Pole pole;
    pole.bone = p.bone;
    pole.parent = parent;
    pole.point = p.point;
    pole.scale = p.weight * length_;
    // |M - S| and |T - M| at rest: the rest heads' distance and the bone's length.
    const double upper =
        (kin.rig().bones[p.bone].rest.block<3, 1>(0, 3) - kin.rig().bones[parent].rest.block<3, 1>(0, 3)).norm();
    const double shorter = std::min(upper, kin.rig().bones[p.bone].length);
    pole.bend_floor = kBendFloorShare * (shorter > 0 ? shorter : length_);
    poles_.push_back(pole);
    layout_.push_back(pole_code(p.bone));
    mark_chain(kin, p.bone);
  }
  return {};
}

std::string GoalSet::set_stiffness(const Kinematics& kin, const Goals& goals) {
  const int bones = kin.num_bones();
  if (!goals.stiffness.empty() && static_cast<int>(goals.stiffness.size()) != bones)
    return "goals has " + std::to_string(goals.stiffness.size()) + " stiffness values, expected " +
           std::to_string(bones) + " (one per bone) or none";
  for (int b = 0; b < static_cast<int>(goals.stiffness.size()); ++b)
    if (!valid_soft_weight(goals.stiffness[b])) return "the stiffness of " + bone_label(kin.rig(), b) + kSoftWeightRule;
  stiffness_ = goals.stiffness;
  return {};
}

bool GoalSet::operator==(const GoalSet& other) const {
  if (plain_ != other.plain_ || layout_ != other.layout_) return false;
  for (int p = 0; p < num_poles(); ++p)
    if (poles_[p].point != other.poles_[p].point || poles_[p].scale != other.poles_[p].scale) return false;
  if (rest_scale_ != other.rest_scale_) return false;
  if (!rest_bones_.empty() && rest_reference_ != other.rest_reference_) return false;
  if (plain_) return target_.size() == other.target_.size() && target_ == other.target_;
  for (int b = 0; b < num_blocks(); ++b) {
    const Block &x = blocks_[b], &y = other.blocks_[b];
    if (x.scale != y.scale || x.position != y.position || x.rotation != y.rotation || x.yields != y.yields)
      return false;
  }
  return true;
}

double GoalSet::largest_change_from(const GoalSet& before) const {
  if (before.layout_ != layout_) return -1;
  double largest = 0;
  for (int b = 0; b < num_blocks(); ++b) {
    const Block& now = blocks_[b];
    const Block& then = before.blocks_[b];
    const double change = now.orientation ? Eigen::AngleAxisd(then.rotation.transpose() * now.rotation).angle()
                                          : (now.position - then.position).norm();
    largest = std::max(largest, now.scale * change);
  }
  return largest;
}

}  // namespace ik

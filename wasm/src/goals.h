// What each end effector should reach: a position, an orientation, or both, each with a weight.
//
// The residual has, per effector in the rig's effector order, 3 position rows if it has a
// position goal, then 3 orientation rows if it has an orientation goal (a goal of weight 0
// counts as no goal and has no rows):
//   position rows     w_p (x - x_b)                               rig units
//   orientation rows  w_o L log(R_target^T R_tip)                 rig units (L in rig units per radian)
// R_tip is Kinematics::tip_rotation() of the effector's bone, log the rotation vector (so3.h) and
// L the length scale (Goals::length_scale; default the rig's reach: the longest sum of bone
// lengths from a root to an effector), so E = 1/2 |r|^2 stays in rig units^2.
// Position goals of weight 1 and nothing else are "plain": exactly today's x(A) - x_b, which
// every method (and paper mode, which takes nothing else) evaluates by the original code path.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "kinematics.h"

namespace ik {

struct EffectorGoal {
  bool position = true;
  Eigen::Vector3d position_target = Eigen::Vector3d::Zero();  // x_b, rig units
  double position_weight = 1;                                  // w_p >= 0
  bool orientation = false;
  Eigen::Matrix3d orientation_target = Eigen::Matrix3d::Identity();  // R_target, a rotation (world)
  double orientation_weight = 1;                                      // w_o >= 0
};

struct Goals {
  std::vector<EffectorGoal> effectors;  // one per end effector, in the rig's effector order
  double length_scale = 0;              // L, rig units per radian; 0: the rig's reach
};

// The longest sum of bone lengths from a root to an end effector (rig units; 1 if that is 0).
double rig_reach(const Kinematics& kin);

// Goals compiled into residual blocks of 3 rows each, in row order.
class GoalSet {
 public:
  struct Block {
    int effector = 0;          // index into the effector list
    bool orientation = false;  // false: a position block
    double scale = 1;          // w_p, or w_o * L for an orientation block
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  };

  // Plain position goals of weight 1 at `target` (3 per effector, rig units), taken as given:
  // sizes and values are checked by check_solve_input, before the goals are used.
  void set_positions(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& target);
  // Compiles `goals` for `kin`; returns an empty string, or what is wrong (the set is then unusable).
  std::string set(const Kinematics& kin, const Goals& goals);

  bool plain() const { return plain_; }
  // The 3 x #effectors target of plain goals (as given to set_positions()).
  const Eigen::VectorXd& plain_target() const { return target_; }
  int rows() const { return 3 * static_cast<int>(blocks_.size()); }
  int num_blocks() const { return static_cast<int>(blocks_.size()); }
  const Block& block(int b) const { return blocks_[b]; }
  bool has_orientation() const { return has_orientation_; }
  // Effector e's position block, or -1.
  int position_block(int e) const { return position_block_[e]; }
  // The blocks' (effector, kind) in order: equal layouts give equal residual structure.
  const std::vector<int>& layout() const { return layout_; }

  bool operator==(const GoalSet& other) const;

 private:
  void add(const Block& block);
  bool plain_ = true;
  bool has_orientation_ = false;
  Eigen::VectorXd target_;
  std::vector<Block> blocks_;
  std::vector<int> position_block_;
  std::vector<int> layout_;
};

}  // namespace ik

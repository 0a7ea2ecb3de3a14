// What each end effector should reach: a position, an orientation, or both, each with a weight.
//
// The residual has, per effector in the rig's effector order, 3 position rows if it has a
// position goal, then 3 orientation rows if it has an orientation goal (a goal of weight 0
// counts as no goal and has no rows):
//   position rows     w_p (x - x_b)                               rig units
//   orientation rows  w_o L log(R_target^T R_tip)                 rig units (L in rig units per radian)
// with w_p and w_o the weights divided by the largest weight of any goal (they are relative),
// R_tip is Kinematics::tip_rotation() of the effector's bone, log the rotation vector (so3.h) and
// L the length scale (Goals::length_scale; default the rig's reach: the longest sum of bone
// lengths from a root to an effector), so E = 1/2 |r|^2 stays in rig units^2.
// After those "hard" rows come the "soft" ones, which never decide "on target" (Solver::on_target):
//   pole rows         3 per bend hint (PoleGoal; pole_residual.h)     rig units
//   rest rows         3 per bone with a rest pull (rest_residual.h)   rig units
// The rest rows exist only while the solver's rest_weight is > 0 (set_rest(), called by
// Solver::start()), for the bones on the chain of a goal or a pole whose stiffness is > 0.
// Position goals of weight 1 and nothing else (no pole, no rest pull) are "plain": exactly
// today's x(A) - x_b, which every method (and paper mode, which takes nothing else) evaluates by
// the original code path.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "kinematics.h"

namespace ik {

struct EffectorGoal {
  bool position = true;
  Eigen::Vector3d position_target = Eigen::Vector3d::Zero();  // x_b, rig units
  double position_weight = 1;                                 // w_p >= 0, relative (see Goals)
  bool orientation = false;
  Eigen::Matrix3d orientation_target = Eigen::Matrix3d::Identity();  // R_target, a rotation (world)
  double orientation_weight = 1;                                     // w_o >= 0, relative (see Goals)
  // Strict priority (solver option strict_priority): this effector's goals give way first when
  // not every goal can be met (the one a user drags, while the others stay pinned). The solve
  // holds the other goals from its start and brings these as close as their freedom allows.
  bool yields = false;
};

// A bend hint (pole target) for the two-bone limb ending in `bone` (forearm, shin): S = head of
// its parent (shoulder), M = head of `bone` (elbow), T = tip of `bone` (wrist). It asks that M
// lie on the side of the S-T axis where `point` lies (the knee points at it); a soft term,
// zero when it does (pole_residual.h).
struct PoleGoal {
  int bone = 0;                                     // a bone with a parent
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // the pole, rig units (world)
  double weight = 1;                                // 0..kMaxSoftWeight; 0: no pole
};

// Limits (size_limits.h, checked by GoalSet::set()): points within +-kMaxCoordinate, the length
// scale at most kMaxCoordinate, pole weights and stiffness at most kMaxSoftWeight. The goals'
// weights are relative: each is divided by the largest, so that the same weight on every goal,
// however large or small, is the plain objective, and E's scale (the E test) stays that of the
// distances. The soft weights count against a goal of weight 1.
struct Goals {
  std::vector<EffectorGoal> effectors;  // one per end effector, in the rig's effector order
  double length_scale = 0;              // L, rig units per radian; 0: the rig's reach
  std::vector<PoleGoal> poles;          // bend hints, soft
  // Per bone, the factor of its rest rows (0..kMaxSoftWeight; 0: the bone feels no rest pull). Empty:
  // all 1. Read only with the solver option rest_weight > 0.
  std::vector<double> stiffness;
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
    bool yields = false;       // EffectorGoal::yields
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  };

  // A bend hint compiled: rows w L (q_hat - bend direction), pole_residual.h.
  struct Pole {
    int bone = 0, parent = 0;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double scale = 1;       // w L, rig units
    double bend_floor = 1;  // delta of pole_residual.h, rig units
  };

  // Plain position goals of weight 1 at `target` (3 per effector, rig units), taken as given:
  // sizes and values are checked by check_solve_input, before the goals are used.
  void set_positions(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& target);
  // Compiles `goals` for `kin`; returns an empty string, or what is wrong (the set is then unusable).
  std::string set(const Kinematics& kin, const Goals& goals);

  // Sets the rest rows: `weight` (the option rest_weight, >= 0; 0 or not finite: none) pulls
  // each angle of the bones on a goal's or a pole's chain towards 0 degrees, or with
  // `from_start` towards `start` (#angles, degrees, projected into the limits). Rows per angle j
  // of bone b: weight * stiffness_b * L * (pi / 180) * (a_j - ref_j), rig units. A `start` of the
  // wrong size gives no rows (the solver reports it). No allocation once sized.
  void set_rest(const Kinematics& kin, double weight, bool from_start, const Eigen::Ref<const Eigen::VectorXd>& start);

  // Plain position goals of weight 1 and no soft rows: the original objective.
  bool plain() const { return plain_ && !has_soft(); }
  // Position goals of weight 1 only (soft rows aside): plain_target() holds their target.
  bool plain_positions() const { return plain_; }
  // The 3 x #effectors target of plain goals (as given to set_positions()).
  const Eigen::VectorXd& plain_target() const { return target_; }
  // All rows: hard blocks, then 3 per pole, then 3 per rest bone.
  int rows() const { return 3 * (num_blocks() + num_poles() + num_rest()); }
  // The hard rows (positions and orientations): the first ones.
  int hard_rows() const { return 3 * num_blocks(); }
  int num_blocks() const { return static_cast<int>(blocks_.size()); }
  const Block& block(int b) const { return blocks_[b]; }
  // Sets block b's scale (w_p, or w_o * L): the solver's reweighting within one solve.
  void set_block_scale(int b, double scale) { blocks_[b].scale = scale; }
  bool has_orientation() const { return has_orientation_; }
  // Does some block yield (EffectorGoal::yields) while another does not?
  bool has_yielding() const { return has_yielding_; }
  int num_poles() const { return static_cast<int>(poles_.size()); }
  const Pole& pole(int p) const { return poles_[p]; }
  // Rest rows 3i..3i+2 after the poles' rows belong to bone rest_bone(i), scaled by rest_scale(i)
  // = weight * stiffness * L (rig units per radian).
  int num_rest() const { return static_cast<int>(rest_bones_.size()); }
  int rest_bone(int i) const { return rest_bones_[i]; }
  double rest_scale(int i) const { return rest_scale_[i]; }
  const Eigen::VectorXd& rest_reference() const { return rest_reference_; }  // #angles, degrees
  // Are there pole or rest rows, and are they on (not dropped by the solver)?
  bool has_soft() const { return !poles_.empty() || !rest_bones_.empty(); }
  bool soft_on() const { return soft_scale_ > 0 && has_soft(); }
  // The factor of every soft row (1 after set(); the solver lowers it, then sets 0 to drop them).
  // At 0 the soft rows read 0 (residual and Jacobian); the layout stays.
  double soft_scale() const { return soft_scale_; }
  void set_soft_scale(double scale) { soft_scale_ = scale; }
  // The bones whose angles move the rows of 3-row block k (hard blocks, then poles, then rest
  // bones), parents first; written to `bones` (allocates: for set-up only).
  void moving_bones(const Kinematics& kin, int k, std::vector<int>& bones) const;
  // How far the targets moved from `before` to this set: the largest over the blocks of a
  // position's scale times its move (rig units), an orientation's scale times the angle between
  // its rotations (radians); -1 when the layouts differ. No allocation.
  double largest_change_from(const GoalSet& before) const;
  // Effector e's position block, or -1.
  int position_block(int e) const { return position_block_[e]; }
  // The blocks' (effector, kind) in order: equal layouts give equal residual structure.
  const std::vector<int>& layout() const { return layout_; }

  bool operator==(const GoalSet& other) const;

 private:
  // The steps of set(). clear(): no goal, sized for `kin`. effector_goal_problem(): what is wrong
  // with an effector's goal, or "". add_effector_blocks(): the blocks of the goals on, weights
  // relative to the largest (length_ set before). add_poles(), set_stiffness(): check and take
  // them, or say what is wrong.
  void clear(const Kinematics& kin);
  std::string effector_goal_problem(const Goals& goals) const;
  void add_effector_blocks(const Kinematics& kin, const Goals& goals);
  std::string add_poles(const Kinematics& kin, const Goals& goals);
  std::string set_stiffness(const Kinematics& kin, const Goals& goals);
  void add(const Block& block);
  void mark_chain(const Kinematics& kin, int bone);
  bool plain_ = true;
  double soft_scale_ = 1;
  double length_ = 1;  // L
  std::vector<Pole> poles_;
  std::vector<double> stiffness_;  // per bone (empty: all 1)
  std::vector<char> on_chain_;     // per bone: on the chain of a goal or a pole
  std::vector<int> rest_bones_;
  std::vector<double> rest_scale_;
  Eigen::VectorXd rest_reference_;
  bool has_orientation_ = false;
  bool has_yielding_ = false;
  Eigen::VectorXd target_;
  std::vector<Block> blocks_;
  std::vector<int> position_block_;
  std::vector<int> layout_;
};

}  // namespace ik

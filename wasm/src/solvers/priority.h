// Strict priority between goals, for a solve that cannot meet them all: a target beyond reach, or
// an orientation that the position leaves no room for. The hard blocks (goals.h) fall into two
// levels:
//   held       the goals that can be met: kept within their tolerance (tip_tolerance, or the
//              orientation tolerance), whatever the others ask;
//   given up   the others, brought as close as the freedom the held ones leave allows.
// The step is the task-priority damped least-squares step at the residual size:
//   (Jf Jf^T + D) y = r,   d = -Jf^T y,
// D = lambda on the given-up rows (and the soft rows), kHeldDamping * lambda + floor on the held
// ones. With D = 0 on the held rows, Jh d = -r_h exactly (Newton on the held goals) and the rest
// of d is the damped least-squares step of the given-up rows within the null space of Jh: a
// lexicographic solve, not a weighted sum (the held rows' damping is only there to keep the
// system positive definite at a singular pose). Bounds: the clip-on-the-limit active set.
//
// Which goals are given up, one at a time until the held ones can be met: at a point where the
// solve stopped with a held goal off target, the block farthest off among, in turn, the
// orientation blocks of effectors off target at the solve's start (in position or orientation),
// the position blocks off target there,
// then the orientation blocks beyond their tolerance here, the position blocks beyond theirs.
// What was on target when the solve began (a pinned hand while another is dragged) is kept
// before what was asked anew, also when the least-squares point met the new goal at the
// others' cost, and an orientation is given up before a position (inside one effector too).
// No allocation after resize().
#pragma once

#include <Eigen/Core>
#include <vector>

#include "active_set.h"
#include "block_pattern.h"
#include "damped_system.h"
#include "deadline.h"
#include "goals.h"
#include "kinematics.h"

namespace ik {

// How far off a goal may be and count as met.
struct GoalTolerance {
  double tip = 0;              // rig units: a position block's distance
  double orientation_deg = 0;  // degrees: an orientation block's angle
};

// Block b's error at residual `r` as a share of its tolerance (<= 1: met).
double block_share(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r, int b, const GoalTolerance& tol);

class Priority {
 public:
  // The held rows' damping as a share of the given-up rows' lambda.
  static constexpr double kHeldDamping = 1e-8;

  // Workspace for the rows of `goals` (hard blocks, then soft rows) and `angles` angles; nothing
  // given up (allocates).
  void resize(const GoalSet& goals, int angles);

  // Nothing given up.
  void clear();
  // Some goal is given up (the solve is in priority mode).
  bool active() const { return given_up_count_ > 0; }
  // Every goal as an equal for a while (active() false), then the same goals given up again.
  void suspend();
  void resume();
  // How many goals (blocks) are given up.
  int count() const { return given_up_count_; }
  // Per hard block: 1 if given up. Same size as the goals' blocks.
  const std::vector<char>& given_up() const { return given_up_; }
  // Gives up the blocks of `goals` that yield (EffectorGoal::yields): an orientation block, or a
  // position block of an effector without one (position first: a yielding effector's position
  // is given up only when it cannot be held, by give_up_next()).
  void give_up_yielding(const GoalSet& goals);

  // Notes which blocks are off target at the solve's start (residual `r` there).
  void note_start(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalTolerance& tol);

  // Gives up a held block of `goals`, in the order above, judged at residual `r`. Returns false
  // when every held block is within its tolerance there, when giving one up would leave no goal
  // held, or when a tolerance is 0 (no goal can be held within it).
  bool give_up_next(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalTolerance& tol);

  // The worst held block's error as a share of its tolerance (<= 1: every held goal met; 0: none held).
  double held_share(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalTolerance& tol) const;
  // 1/2 |r|^2 over the held rows, and over the others (given-up hard rows and soft rows), rig units^2.
  double held_E(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r) const;
  double given_up_E(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r) const;
  // Is a given-up position goal off target at `r`? Is a given-up orientation goal?
  bool position_given_up(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r,
                         const GoalTolerance& tol) const;
  bool orientation_given_up(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r,
                            const GoalTolerance& tol) const;

  // Jf Jf^T over the movable angles of `kin` (lower < upper) with the Jacobian `J` (rows x
  // angles, rig units per degree) of sparsity `pattern`. Returns false if it is not finite.
  bool prepare(const Kinematics& kin, const Eigen::MatrixXd& J, const BlockPattern& pattern);
  // The mean diagonal of Jf Jf^T over the rows in use (after prepare()).
  double scale() const { return scale_; }

  enum class Status { ok, failed, out_of_time };
  // Writes `trial` = P(a + d) for the priority step from `a` (degrees) with residual `r`, damping
  // `lambda` on the given-up rows (rig units^2, like Jf Jf^T) and `floor` added on the held ones.
  Status step(const Kinematics& kin, const Eigen::MatrixXd& J, const BlockPattern& pattern,
              const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& r, double lambda,
              double floor, const Deadline& deadline, Eigen::Ref<Eigen::VectorXd> trial);
  // The decrease of 1/2 |r|^2 over the held rows (`held`) or the others that the linear model
  // predicts for the last step(): -r . Jd - 1/2 |Jd|^2 over those rows, rig units^2.
  double predicted_decrease(const Eigen::Ref<const Eigen::VectorXd>& r, bool held) const;

  // |g| of the given-up rows' gradient Jf^T r within the null space of the held rows' Jacobian,
  // leaving out the angles on a limit that it pushes outward (rig units^2 per degree): 0 at the
  // lexicographic closest point. After prepare() at the same point.
  double reduced_gradient_norm(const Kinematics& kin, const Eigen::MatrixXd& J, const BlockPattern& pattern,
                               const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& r);

 private:
  // Was effector e off target at the start (one of its blocks beyond its tolerance)?
  bool effector_off_at_start(const GoalSet& goals, int e) const;
  // Is row i held (a row of a held hard block)?
  bool held_row(int i) const { return i < held_rows_ && !given_up_[i / 3]; }

  std::vector<char> given_up_;
  std::vector<char> off_at_start_;  // per hard block: beyond its tolerance at the solve's start
  int given_up_count_ = 0;
  int suspended_count_ = 0;  // given_up_count_ while suspended
  int held_rows_ = 0;        // hard rows: the blocks' rows; rows past them (soft) are never held
  std::vector<int> movable_;
  double scale_ = 1;
  Eigen::MatrixXd normal_, held_normal_;
  DampedSystem system_;
  Eigen::VectorXd y_, held_y_, gradient_, jd_;
  ActiveSet active_set_;
};

}  // namespace ik

// Restarting only the chains that are off target, for a solve that must not move the rest of the
// pose (restarts = 0 while a user drags).
//
// A run can end at a true local minimum off target that no escape along negative curvature
// leaves: a character's foot whose effector is the toe, with the ankle on its limit, cannot rise
// further by any small move of hip, knee and ankle (bending the knee first lowers the toe), yet a
// bent leg reaches the target. A chain restart starts a new run from the best point with only the
// movable angles of the off-target effectors' chains moved, by up to 15, 30, 60 or 120 degrees or
// anywhere inside their limits, in turn (quasi-random), leaving the bones that also carry an effector on
// target as they are. An effector whose target lies beyond everything its chain can reach (the
// distance from the fixed joint of its first movable bone exceeds the sum of the rigid segments
// below it) is left out: its closest point is not a local accident.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "goals.h"
#include "kinematics.h"
#include "quasi_random.h"

namespace ik {

class ChainRestart {
 public:
  // Workspace for `kin` (allocates).
  void resize(const Kinematics& kin);

  // From the best point `best` (#angles, degrees; `kin` posed there) with residual `r`
  // (goal_residual.h, towards `goals`): writes the start of chain restart `attempt` (1, 2, ... in a
  // solve) to `start`, with the off-target chains moved by a point of `sequence`. Returns false
  // when no effector is off target within its reach (nothing worth restarting). `slack` (rig
  // units): how far off a tip may be and count as on target; a target that much beyond the
  // chain's reach still counts as within it. `held_fixed`: see beyond_reach(). No allocation.
  bool propose(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& best,
               const Eigen::Ref<const Eigen::VectorXd>& r, const GoalSet& goals, double slack, bool held_fixed,
               const QuasiRandom& sequence, long attempt, Eigen::Ref<Eigen::VectorXd> start);

  // With `kin` posed at a point with residual `r`: is some off-target effector's target beyond
  // what its chain reaches (beyond_reach)? No allocation.
  bool beyond_any(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalSet& goals, double slack,
                  bool held_fixed);

 private:
  // Which effectors are off target at residual `r` (off_) and which bones carry one on target (kept_).
  void mark(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalSet& goals);
  // Is effector e's target farther from its chain's first movable bone's joint than the chain
  // reaches from there, plus `slack`? An effector without a position goal never is. After mark().
  // `held_fixed` (strict priority with goals given up: the goals on target are held): only the
  // part of the chain below the bones it shares with on-target chains counts, which the held
  // goals keep from swinging it further; false: the whole chain (the other effectors' own joints
  // can make up for a shared bone's move, as fingers do for a wrist).
  bool beyond_reach(const Kinematics& kin, int e, const GoalSet& goals, double slack, bool held_fixed) const;
  std::vector<char> off_;           // per effector: off target (after mark())
  std::vector<char> moved_, kept_;  // per bone: on an off-target chain / on an on-target chain
  Eigen::VectorXd unit_, anywhere_;
};

}  // namespace ik

#include "chain_restart.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "goal_residual.h"

namespace ik {

namespace {

// Chain restarts use the sequence's points from here on, after any whole-pose restart's.
constexpr long kFirstPoint = 1L << 24;
// Perturbation radii, degrees, used in turn; infinity: anywhere inside the limits (as a restart).
constexpr double kRadiiDeg[] = {15, 30, 60, 120, std::numeric_limits<double>::infinity()};

bool movable(const Kinematics& kin, int bone) {
  for (int k = 0; k < 3; ++k)
    if (kin.lower()[3 * bone + k] < kin.upper()[3 * bone + k]) return true;
  return false;
}

Eigen::Vector3d rest_origin(const Rig& rig, int bone) { return rig.bones[bone].rest.block<3, 1>(0, 3); }

}  // namespace

void ChainRestart::resize(const Kinematics& kin) {
  off_.assign(kin.num_effectors(), 0);
  moved_.assign(kin.num_bones(), 0);
  kept_.assign(kin.num_bones(), 0);
  unit_.resize(kin.num_angles());
  anywhere_.resize(kin.num_angles());
}

void ChainRestart::mark(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalSet& goals) {
  const double largest = largest_goal_distance(goals, r);
  std::fill(kept_.begin(), kept_.end(), 0);
  for (int e = 0; e < kin.num_effectors(); ++e) {
    off_[e] = largest > 0 && goal_off_target(goals, r, e, largest);
    if (!off_[e])
      for (int b : kin.effector_chain(e)) kept_[b] = 1;
  }
}

bool ChainRestart::beyond_reach(const Kinematics& kin, int e, const GoalSet& goals, double slack,
                                bool held_fixed) const {
  Eigen::Vector3d target;
  if (goals.plain()) {
    target = goals.plain_target().segment<3>(3 * e);
  } else {
    const int b = goals.position_block(e);
    if (b < 0) return false;
    target = goals.block(b).position;
  }
  // The chain's first movable bone (held_fixed: below the ones shared with on-target chains), and
  // its reach: joint to joint down the chain, then the effector bone itself (rigid at any pose).
  const std::vector<int>& chain = kin.effector_chain(e);  // root first
  const int bone = kin.rig().effectors[e];
  for (size_t i = 0; i < chain.size(); ++i) {
    if (!movable(kin, chain[i]) || (held_fixed && kept_[chain[i]])) continue;
    double length = kin.rig().bones[bone].length;
    for (size_t j = i; j + 1 < chain.size(); ++j)
      length += (rest_origin(kin.rig(), chain[j + 1]) - rest_origin(kin.rig(), chain[j])).norm();
    return (target - kin.joint_origin(chain[i])).norm() >= length + slack;
  }
  return true;  // nothing on its chain moves
}

bool ChainRestart::beyond_any(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& r, const GoalSet& goals,
                              double slack, bool held_fixed) {
  mark(kin, r, goals);
  for (int e = 0; e < kin.num_effectors(); ++e)
    if (off_[e] && beyond_reach(kin, e, goals, slack, held_fixed)) return true;
  return false;
}

bool ChainRestart::propose(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& best,
                           const Eigen::Ref<const Eigen::VectorXd>& r, const GoalSet& goals, double slack,
                           bool held_fixed, const QuasiRandom& sequence, long attempt,
                           Eigen::Ref<Eigen::VectorXd> start) {
  mark(kin, r, goals);
  std::fill(moved_.begin(), moved_.end(), 0);
  bool any = false;
  for (int e = 0; e < kin.num_effectors(); ++e) {
    if (!off_[e] || beyond_reach(kin, e, goals, slack, held_fixed)) continue;
    for (int b : kin.effector_chain(e)) moved_[b] = 1;
    any = true;
  }
  if (!any) return false;
  // Bones shared with an on-target chain stay, unless that leaves nothing to move.
  bool exclusive = false;
  for (int b = 0; b < kin.num_bones(); ++b) exclusive = exclusive || (moved_[b] && !kept_[b] && movable(kin, b));

  sequence.point(kFirstPoint + attempt, unit_);
  const double radius = kRadiiDeg[(attempt - 1) % (sizeof kRadiiDeg / sizeof kRadiiDeg[0])];
  if (std::isinf(radius)) point_in_limits(unit_, kin.lower(), kin.upper(), anywhere_);
  start = best;
  for (int b = 0; b < kin.num_bones(); ++b) {
    if (!moved_[b] || (exclusive && kept_[b])) continue;
    for (int k = 3 * b; k < 3 * b + 3; ++k)
      start[k] = std::isinf(radius) ? anywhere_[k] : start[k] + radius * (2 * unit_[k] - 1);
  }
  kin.project(start);
  return true;
}

}  // namespace ik

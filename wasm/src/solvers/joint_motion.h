// Bounded joint speed: how far a solve moves the body, measured where the joints go, and the
// pose partway to a solution that lies too far off.
//
// A drag that moves its target a little should move the body a little. When the only solutions
// near the new target lie on another branch (a straight leg whose ankle is on its limit can
// only reach a nearer toe target with the knee well bent), the solve's answer is far from where
// it started, and returned as it is the page would show a one-frame snap. With the option
// max_joint_move > 0 the Solver instead returns the pose a fraction t of the way (in angles)
// from the start to that answer, the largest t for which no joint (a bone's head or tip) has
// moved more than max_joint_move; the solve stops with StopReason::joint_speed, and the next
// solve, from there, goes on: the body changes branch over a few frames at a bounded speed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "kinematics.h"

namespace ik {

class JointMotion {
 public:
  // Workspace for `kin`'s bones (allocates).
  void resize(const Kinematics& kin);
  // Records every bone's head and tip, with `kin` posed at the solve's start. No allocation.
  void note_start(const Kinematics& kin);
  // The largest distance (rig units) a bone's head or tip has moved from the start, with `kin`
  // posed at the point in question. No allocation.
  double largest_move(const Kinematics& kin) const;
  // With `end` (#angles, degrees) farther than `bound` (rig units) from the start `start`: writes
  // to `out` the point start + t (end - start) for the largest t in [0, 1) found by bisection
  // whose largest_move() is at most `bound` (t = 0 when none is), and leaves `kin` posed there.
  // Returns t. No allocation.
  double limit(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& start,
               const Eigen::Ref<const Eigen::VectorXd>& end, double bound, Eigen::Ref<Eigen::VectorXd> out) const;

 private:
  std::vector<Eigen::Vector3d> heads_, tips_;  // per bone, at the start
};

}  // namespace ik

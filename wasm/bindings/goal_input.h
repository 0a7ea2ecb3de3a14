// Goals as they cross from JavaScript: per end effector, in the rig's effector order, the kGoalStride
// numbers [positionWeight, orientationWeight, qx, qy, qz, qw, yields] (a weight of 0: no such goal; the
// quaternion is the target orientation of the effector bone's frame in rig coordinates, any
// nonzero length; yields 1: EffectorGoal::yields, else 0). The positions come from the solve's target (3 per effector,
// rig units), so a drag that only moves targets writes the same buffer as a plain solve. Bend hints cross as
// kPoleStride numbers each, [bone, x, y, z, weight] (rig units); stiffness as one number per bone
// or none (all 1).
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "goals.h"
#include "js_arrays.h"

namespace ik::js {

constexpr int kGoalStride = 7;
constexpr int kPoleStride = 5;

class GoalInput {
 public:
  // Reads `packed` (kGoalStride numbers per effector of `kin`), `poles` (kPoleStride numbers per
  // bend hint), `stiffness` (#bones numbers, or none) and the length scale (rig units per radian;
  // 0: the rig's reach). Throws RigError naming the effector or pole and the field; the solver's
  // start() checks the rest (GoalSet::set()).
  void set(const Kinematics& kin, const std::vector<double>& packed, const std::vector<double>& poles,
           const std::vector<double>& stiffness, double length_scale) {
    const int m = kin.num_effectors();
    if (static_cast<int>(packed.size()) != kGoalStride * m)
      throw RigError("goals have " + std::to_string(packed.size()) + " numbers, expected " +
                     std::to_string(kGoalStride * m) + " (" + std::to_string(kGoalStride) + " per end effector)");
    if (!std::isfinite(length_scale) || length_scale < 0)
      throw RigError("the goals' length scale must be a finite number >= 0 (0: the rig's reach)");
    goals_.length_scale = length_scale;
    goals_.effectors.assign(m, EffectorGoal());
    for (int e = 0; e < m; ++e) {
      const double* g = packed.data() + kGoalStride * e;
      const auto field = [e](const char* what) {
        return std::string("the ") + what + " of end effector " + std::to_string(e) + "'s goal";
      };
      if (!std::isfinite(g[0]) || g[0] < 0) throw RigError(field("position weight") + " must be a finite number >= 0");
      if (!std::isfinite(g[1]) || g[1] < 0)
        throw RigError(field("orientation weight") + " must be a finite number >= 0");
      EffectorGoal& goal = goals_.effectors[e];
      goal.position = g[0] > 0;
      goal.position_weight = g[0];
      goal.orientation = g[1] > 0;
      goal.orientation_weight = g[1];
      if (g[6] != 0 && g[6] != 1) throw RigError(field("yields flag") + " must be 0 or 1");
      goal.yields = g[6] == 1;
      if (!goal.orientation) continue;
      const Eigen::Quaterniond q(g[5], g[2], g[3], g[4]);
      const double norm = q.norm();
      if (!std::isfinite(norm) || norm < 1e-9)
        throw RigError(field("orientation") + " is not a rotation (a quaternion of finite, nonzero length)");
      goal.orientation_target = q.normalized().toRotationMatrix();
    }
    if (poles.size() % kPoleStride != 0)
      throw RigError("poles have " + std::to_string(poles.size()) + " numbers, not " + std::to_string(kPoleStride) +
                     " per pole (bone, x, y, z, weight)");
    goals_.poles.resize(poles.size() / kPoleStride);
    for (size_t k = 0; k < goals_.poles.size(); ++k) {
      const double* p = poles.data() + kPoleStride * k;
      if (!(p[0] >= 0 && p[0] < kin.num_bones() && p[0] == std::floor(p[0])))
        throw RigError("pole " + std::to_string(k) + "'s bone is not a bone index");
      goals_.poles[k] = PoleGoal{static_cast<int>(p[0]), Eigen::Vector3d(p[1], p[2], p[3]), p[4]};
    }
    goals_.stiffness = stiffness;
    effectors_ = kin.rig().effectors;
  }

  // The goals with their positions taken from `target` (3 per effector, rig units). Throws if
  // the rig's effector list changed since set(). No allocation.
  const Goals& with_positions(const Kinematics& kin, const double* target) {
    if (kin.rig().effectors != effectors_)
      throw RigError("the end effectors changed since the goals were set: set the goals again");
    for (size_t e = 0; e < goals_.effectors.size(); ++e)
      goals_.effectors[e].position_target = Eigen::Map<const Eigen::Vector3d>(target + 3 * e);
    return goals_;
  }

 private:
  Goals goals_;
  std::vector<int> effectors_;  // the effector list the goals were set for
};

}  // namespace ik::js

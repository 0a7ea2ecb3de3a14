// The clip-on-the-limit active set of the Newton-type steps (lm, gn, newton). A step solved over
// the free angles can carry some of them past their limits; projecting it afterwards bends it
// away from the direction solved for. Instead, pass by pass:
//   1. solve the method's system for the angles still in the set;
//   2. each angle in the set whose new value angle + step would leave [lower, upper] is fixed on
//      the limit it crosses (its step becomes limit - angle), leaves the set, and the method
//      takes its known move out of the system (its column moves to the right-hand side);
// until a pass fixes none, or after kPasses passes. No allocation after resize().
#pragma once

#include <Eigen/Core>
#include <vector>

#include "deadline.h"

namespace ik {

class ActiveSet {
 public:
  // Passes per step (each solves the system once).
  static constexpr int kPasses = 4;

  // Which angles whose step leaves the box are fixed on the limit.
  enum class Fix {
    past_limit,     // every one
    on_limit_only,  // only one already on the limit it would cross (held there, step 0); the
                    // others keep their whole step, for a projected line search to bend
  };

  enum class Status {
    done,          // step() holds the step
    solve_failed,  // the method's solve returned false (the method knows why)
    out_of_time,   // the deadline passed while going through the angles
  };

  // Workspace for `angles` angles (allocates).
  void resize(int angles) {
    mask_.resize(angles);
    step_.resize(angles);
  }

  // One step from `angles` (#angles, degrees) inside [lower, upper] (#angles each, degrees) over
  // the free angles free[0..num_free) (ascending). The method supplies
  //   solve():            solves its system for the angles with mask() 1; false to give up;
  //   proposed(i):        angle i's step from that solution, degrees;
  //   take_out(i, step):  angle i now moves by the known `step` (degrees): out of the system.
  // Afterwards step() holds every angle's step (0 for the angles that are not free) and mask()
  // 1 for the angles still in the set. `deadline` is read every 64 angles.
  template <class Solve, class Proposed, class TakeOut>
  Status run(const Eigen::VectorXd& angles, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
             const std::vector<int>& free, int num_free, Fix fix, const Deadline& deadline, Solve&& solve,
             Proposed&& proposed, TakeOut&& take_out) {
    mask_.setZero();
    for (int c = 0; c < num_free; ++c) mask_[free[c]] = 1;
    step_.setZero();
    for (int pass = 0; pass < kPasses; ++pass) {
      if (!solve()) return Status::solve_failed;
      bool fixed_more = false;
      for (int c = 0; c < num_free; ++c) {
        if (c % 64 == 63 && deadline.passed()) return Status::out_of_time;
        const int i = free[c];
        if (mask_[i] == 0) continue;
        const double d = proposed(i);
        const double to = angles[i] + d;
        const bool past_lower = to < lower[i];
        const bool past_upper = to > upper[i];
        const bool on_limit = angles[i] <= lower[i] || angles[i] >= upper[i];
        if (!(past_lower || past_upper) || (fix == Fix::on_limit_only && !on_limit)) {
          step_[i] = d;
          continue;
        }
        step_[i] = (past_lower ? lower[i] : upper[i]) - angles[i];
        mask_[i] = 0;
        fixed_more = true;
        take_out(i, step_[i]);
      }
      if (!fixed_more) break;
    }
    return Status::done;
  }

  // 1 for an angle still in the set, 0 otherwise (#angles).
  const Eigen::VectorXd& mask() const { return mask_; }
  // Each angle's step (#angles, degrees); the method may scale it.
  Eigen::VectorXd& step() { return step_; }
  const Eigen::VectorXd& step() const { return step_; }

 private:
  Eigen::VectorXd mask_, step_;
};

}  // namespace ik

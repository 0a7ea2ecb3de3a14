// Projected backtracking (Calamai & More): try P(A + alpha p) for alpha = alpha_0, alpha_0 * factor, ...
// and take the first trial with enough decrease. P clamps each angle into its limits.
#pragma once

#include <Eigen/Core>

#include "deadline.h"
#include "goals.h"
#include "kinematics.h"

namespace ik {

struct BacktrackingOptions {
  double initial_step = 1;  // alpha_0 (dimensionless multiple of the direction)
  double factor = 0.5;      // alpha_{i+1} = factor * alpha_i, in (0, 1)
  double c1 = 1e-3;         // accept when E(trial) < E0 + c1 * slope; c1 = 0: plain decrease
  // slope = grad . (trial - A) on the projected trial (Calamai & More); false: alpha grad . p, the
  // unprojected slope the original program used.
  bool projected_slope = true;
  int max_tries = 60;  // trials before giving up
  Deadline deadline;   // gives up once it passes (checked every few trials)
};

struct BacktrackingResult {
  bool found = false;      // a trial was accepted; false when the step became 0 or max_tries failed
  double step = 0;         // the accepted alpha (0 if none)
  double E = 0;            // E at the accepted trial
  int evaluations = 0;     // E evaluations made (forward kinematics)
  bool timed_out = false;  // gave up because the deadline passed
};

// From `angles` (#angles, degrees) with E = `E0` and gradient `gradient` (#angles) along
// `direction` (#angles, degrees per unit alpha) towards `goals` (goals.h). Writes the
// accepted trial angles to `trial` and its residual to `residual`; on success `kin` is left
// posed at `trial`. Gives up as soon as the projected trial equals `angles` (step 0), or when the
// deadline has passed.
// No allocation.
BacktrackingResult projected_backtracking(Kinematics& kin, const GoalSet& goals,
                                          const Eigen::Ref<const Eigen::VectorXd>& angles, double E0,
                                          const Eigen::Ref<const Eigen::VectorXd>& gradient,
                                          const Eigen::Ref<const Eigen::VectorXd>& direction,
                                          const BacktrackingOptions& options, Eigen::Ref<Eigen::VectorXd> trial,
                                          Eigen::Ref<Eigen::VectorXd> residual);

// Scales `step` (#angles, degrees) down, if need be, so that no entry exceeds `max_change`
// degrees in size. Returns the largest |entry| before scaling (not finite: `step` is left as is).
double cap_largest_change(Eigen::Ref<Eigen::VectorXd> step, double max_change);

}  // namespace ik

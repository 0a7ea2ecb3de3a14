#include "line_search.h"

#include <cmath>

#include "goal_residual.h"

namespace ik {

BacktrackingResult projected_backtracking(Kinematics& kin, const GoalSet& goals,
                                          const Eigen::Ref<const Eigen::VectorXd>& angles, double E0,
                                          const Eigen::Ref<const Eigen::VectorXd>& gradient,
                                          const Eigen::Ref<const Eigen::VectorXd>& direction,
                                          const BacktrackingOptions& options, Eigen::Ref<Eigen::VectorXd> trial,
                                          Eigen::Ref<Eigen::VectorXd> residual) {
  BacktrackingResult result;
  double alpha = options.initial_step;
  for (int i = 0; i < options.max_tries; ++i, alpha *= options.factor) {
    trial = angles + alpha * direction;
    kin.project(trial);
    if (trial == angles) break;  // the step is 0
    const double E = goal_objective(kin, goals, trial, residual);
    ++result.evaluations;
    const double slope = options.projected_slope ? gradient.dot(trial - angles) : alpha * gradient.dot(direction);
    const double bound = E0 + options.c1 * slope;
    if (std::isfinite(E) && E < bound) {
      result.found = true;
      result.step = alpha;
      result.E = E;
      return result;
    }
    if (i % 4 == 3 && options.deadline.passed()) {
      result.timed_out = true;
      break;
    }
  }
  return result;
}

double cap_largest_change(Eigen::Ref<Eigen::VectorXd> step, double max_change) {
  const double largest = step.cwiseAbs().maxCoeff();
  if (std::isfinite(largest) && largest > max_change) step *= max_change / largest;
  return largest;
}

}  // namespace ik

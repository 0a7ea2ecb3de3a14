// The rules a finished solve's summary obeys whatever happened on the way (SolverSummary): no
// NaN among its numbers, and stop_reason converged_E exactly when `reached`.
#include <cmath>
#include <limits>

#include "solver.h"

namespace ik {

void Solver::keep_contract() {
  SolverSummary& s = summary_;
  bool overflowed = false;
  for (double* x : {&s.initial_E, &s.E, &s.gradient_norm, &s.tip_distance})
    if (std::isnan(*x)) {
      *x = std::numeric_limits<double>::infinity();
      overflowed = true;
    }
  if (overflowed) {
    s.reached = false;
    s.stop_reason = StopReason::numerical_failure;
    if (s.message.empty()) s.message = "E or its gradient overflowed";
  }
  if (s.reached == (s.stop_reason == StopReason::converged_E)) return;
  // The best point is on target (a later run, e.g. towards the soft terms' optimum, failed):
  // that is the answer. Or it is not, whatever the last test said: a closest point or a stop.
  if (s.reached) {
    s.stop_reason = StopReason::converged_E;
    s.message.clear();
  } else {
    s.stop_reason = s.gradient_norm < opt_.gradient_tolerance ? StopReason::converged_grad : StopReason::zero_step;
  }
}

}  // namespace ik

// When a run off target has settled: its distance from the goals (rig units) has fallen by less
// than a threshold over the last kSteps accepted steps. Near a closest point that a target out
// of reach leaves, a Newton-type run still crawls for hundreds of steps (a straight arm pointing
// at the target is a singular pose) while no one can see the difference: a settled run is
// judged where it is, as a stationary point would be (Solver::advance).
#pragma once

#include <limits>

namespace ik {

class Settling {
 public:
  static constexpr int kSteps = 5;

  // A new run: nothing recorded.
  void begin_run() { count_ = 0; }

  // After an accepted step to `distance` (rig units): has it fallen by less than `threshold`
  // (rig units) over the last kSteps steps?
  bool settled(double distance, double threshold) {
    const double before = count_ >= kSteps ? last_[count_ % kSteps] : std::numeric_limits<double>::infinity();
    last_[count_ % kSteps] = distance;
    ++count_;
    return before - distance < threshold;
  }

 private:
  double last_[kSteps] = {};
  long count_ = 0;
};

}  // namespace ik

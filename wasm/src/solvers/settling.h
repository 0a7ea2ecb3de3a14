// When a run off target has settled on a closest point: its distance from the goals (rig units)
// has stopped falling, up to a threshold. Near the closest point that a target out of reach
// leaves, a Newton-type run still crawls for hundreds of steps (a straight arm pointing at the
// target is a singular pose) while no one can see the difference: a settled run is judged where
// it is, as a stationary point would be (Solver::advance).
#pragma once

#include <limits>

namespace ik {

class Settling {
 public:
  static constexpr int kSteps = 5;

  // A new run: nothing recorded, not ended by settling.
  void begin_run() {
    count_ = 0;
    ended_ = false;
  }

  // Whether the run was ended by settling (Solver::settles() says so); false after begin_run().
  bool ended() const { return ended_; }
  void set_ended(bool ended) { ended_ = ended; }

  // After an accepted step to `distance` (rig units): records it.
  void record(double distance) { last_[count_++ % kWindow] = distance; }

  // Has the distance fallen by less than `threshold` (rig units) over the last kSteps steps?
  bool stalled(double threshold) const { return count_ > kSteps && at(kSteps) - at(0) < threshold; }

  // Does the run settle beyond `tolerance`? Over the last two spans of kSteps steps the distance
  // fell by p1, then p2 < `threshold`; were it to go on falling at that rate (geometrically, by
  // p2 / p1 per span) it would fall by less than `threshold` more and stay above `tolerance`
  // (rig units). A run still closing on a reachable target slowly (gradient descent) has not.
  bool settled(double threshold, double tolerance) const {
    if (count_ <= 2 * kSteps) return false;
    const double p1 = at(2 * kSteps) - at(kSteps), p2 = at(kSteps) - at(0);
    if (!(p2 < threshold)) return false;
    if (p2 <= 0) return at(0) > tolerance;
    if (!(p2 < p1)) return false;
    const double rate = p2 / p1, more = p2 * rate / (1 - rate);
    return more < threshold && at(0) - more > tolerance;
  }

 private:
  static constexpr int kWindow = 2 * kSteps + 1;
  // The distance `back` steps ago (0: the last one recorded).
  double at(int back) const { return last_[(count_ - 1 - back) % kWindow]; }
  double last_[kWindow] = {};
  long count_ = 0;
  bool ended_ = false;
};

}  // namespace ik

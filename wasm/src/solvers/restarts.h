// Whole restarts of a solve (option restarts, outside paper mode): the quasi-random start points
// inside the limits, how many a solve has used, and when a run stalls (its best E has not fallen
// below 90% of itself for stall_iterations accepted steps). The same sequence draws the chain
// restarts' moves (chain_restart.h).
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "quasi_random.h"

namespace ik {

class Restarts {
 public:
  // A new solve over `angles` angles with the sequence of `seed` (rebuilt, allocating, only when
  // either changed): no restart used, a new run.
  void begin_solve(int angles, std::uint32_t seed);
  // A new run: stall tracking starts again.
  void begin_run();
  // After an accepted step to E (rig units^2): has the run stalled, its best E not below 90% of
  // the previous best for `stall_iterations` steps?
  bool stalls(double E, int stall_iterations);
  // Counts a restart, writes its start (#angles, degrees, inside `lower`..`upper`, #angles each)
  // to `start` and begins a new run. No allocation.
  void next_start(const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, Eigen::Ref<Eigen::VectorXd> start);

  // Restart k's start (k >= 1) of `sequence` (#angles, degrees, inside `lower`..`upper`) into
  // `start`; `unit` is scratch of #angles. What next_start() gives for its k-th restart, for
  // harnesses that restart other solvers the same way. No allocation.
  static void start_of(const QuasiRandom& sequence, long k, const Eigen::Ref<const Eigen::VectorXd>& lower,
                       const Eigen::Ref<const Eigen::VectorXd>& upper, Eigen::Ref<Eigen::VectorXd> unit,
                       Eigen::Ref<Eigen::VectorXd> start);

  // Restarts used in this solve.
  long used() const { return used_; }
  const QuasiRandom& sequence() const { return sequence_; }

 private:
  QuasiRandom sequence_;
  std::uint32_t seed_ = 0;
  long used_ = 0;
  int run_iterations_ = 0, run_best_iteration_ = 0;
  double run_best_E_ = 0;
  Eigen::VectorXd unit_;
};

}  // namespace ik

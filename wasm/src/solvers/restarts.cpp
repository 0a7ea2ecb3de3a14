#include "restarts.h"

#include <limits>

namespace ik {

void Restarts::begin_solve(int angles, std::uint32_t seed) {
  if (seed_ != seed || sequence_.dimension() != angles) {
    sequence_ = QuasiRandom(angles, seed);
    seed_ = seed;
  }
  if (unit_.size() != angles) unit_.resize(angles);
  used_ = 0;
  begin_run();
}

void Restarts::begin_run() {
  run_iterations_ = run_best_iteration_ = 0;
  run_best_E_ = std::numeric_limits<double>::infinity();
}

bool Restarts::stalls(double E, int stall_iterations) {
  ++run_iterations_;
  if (E < 0.9 * run_best_E_) {
    run_best_E_ = E;
    run_best_iteration_ = run_iterations_;
    return false;
  }
  return run_iterations_ - run_best_iteration_ >= stall_iterations;
}

void Restarts::next_start(const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                          Eigen::Ref<Eigen::VectorXd> start) {
  ++used_;
  start_of(sequence_, used_, lower, upper, unit_, start);
  begin_run();
}

void Restarts::start_of(const QuasiRandom& sequence, long k, const Eigen::Ref<const Eigen::VectorXd>& lower,
                        const Eigen::Ref<const Eigen::VectorXd>& upper, Eigen::Ref<Eigen::VectorXd> unit,
                        Eigen::Ref<Eigen::VectorXd> start) {
  sequence.point(k, unit);
  point_in_limits(unit, lower, upper, start);
}

}  // namespace ik

// Projected gradient descent as the report ran it: p = -grad E, then projected backtracking
// from alpha = 180/pi, halving until E decreases (no sufficient-decrease constant).
#include <memory>

#include "solver.h"

namespace ik {

namespace {

class GradientDescent final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "gd"; }

 private:
  void resize(int /*residuals*/, int angles) override { direction_.resize(angles); }

  Progress iterate() override {
    // Outside paper mode, angles that cannot move (fixed, or pushed against a bound) stay put.
    if (opt_.paper_mode)
      direction_ = -g_;
    else
      direction_ = -g_.cwiseProduct(free_mask_);
    return backtrack(direction_, opt_.gd_initial_step, 0) ? Progress::moved : Progress::stuck;
  }

  Eigen::VectorXd direction_;
};

}  // namespace

std::unique_ptr<Solver> make_gd_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<GradientDescent>(kin, options);
}

}  // namespace ik

// Projected gradient descent: p = -grad E, then projected backtracking.
// Paper mode, as the report ran it: every line search starts at alpha = gd_initial_step (180/pi)
// and halves until E decreases (no sufficient-decrease constant, c1 = 0).
// Outside paper mode: the angles that cannot move (fixed, or pushed against a bound) stay put,
// and each line search starts at the Barzilai-Borwein step alpha = s's / s'y (s, y: the last
// change of the angles and of the gradient; gd_initial_step at a run's first iteration or when
// s'y <= 0), the spectral projected gradient of Birgin, Martinez and Raydan with a monotone
// Armijo test (c1 = kArmijoC1, not the option armijo_c1): the direction is still -grad E, but its
// length follows the curvature met along the way instead of starting from 180/pi every time.
#include <algorithm>
#include <memory>

#include "solver.h"

namespace ik {

namespace {

class GradientDescent final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "gd"; }

 private:
  void resize(int /*residuals*/, int angles) override {
    direction_.resize(angles);
    previous_angles_.resize(angles);
    previous_gradient_.resize(angles);
  }

  void reset() override { has_previous_ = false; }

  Progress iterate() override {
    if (opt_.paper_mode) {
      direction_ = -g_;
      return backtrack(direction_, opt_.gd_initial_step, 0) ? Progress::moved : Progress::stuck;
    }
    direction_ = -g_.cwiseProduct(free_mask_);
    double step = opt_.gd_initial_step;
    if (has_previous_) {
      const double ss = (a_ - previous_angles_).squaredNorm();
      const double sy = (a_ - previous_angles_).dot(g_ - previous_gradient_);
      if (sy > 0 && ss > 0) step = std::clamp(ss / sy, kMinStep, kMaxStep);
    }
    previous_angles_ = a_;
    previous_gradient_ = g_;
    has_previous_ = true;
    return backtrack(direction_, step, kArmijoC1) ? Progress::moved : Progress::stuck;
  }

  static constexpr double kArmijoC1 = 1e-4;
  static constexpr double kMinStep = 1e-10, kMaxStep = 1e10;
  Eigen::VectorXd direction_, previous_angles_, previous_gradient_;
  bool has_previous_ = false;
};

}  // namespace

std::unique_ptr<Solver> make_gd_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<GradientDescent>(kin, options);
}

}  // namespace ik

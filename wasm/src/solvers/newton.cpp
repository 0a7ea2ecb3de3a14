// Projected Newton with the exact Hessian of E:
//   Hess E = J^T J + sum_i r_i Hess x_i     (tip second derivatives from tip_hessian.h)
// restricted to the free angles (not fixed, not on a bound that grad E pushes outward; the
// others keep their value, Bertsekas' projected Newton). The reduced Hessian is shifted,
// H + mu I, with mu proportional to |r| (so the shift vanishes at a solution and convergence
// stays quadratic even where J J^T is singular), and mu grows 4x until the Cholesky factorisation
// succeeds (indefinite H). The step is capped at newton_max_step_deg per angle, then projected
// Armijo backtracking from alpha = 1.
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <memory>

#include "solver.h"
#include "tip_hessian.h"

namespace ik {

namespace {

class ProjectedNewton final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "newton"; }

 private:
  void resize(int /*residuals*/, int n) override {
    H_.resize(n, n);
    shifted_.resize(n, n);
    llt_ = Eigen::LLT<Eigen::MatrixXd>(n);
    direction_.resize(n);
    gf_.resize(n);
  }

  Progress iterate() override {
    if (num_free_ == 0) return Progress::stuck;
    // kin_ is posed at a_ (update_derivatives ran there).
    H_.noalias() = J_.transpose() * J_;
    add_weighted_tip_hessian(kin_, r_, H_);
    gf_ = g_.cwiseProduct(free_mask_);
    double mean_diagonal = 0;
    for (int i = 0; i < n_; ++i) {
      if (free_mask_[i] != 0) {
        mean_diagonal += std::abs(H_(i, i));
        continue;
      }
      H_.row(i).setZero();
      H_.col(i).setZero();
      H_(i, i) = 1;
    }
    mean_diagonal /= num_free_;
    if (!std::isfinite(mean_diagonal)) return fail("the Hessian is not finite");
    if (!(mean_diagonal > 0)) return Progress::stuck;  // no free angle moves a tip

    const double floor = 1e-12 * mean_diagonal;
    double mu = std::max(floor, mean_diagonal * std::sqrt(2 * E_) / reach_);
    bool factored = false;
    for (int attempt = 0; attempt < kMaxShifts && !factored; ++attempt, mu *= 4) {
      shifted_ = H_;
      shifted_.diagonal() += mu * free_mask_;
      llt_.compute(shifted_);
      factored = llt_.info() == Eigen::Success;
    }
    if (!factored) return fail("the shifted Hessian could not be factorised");
    direction_ = gf_;
    llt_.solveInPlace(direction_);
    direction_ = -direction_.cwiseProduct(free_mask_);
    const double largest = direction_.cwiseAbs().maxCoeff();
    if (!std::isfinite(largest)) return fail("the Newton step is not finite");
    if (largest > opt_.newton_max_step_deg) direction_ *= opt_.newton_max_step_deg / largest;

    return backtrack(direction_, 1, opt_.armijo_c1) ? Progress::moved : Progress::stuck;
  }

  static constexpr int kMaxShifts = 60;  // 4^60: any finite Hessian becomes positive definite
  Eigen::MatrixXd H_, shifted_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::VectorXd direction_, gf_;
};

}  // namespace

std::unique_ptr<Solver> make_newton_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<ProjectedNewton>(kin, options);
}

}  // namespace ik

// Projected Newton with the exact Hessian of E:
//   H = Hess E = J^T J + C,   C = sum_i r_i Hess x_i     (tip second derivatives, tip_hessian.h)
// on the free angles (not fixed, not on a bound that grad E pushes outward; the others keep
// their value, as in Bertsekas' projected Newton).
//
// Near an IK solution H is singular (more angles than tip coordinates) and slightly indefinite:
// along the null space of J only C ~ |r| is left, which says little and may be negative. The
// step therefore solves
//   (H + f (I - P) + mu I) p = -g,   P = Jf^T (Jf Jf^T)^-1 Jf  (projector onto J's row space)
// with f = |r| s / reach, s the mean |diagonal| of H over the free angles: the exact curvature is
// kept along J's row space, so the last iterations converge quadratically, while the null space
// gets curvature of C's size and cannot send the step far. The shift
//   mu = (m |r|^2 / reach^2 + floor) * s
// damps the step, m adapted to the gain ratio rho = actual / predicted decrease of the quadratic
// model (Nielsen's rule, damping.h, as lm's), and grows 4x while the Cholesky factorisation fails
// (the matrix indefinite). An angle whose step would leave its limits is fixed on the limit and
// the rest re-solved (active_set.h); the step is capped at newton_max_step_deg per angle.
//
// Orientation goals (goals.h): C holds the exact second derivatives of the position rows only
// (weights w_p r, goal_residual.h); the orientation rows enter H through J^T J alone, a
// Gauss-Newton-type Hessian for those terms (their second derivatives, which vanish on target,
// are left out).
#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <memory>

#include "active_set.h"
#include "damping.h"
#include "goal_residual.h"
#include "line_search.h"
#include "size_limits.h"
#include "solver.h"
#include "tip_hessian.h"

namespace ik {

namespace {

class ProjectedNewton final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "newton"; }

 private:
  int angle_limit(int residuals) const override { return dense_angle_limit(residuals); }
  void resize(int m, int n) override {
    H_.resize(n, n);
    modified_.resize(n, n);
    shifted_.resize(n, n);
    // Each LLT sized by factorising a zero matrix (it stops at the first pivot), so compute()
    // allocates nothing. Not `llt_ = Eigen::LLT<Eigen::MatrixXd>(n)`: Eigen's sizing constructor
    // leaves info() and the kept norm uninitialised, and the assignment copied them.
    llt_.compute(Eigen::MatrixXd::Zero(n, n));
    Jm_.resize(m, n);
    Y_.resize(m, n);
    normal_.resize(m, m);
    normal_llt_.compute(Eigen::MatrixXd::Zero(m, m));
    rhs_.resize(n);
    step_.resize(n);
    work_.resize(n);
    active_set_.resize(n);
    weights_.resize(kin_.num_residuals());
    // The tip Hessian over the movable angles only when some are fixed (a URDF joint's two locked
    // angles): their rows and columns of H count for nothing (modify_hessian() replaces them by
    // the identity's, and the step is 0 there), and the solver's J has no columns for them.
    position_.resize(n);
    fixed_angles_ = false;
    for (int i = 0; i < n; ++i) {
      const bool movable = kin_.lower()[i] < kin_.upper()[i];
      position_[i] = movable ? i : -1;
      fixed_angles_ = fixed_angles_ || !movable;
    }
    bones_.resize(kin_.num_bones());
  }

  // H_ += the weighted tip Hessian (weights: 3 x #effectors).
  void add_tip_hessian(const Eigen::Ref<const Eigen::VectorXd>& weights) {
    if (fixed_angles_)
      add_weighted_tip_hessian(kin_, weights, position_, bones_, H_);
    else
      add_weighted_tip_hessian(kin_, weights, H_);
  }

  void reset() override { damping_.reset(opt_.lm_initial_mu); }

  Progress iterate() override {
    if (num_free_ == 0) return Progress::stuck;
    kin_.forward(a_);  // the tip Hessian reads the pose; others may have posed kin_ since
    H_.noalias() = J_.transpose() * J_;
    if (goals_.plain()) {
      add_tip_hessian(r_);
    } else {
      tip_hessian_weights(goals_, r_, weights_);
      add_tip_hessian(weights_);
    }
    double s = 0;
    for (int c = 0; c < num_free_; ++c) s += std::abs(H_(free_[c], free_[c]));
    s /= num_free_;
    if (!std::isfinite(s)) return fail("the Hessian is not finite");
    if (!(s > 0)) return Progress::stuck;  // no free angle moves a tip
    const double relative_error2 = 2 * E_ / (reach_ * reach_);
    null_curvature_ = std::sqrt(relative_error2) * s;

    for (int attempt = 0; attempt < opt_.lm_max_rejections; ++attempt) {
      if (attempt > 0 && time_is_up()) return Progress::stuck;
      const double mu = damping_.shift(relative_error2, opt_.lm_damping_floor, s);
      switch (newton_step(mu)) {
        case Step::indefinite: damping_.grow_for_indefinite(); continue;
        case Step::not_finite: return fail("the Newton step is not finite");
        case Step::out_of_time: return Progress::stuck;
        case Step::ok: break;
      }
      if (trial_ == a_) return Progress::stuck;  // the step is 0
      const double E_trial = evaluate(trial_, r_trial_);
      // Gain ratio against the quadratic model g.d + d'H d / 2 of the step actually taken.
      step_ = trial_ - a_;
      work_.noalias() = H_ * step_;
      const double predicted = -(g_.dot(step_) + 0.5 * step_.dot(work_));
      if (damping_.accept(E_, E_trial, predicted)) {
        a_.swap(trial_);
        r_.swap(r_trial_);
        E_ = E_trial;
        return Progress::moved;
      }
    }
    return Progress::stuck;
  }

  // modified_ = H + f (I - P) on the angles with `mask` 1; the other rows and columns become those
  // of the identity. Returns false if J's row space could not be factorised.
  bool modify_hessian(const Eigen::VectorXd& mask) {
    Jm_.noalias() = J_ * mask.asDiagonal();
    normal_.noalias() = Jm_ * Jm_.transpose();
    const double trace = normal_.trace();
    normal_.diagonal().array() += 1e-12 * trace + std::numeric_limits<double>::min();
    normal_llt_.compute(normal_);
    if (normal_llt_.info() != Eigen::Success) return false;
    Y_ = Jm_;
    normal_llt_.solveInPlace(Y_);                                       // (Jm Jm^T)^-1 Jm
    modified_.noalias() = (-null_curvature_) * (Jm_.transpose() * Y_);  // -f P
    modified_ += H_;
    for (int i = 0; i < n_; ++i) {
      if (mask[i] != 0) {
        modified_(i, i) += null_curvature_;
        continue;
      }
      modified_.row(i).setZero();
      modified_.col(i).setZero();
      modified_(i, i) = 1;
    }
    return true;
  }

  enum class Step { ok, indefinite, not_finite, out_of_time };

  // trial_ = P(a_ + p) with (modified H + mu I) p = -g on the free angles; angles that would leave
  // their limits are fixed there and the rest re-solved (each round a factorisation of the size
  // of the rig: the rounds stop when the time budget runs out).
  Step newton_step(double mu) {
    rhs_ = -g_.cwiseProduct(free_mask_);
    Step failure = Step::ok;
    const Eigen::VectorXd& mask = active_set_.mask();
    const auto solve_system = [&] {
      if (!modify_hessian(mask)) {
        failure = Step::not_finite;
        return false;
      }
      shifted_ = modified_;
      shifted_.diagonal() += mu * mask;
      llt_.compute(shifted_);
      if (llt_.info() != Eigen::Success) {
        failure = Step::indefinite;
        return false;
      }
      work_ = rhs_.cwiseProduct(mask);
      llt_.solveInPlace(work_);
      return true;
    };
    const auto proposed = [&](int i) { return work_[i]; };
    const auto take_out = [&](int i, double step) { rhs_.noalias() -= step * H_.col(i); };
    switch (active_set_.run(a_, kin_.lower(), kin_.upper(), free_, num_free_, ActiveSet::Fix::past_limit, deadline(),
                            solve_system, proposed, take_out)) {
      case ActiveSet::Status::solve_failed: return failure;
      case ActiveSet::Status::out_of_time: gave_up_for_time(); return Step::out_of_time;
      case ActiveSet::Status::done: break;
    }
    Eigen::VectorXd& step = active_set_.step();
    if (!std::isfinite(cap_largest_change(step, opt_.newton_max_step_deg))) return Step::not_finite;
    trial_ = a_ + step;
    kin_.project(trial_);
    return Step::ok;
  }

  Eigen::MatrixXd H_, modified_, shifted_, Jm_, Y_, normal_;
  Eigen::LLT<Eigen::MatrixXd> llt_, normal_llt_;
  Eigen::VectorXd rhs_, step_, work_, weights_;  // weights_: the tip Hessian's (3 x #effectors)
  ActiveSet active_set_;
  std::vector<int> position_, bones_;  // the tip Hessian's angle positions (-1: fixed) and bone scratch
  bool fixed_angles_ = false;          // some angle is fixed (min >= max)
  NielsenDamping damping_;
  double null_curvature_ = 0;
};

}  // namespace

std::unique_ptr<Solver> make_newton_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<ProjectedNewton>(kin, options);
}

}  // namespace ik

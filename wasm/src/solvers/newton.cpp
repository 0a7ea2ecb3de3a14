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
// model (Nielsen's rule, as in lm.cpp), and grows 4x while the Cholesky factorisation fails (the
// matrix indefinite). An angle whose step would leave its limits is fixed on the limit and the
// rest re-solved; the step is capped at newton_max_step_deg per angle.
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

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
  int angle_limit(int /*residuals*/) const override { return kMaxDenseAngles; }
  void resize(int m, int n) override {
    H_.resize(n, n);
    modified_.resize(n, n);
    shifted_.resize(n, n);
    llt_ = Eigen::LLT<Eigen::MatrixXd>(n);
    Jm_.resize(m, n);
    Y_.resize(m, n);
    normal_.resize(m, m);
    normal_llt_ = Eigen::LLT<Eigen::MatrixXd>(m);
    rhs_.resize(n);
    step_.resize(n);
    work_.resize(n);
    mask_.resize(n);
  }

  void reset() override {
    m_factor_ = opt_.lm_initial_mu;
    nu_ = 2;
  }

  Progress iterate() override {
    if (num_free_ == 0) return Progress::stuck;
    kin_.forward(a_);  // the tip Hessian reads the pose; others may have posed kin_ since
    H_.noalias() = J_.transpose() * J_;
    add_weighted_tip_hessian(kin_, r_, H_);
    double s = 0;
    for (int c = 0; c < num_free_; ++c) s += std::abs(H_(free_[c], free_[c]));
    s /= num_free_;
    if (!std::isfinite(s)) return fail("the Hessian is not finite");
    if (!(s > 0)) return Progress::stuck;  // no free angle moves a tip
    const double relative_error2 = 2 * E_ / (reach_ * reach_);
    null_curvature_ = std::sqrt(relative_error2) * s;

    for (int attempt = 0; attempt < opt_.lm_max_rejections; ++attempt) {
      if (attempt > 0 && time_is_up()) return Progress::stuck;
      const double mu = (m_factor_ * relative_error2 + opt_.lm_damping_floor) * s;
      switch (newton_step(mu)) {
        case Step::indefinite:
          m_factor_ = std::min(4 * std::max(m_factor_, 1e-6), kMaxFactor);
          continue;
        case Step::not_finite:
          return fail("the Newton step is not finite");
        case Step::ok:
          break;
      }
      if (trial_ == a_) return Progress::stuck;  // the step is 0
      const double E_trial = evaluate(trial_, r_trial_);
      // Gain ratio against the quadratic model g.d + d'H d / 2 of the step actually taken.
      step_ = trial_ - a_;
      work_.noalias() = H_ * step_;
      const double predicted = -(g_.dot(step_) + 0.5 * step_.dot(work_));
      const double rho = (E_ - E_trial) / predicted;
      if (std::isfinite(E_trial) && E_trial < E_ && predicted > 0 && rho > kMinGain) {
        m_factor_ = std::max(m_factor_ * std::max(1.0 / 3, 1 - std::pow(2 * rho - 1, 3)), kMinFactor);
        nu_ = 2;
        a_.swap(trial_);
        r_.swap(r_trial_);
        E_ = E_trial;
        return Progress::moved;
      }
      m_factor_ = std::min(m_factor_ * nu_, kMaxFactor);
      nu_ = std::min(2 * nu_, 64.0);
    }
    return Progress::stuck;
  }

  // modified_ = H + f (I - P) on the angles with mask_ 1; the other rows and columns become those
  // of the identity. Returns false if J's row space could not be factorised.
  bool modify_hessian() {
    Jm_.noalias() = J_ * mask_.asDiagonal();
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
      if (mask_[i] != 0) {
        modified_(i, i) += null_curvature_;
        continue;
      }
      modified_.row(i).setZero();
      modified_.col(i).setZero();
      modified_(i, i) = 1;
    }
    return true;
  }

  enum class Step { ok, indefinite, not_finite };

  // trial_ = P(a_ + p) with (modified H + mu I) p = -g on the free angles; angles that would leave
  // their limits are fixed there and the rest re-solved.
  Step newton_step(double mu) {
    mask_ = free_mask_;
    rhs_ = -g_.cwiseProduct(mask_);
    step_.setZero();
    for (int pass = 0; pass < kActiveSetPasses; ++pass) {
      if (!modify_hessian()) return Step::not_finite;
      shifted_ = modified_;
      shifted_.diagonal() += mu * mask_;
      llt_.compute(shifted_);
      if (llt_.info() != Eigen::Success) return Step::indefinite;
      work_ = rhs_.cwiseProduct(mask_);
      llt_.solveInPlace(work_);
      bool clipped_more = false;
      for (int c = 0; c < num_free_; ++c) {
        const int i = free_[c];
        if (mask_[i] == 0) continue;
        const double to = a_[i] + work_[i];
        if (to < kin_.lower()[i] || to > kin_.upper()[i]) {
          step_[i] = (to < kin_.lower()[i] ? kin_.lower()[i] : kin_.upper()[i]) - a_[i];
          mask_[i] = 0;
          clipped_more = true;
          rhs_.noalias() -= step_[i] * H_.col(i);  // this angle now moves by a known amount
        } else {
          step_[i] = work_[i];
        }
      }
      if (!clipped_more) break;
    }
    if (!std::isfinite(cap_largest_change(step_, opt_.newton_max_step_deg))) return Step::not_finite;
    trial_ = a_ + step_;
    kin_.project(trial_);
    return Step::ok;
  }

  static constexpr int kActiveSetPasses = 4;
  static constexpr double kMinGain = 1e-4;
  static constexpr double kMinFactor = 1e-12;
  static constexpr double kMaxFactor = 1e16;
  Eigen::MatrixXd H_, modified_, shifted_, Jm_, Y_, normal_;
  Eigen::LLT<Eigen::MatrixXd> llt_, normal_llt_;
  Eigen::VectorXd rhs_, step_, work_, mask_;
  double m_factor_ = 1, nu_ = 2, null_curvature_ = 0;
};

}  // namespace

std::unique_ptr<Solver> make_newton_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<ProjectedNewton>(kin, options);
}

}  // namespace ik

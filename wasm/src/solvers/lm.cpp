// Levenberg-Marquardt, solved at the residual size (3 x #effectors):
//   step on the free angles  d = -W Jf^T (Jf W Jf^T + lambda I)^-1 r
// (W: 1 on the angles, root_unit^2 on a floating root's translation: the least change that
// meets the linearised goals, the root's move counted in units of root_unit)
// with error-dependent damping lambda = (mu |r|^2 / reach^2 + lm_damping_floor) * s, s the mean
// diagonal of Jf Jf^T (so lambda shrinks like |r|^2 and the local convergence is quadratic even
// where J is rank-deficient), and mu adapted from the gain ratio rho = actual / predicted
// decrease (Nielsen's rule, damping.h). Bounds are handled inside the step: an angle whose step
// would leave its limits is fixed on the limit and the rest re-solved (active_set.h); angles that
// are fixed or pushed outward by grad E are not in Jf at all.
//
// With orientation goals (goals.h) the residual is made of 3-row blocks, each an effector's
// position or orientation; the sparsity below is per block (a block's rows move with the angles
// on its effector's chain; a pole's, with its limb's chain; a rest bone's, with that bone's
// angles). Plain goals have one position block per effector, as before.
//
// A preferred move d0 (Solver::set_preferred_move()) joins the solve's first step: the system's
// right-hand side becomes r + Jf d0 and the step d0 + (the step above), so that the linearised
// goals see none of d0; an angle fixed on a limit takes its known move out as d - d0_i. A first
// trial that it makes worse is tried again without it.
//
// Restarts after a stall (option `restarts`) are the base Solver's, as for every method.
#include <cmath>
#include <memory>
#include <vector>

#include "active_set.h"
#include "damped_system.h"
#include "damping.h"
#include "solver.h"

namespace ik {

namespace {

class LevenbergMarquardt final : public Solver {
 public:
  using Solver::Solver;
  // |r| below this share of the reach is round-off: no step is tried.
  static constexpr double kRoundOffShare = 1e-12;
  const char* name() const override { return "lm"; }

 private:
  void resize(int m, int n) override {
    normal_.resize(m, m);
    system_.resize(m);
    jd_.resize(m);
    rhs_.resize(m);
    active_set_.resize(n);
  }

  void reset() override { damping_.reset(opt_.lm_initial_mu); }

  Progress iterate() override {
    const int nf = num_free_;
    if (nf == 0) return Progress::stuck;
    // An error at round-off (a tracked frame whose targets did not move, polished because of
    // min_iterations) leaves no decrease to find: every trial would be rejected, each costing a
    // factorisation (10 of them a frame on the avatar's still frames). Checked before Jf Jf^T is
    // built, which such a frame does not need either.
    const double relative_error2 = 2 * E_ / (reach_ * reach_);
    if (relative_error2 < kRoundOffShare * kRoundOffShare) return Progress::stuck;
    // Jf Jf^T from the 3x1 blocks of J that can be non-zero (block_pattern.h).
    normal_.setZero();
    for (int c = 0; c < nf; ++c) {
      if (c % 64 == 63 && time_is_up()) return Progress::stuck;
      pattern_.accumulate(J_, free_[c], normal_);
    }
    pattern_.symmetrize(normal_);
    // The mean over the rows in use: soft rows the Solver dropped (all 0) do not count.
    const double s = normal_.trace() / (goals_.soft_on() ? m_ : goals_.hard_rows());
    if (!std::isfinite(s)) return fail("the Jacobian is not finite");
    if (!(s > 0)) return Progress::stuck;  // no free angle moves a tip

    const Eigen::VectorXd* preferred = preferred_move();
    mark_preferred_move_used();
    for (int attempt = 0; attempt < opt_.lm_max_rejections; ++attempt) {
      if (attempt > 0 && time_is_up()) return Progress::stuck;
      const double lambda = damping_.shift(relative_error2, opt_.lm_damping_floor, s);
      switch (damped_step(lambda, attempt == 0 ? preferred : nullptr)) {
        case Step::failed: return fail("the damped normal matrix could not be factorised");
        case Step::out_of_time: return Progress::stuck;
        case Step::ok: break;
      }
      if (trial_ == a_) return Progress::stuck;  // the step is 0
      const double E_trial = evaluate(trial_, r_trial_);
      // Gain ratio: actual decrease over the decrease the linear model predicts for the
      // (projected) step taken.
      jd_.setZero();
      for (int c = 0; c < nf; ++c) pattern_.add(J_, free_[c], trial_[free_[c]] - a_[free_[c]], jd_);
      const double predicted = -r_.dot(jd_) - 0.5 * jd_.squaredNorm();
      if (damping_.accept(E_, E_trial, predicted)) {
        a_.swap(trial_);
        r_.swap(r_trial_);
        E_ = E_trial;
        return Progress::moved;
      }
    }
    return Progress::stuck;
  }

  enum class Step { ok, failed, out_of_time };

  // Writes trial_ = P(a_ + d) for the damped step d with `lambda` (with `preferred`, d0 + that
  // step: the header), bounds handled by the active set. Fails if the factorisation failed; stops
  // when the time budget ran out (on a rig of thousands of angles, taking fixed columns out costs
  // as much as building the matrix).
  Step damped_step(double lambda, const Eigen::VectorXd* preferred) {
    // (Jf W Jf^T + lambda I) y = r + Jf d0 over the angles still in the set.
    if (preferred) {
      rhs_ = r_;
      for (int c = 0; c < num_free_; ++c) pattern_.add(J_, free_[c], (*preferred)[free_[c]], rhs_);
    }
    system_.begin(normal_, preferred ? rhs_ : r_);
    system_.shift().setConstant(lambda);
    const auto solve_system = [&] { return system_.solve(); };
    const auto d0 = [&](int i) { return preferred ? (*preferred)[i] : 0.0; };
    // Angle i's step d0_i - w_i (Jf^T y)_i (w_i: its column's weight, BlockPattern::weight).
    const auto proposed = [&](int i) { return d0(i) - pattern_.weight(i) * pattern_.dot(J_, i, system_.y()); };
    // Angle i moves by a known d: its column leaves the system (the right-hand side held d0_i of it).
    const auto take_out = [&](int i, double d) { system_.take_out(pattern_, J_, i, d - d0(i)); };
    switch (active_set_.run(a_, kin_.lower(), kin_.upper(), free_, num_free_, ActiveSet::Fix::past_limit, deadline(),
                            solve_system, proposed, take_out)) {
      case ActiveSet::Status::solve_failed: return Step::failed;
      case ActiveSet::Status::out_of_time: gave_up_for_time(); return Step::out_of_time;
      case ActiveSet::Status::done: break;
    }
    trial_ = a_;
    for (int c = 0; c < num_free_; ++c) trial_[free_[c]] += active_set_.step()[free_[c]];
    kin_.project(trial_);
    return Step::ok;
  }

  Eigen::MatrixXd normal_;
  DampedSystem system_;
  Eigen::VectorXd jd_, rhs_;
  ActiveSet active_set_;
  NielsenDamping damping_;
};

}  // namespace

std::unique_ptr<Solver> make_lm_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<LevenbergMarquardt>(kin, options);
}

}  // namespace ik

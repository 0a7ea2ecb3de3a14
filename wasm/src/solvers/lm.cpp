// Levenberg-Marquardt, solved at the residual size (3 x #effectors):
//   step on the free angles  d = -Jf^T (Jf Jf^T + lambda I)^-1 r
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
// Restarts after a stall (option `restarts`) are the base Solver's, as for every method.
#include <cmath>
#include <memory>
#include <vector>

#include "active_set.h"
#include "damping.h"
#include "small_cholesky.h"
#include "solver.h"

namespace ik {

namespace {

class LevenbergMarquardt final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "lm"; }

 private:
  void resize(int m, int n) override {
    // Per angle, the residual blocks it moves (those of the effectors whose chain holds its
    // bone), ascending: counted per bone, then filled block by block.
    // Soft blocks (poles, rest bones) count like the goals' blocks (GoalSet::moving_bones()).
    const int blocks = m / 3;
    std::vector<int> per_bone(kin_.num_bones() + 1, 0), moving;
    for (int k = 0; k < blocks; ++k) {
      goals_.moving_bones(kin_, k, moving);
      for (int b : moving) ++per_bone[b + 1];
    }
    for (int b = 0; b < kin_.num_bones(); ++b) per_bone[b + 1] += per_bone[b];
    std::vector<int> bone_effectors(per_bone.back()), fill(per_bone.begin(), per_bone.end() - 1);
    for (int k = 0; k < blocks; ++k) {
      goals_.moving_bones(kin_, k, moving);
      for (int b : moving) bone_effectors[fill[b]++] = k;
    }
    column_start_.assign(n + 1, 0);
    column_effectors_.clear();
    for (int j = 0; j < n; ++j) {
      column_start_[j] = static_cast<int>(column_effectors_.size());
      column_effectors_.insert(column_effectors_.end(), bone_effectors.begin() + per_bone[j / 3],
                               bone_effectors.begin() + per_bone[j / 3 + 1]);
    }
    column_start_[n] = static_cast<int>(column_effectors_.size());
    normal_.resize(m, m);
    reduced_.resize(m, m);
    shifted_.resize(m, m);
    y_.resize(m);
    rhs_.resize(m);
    jd_.resize(m);
    active_set_.resize(n);
  }

  void reset() override { damping_.reset(opt_.lm_initial_mu); }

  Progress iterate() override {
    const int nf = num_free_;
    if (nf == 0) return Progress::stuck;
    // Jf Jf^T from the 3x1 blocks of J that can be non-zero: column j of J moves only the tips
    // of the effectors whose chain holds j's bone.
    normal_.setZero();
    for (int c = 0; c < nf; ++c) {
      if (c % 64 == 63 && time_is_up()) return Progress::stuck;
      const int j = free_[c];
      for (int p = column_start_[j]; p < column_start_[j + 1]; ++p) {
        const int e = column_effectors_[p];
        for (int q = p; q < column_start_[j + 1]; ++q) {
          const int f = column_effectors_[q];
          normal_.block<3, 3>(3 * e, 3 * f).noalias() += block(e, j) * block(f, j).transpose();
        }
      }
    }
    for (int e = 0; e < m_ / 3; ++e)
      for (int f = e + 1; f < m_ / 3; ++f) normal_.block<3, 3>(3 * f, 3 * e) = normal_.block<3, 3>(3 * e, 3 * f).transpose();
    // The mean over the rows in use: soft rows the Solver dropped (all 0) do not count.
    const double s = normal_.trace() / (goals_.soft_on() ? m_ : goals_.hard_rows());
    if (!std::isfinite(s)) return fail("the Jacobian is not finite");
    if (!(s > 0)) return Progress::stuck;  // no free angle moves a tip
    const double relative_error2 = 2 * E_ / (reach_ * reach_);

    for (int attempt = 0; attempt < opt_.lm_max_rejections; ++attempt) {
      if (attempt > 0 && time_is_up()) return Progress::stuck;
      const double lambda = damping_.shift(relative_error2, opt_.lm_damping_floor, s);
      switch (damped_step(lambda)) {
        case Step::failed: return fail("the damped normal matrix could not be factorised");
        case Step::out_of_time: return Progress::stuck;
        case Step::ok: break;
      }
      if (trial_ == a_) return Progress::stuck;  // the step is 0
      const double E_trial = evaluate(trial_, r_trial_);
      // Gain ratio: actual decrease over the decrease the linear model predicts for the
      // (projected) step taken.
      jd_.setZero();
      for (int c = 0; c < nf; ++c) {
        const int j = free_[c];
        const double d = trial_[j] - a_[j];
        for (int p = column_start_[j]; p < column_start_[j + 1]; ++p)
          jd_.segment<3>(3 * column_effectors_[p]) += d * block(column_effectors_[p], j);
      }
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

  // The 3x1 block of J: residual block e (an effector's tip, or its orientation) against angle j.
  Eigen::Block<Eigen::MatrixXd, 3, 1> block(int e, int j) { return J_.block<3, 1>(3 * e, j); }

  enum class Step { ok, failed, out_of_time };

  // Writes trial_ = P(a_ + d) for the damped step d with `lambda`, bounds handled by the active
  // set. Fails if the factorisation failed; stops when the time budget ran out (on a rig of
  // thousands of angles, taking fixed columns out costs as much as building the matrix).
  Step damped_step(double lambda) {
    reduced_ = normal_;
    rhs_ = r_;
    // (Jf Jf^T + lambda I) y = rhs over the angles still in the set.
    const auto solve_system = [&] {
      shifted_ = reduced_;
      shifted_.diagonal().array() += lambda;
      if (!small_cholesky(shifted_, m_)) return false;
      y_ = rhs_;
      small_cholesky_solve(shifted_, m_, y_);
      return true;
    };
    // Angle i's step -(Jf^T y)_i.
    const auto proposed = [&](int i) {
      double d = 0;
      for (int p = column_start_[i]; p < column_start_[i + 1]; ++p)
        d -= block(column_effectors_[p], i).dot(y_.segment<3>(3 * column_effectors_[p]));
      return d;
    };
    // Angle i moves by a known d: its column leaves the system.
    const auto take_out = [&](int i, double d) {
      for (int p = column_start_[i]; p < column_start_[i + 1]; ++p) {
        const int e = column_effectors_[p];
        rhs_.segment<3>(3 * e) += d * block(e, i);
        for (int q = column_start_[i]; q < column_start_[i + 1]; ++q) {
          const int f = column_effectors_[q];
          reduced_.block<3, 3>(3 * e, 3 * f).noalias() -= block(e, i) * block(f, i).transpose();
        }
      }
    };
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

  // Per angle j: the residual blocks it moves, column_effectors_[start[j]..start[j+1]).
  std::vector<int> column_start_, column_effectors_;
  Eigen::MatrixXd normal_, reduced_, shifted_;
  Eigen::VectorXd y_, rhs_, jd_;
  ActiveSet active_set_;
  NielsenDamping damping_;
};

}  // namespace

std::unique_ptr<Solver> make_lm_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<LevenbergMarquardt>(kin, options);
}

}  // namespace ik

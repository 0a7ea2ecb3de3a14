// Levenberg-Marquardt, solved at the residual size (3 x #effectors):
//   step on the free angles  d = -Jf^T (Jf Jf^T + lambda I)^-1 r
// with error-dependent damping lambda = (mu |r|^2 / reach^2 + lm_damping_floor) * s, s the mean
// diagonal of Jf Jf^T (so lambda shrinks like |r|^2 and the local convergence is quadratic even
// where J is rank-deficient), and mu adapted from the gain ratio rho = actual / predicted
// decrease (Nielsen's rule). Bounds are handled inside the step: an angle whose step would
// leave its limits is fixed on the limit and the rest re-solved (a few active-set passes);
// angles that are fixed or pushed outward by grad E are not in Jf at all.
//
// Restarts after a stall (option `restarts`) are the base Solver's, as for every method.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

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
    // Per angle, the effectors whose tips it moves (those whose chain holds its bone), ascending:
    // counted per bone, then filled effector by effector.
    std::vector<int> per_bone(kin_.num_bones() + 1, 0);
    for (int e = 0; e < kin_.num_effectors(); ++e)
      for (int b : kin_.effector_chain(e)) ++per_bone[b + 1];
    for (int b = 0; b < kin_.num_bones(); ++b) per_bone[b + 1] += per_bone[b];
    std::vector<int> bone_effectors(per_bone.back()), fill(per_bone.begin(), per_bone.end() - 1);
    for (int e = 0; e < kin_.num_effectors(); ++e)
      for (int b : kin_.effector_chain(e)) bone_effectors[fill[b]++] = e;
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
    delta_.resize(n);
    clipped_.assign(n, 0);
  }

  void reset() override {
    mu_ = opt_.lm_initial_mu;
    nu_ = 2;
  }

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
    const double s = normal_.trace() / m_;
    if (!std::isfinite(s)) return fail("the Jacobian is not finite");
    if (!(s > 0)) return Progress::stuck;  // no free angle moves a tip
    const double relative_error2 = 2 * E_ / (reach_ * reach_);

    for (int attempt = 0; attempt < opt_.lm_max_rejections; ++attempt) {
      if (attempt > 0 && time_is_up()) return Progress::stuck;
      const double lambda = (mu_ * relative_error2 + opt_.lm_damping_floor) * s;
      switch (damped_step(lambda, nf)) {
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
      const double rho = (E_ - E_trial) / predicted;
      if (std::isfinite(E_trial) && E_trial < E_ && predicted > 0 && rho > kMinGain) {
        mu_ *= std::max(1.0 / 3, 1 - std::pow(2 * rho - 1, 3));
        mu_ = std::max(mu_, kMinMu);
        nu_ = 2;
        a_.swap(trial_);
        r_.swap(r_trial_);
        E_ = E_trial;
        return Progress::moved;
      }
      mu_ = std::min(mu_ * nu_, kMaxMu);
      nu_ = std::min(2 * nu_, kMaxNu);
    }
    return Progress::stuck;
  }

  // The 3x1 block of J: effector e's tip against angle j.
  Eigen::Block<Eigen::MatrixXd, 3, 1> block(int e, int j) { return J_.block<3, 1>(3 * e, j); }

  enum class Step { ok, failed, out_of_time };

  // Writes trial_ = P(a_ + d) for the damped step d with `lambda`, bounds handled by the active
  // set. Fails if the factorisation failed; stops when the time budget ran out (on a rig of
  // thousands of angles, taking clipped columns out costs as much as building the matrix).
  Step damped_step(double lambda, int nf) {
    reduced_ = normal_;
    rhs_ = r_;
    std::fill(clipped_.begin(), clipped_.begin() + nf, 0);
    for (int pass = 0; pass < kActiveSetPasses; ++pass) {
      shifted_ = reduced_;
      shifted_.diagonal().array() += lambda;
      if (!small_cholesky(shifted_, m_)) return Step::failed;
      y_ = rhs_;
      small_cholesky_solve(shifted_, m_, y_);
      bool clipped_more = false;
      for (int c = 0; c < nf; ++c) {
        if (c % 64 == 63 && time_is_up()) return Step::out_of_time;
        if (clipped_[c]) continue;
        const int i = free_[c];
        double d = 0;  // -(Jf^T y)_c
        for (int p = column_start_[i]; p < column_start_[i + 1]; ++p)
          d -= block(column_effectors_[p], i).dot(y_.segment<3>(3 * column_effectors_[p]));
        const double to = a_[i] + d;
        if (to < kin_.lower()[i] || to > kin_.upper()[i]) {
          d = (to < kin_.lower()[i] ? kin_.lower()[i] : kin_.upper()[i]) - a_[i];
          clipped_[c] = 1;
          clipped_more = true;
          // This angle now moves by a known d: take its column out of the system.
          for (int p = column_start_[i]; p < column_start_[i + 1]; ++p) {
            const int e = column_effectors_[p];
            rhs_.segment<3>(3 * e) += d * block(e, i);
            for (int q = column_start_[i]; q < column_start_[i + 1]; ++q) {
              const int f = column_effectors_[q];
              reduced_.block<3, 3>(3 * e, 3 * f).noalias() -= block(e, i) * block(f, i).transpose();
            }
          }
        }
        delta_[c] = d;
      }
      if (!clipped_more) break;
    }
    trial_ = a_;
    for (int c = 0; c < nf; ++c) trial_[free_[c]] += delta_[c];
    kin_.project(trial_);
    return Step::ok;
  }

  static constexpr int kActiveSetPasses = 4;
  static constexpr double kMinGain = 1e-4;
  static constexpr double kMinMu = 1e-12;
  static constexpr double kMaxMu = 1e16;
  static constexpr double kMaxNu = 64;

  std::vector<int> column_start_, column_effectors_;  // per angle j: column_effectors_[start[j]..start[j+1])
  Eigen::MatrixXd normal_, reduced_, shifted_;
  Eigen::VectorXd y_, rhs_, jd_, delta_;
  std::vector<char> clipped_;
  double mu_ = 1, nu_ = 2;
};

}  // namespace

std::unique_ptr<Solver> make_lm_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<LevenbergMarquardt>(kin, options);
}

}  // namespace ik

// Damped BFGS with gradient projection: p = -H grad E with H the inverse-Hessian estimate, then
// projected Armijo backtracking from alpha = 1. The update is Powell's damped one (PROTOCOL.md):
//   theta = 1 if s'y >= 0.2 s'Bs, else 0.8 s'Bs / (s'Bs - s'y);  r = theta y + (1 - theta) B s
//   B <- B - B s s'B / s'Bs + r r' / s'r,   H <- (I - rho s r') H (I - rho r s') + rho s s',  rho = 1 / s'r
// B and H are both kept, over the k angles that can move only (O(k^2) each), so s'Bs needs no
// solve. Paper mode starts from H = I and uses the full gradient. Outside it, H starts as the
// inverse diagonal of J^T J, angles pushed against a bound are left out of the direction, and a
// failed search restarts the estimate.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "size_limits.h"
#include "solver.h"

namespace ik {

namespace {

class DampedBfgs final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "bfgs"; }

 private:
  int angle_limit(int /*residuals*/) const override { return kMaxDenseAngles; }
  // H and B cover the movable angles only (min < max): a fixed angle never moves, so its rows
  // would only cost time (the lamp has 4 movable angles of 15, the beast 41 of 66). Paper mode
  // loses nothing by it: the original's finite differences give a fixed angle a zero gradient,
  // and from H = I its row of H stays that of the identity.
  void resize(int /*residuals*/, int n) override {
    movable_.clear();
    for (int i = 0; i < n; ++i)
      if (kin_.lower()[i] < kin_.upper()[i]) movable_.push_back(i);
    const int k = static_cast<int>(movable_.size());
    H_.resize(k, k);
    B_.resize(k, k);
    for (Eigen::VectorXd* v : {&compact_direction_, &s_, &y_, &g_old_, &Bs_, &r_update_, &Hr_, &gf_, &mask_})
      v->resize(k);
    direction_.setZero(n);
  }

  void reset() override {
    fresh_ = true;  // H is set from J at the first iteration
    have_pair_ = false;
  }

  Progress iterate() override {
    if (fresh_)
      start_curvature();
    else if (have_pair_)
      update();
    // The gradient over the movable angles; outside paper mode without the angles that are
    // pushed against a bound.
    for (int j = 0; j < size(); ++j) {
      mask_[j] = opt_.paper_mode ? 1.0 : free_mask_[movable_[j]];
      gf_[j] = g_[movable_[j]] * mask_[j];
    }
    free_direction();
    if (!opt_.paper_mode && !(compact_direction_.dot(gf_) < 0)) {  // not a descent direction: forget the curvature
      start_curvature();
      free_direction();
    }
    bool moved = backtrack(direction_, 1, opt_.armijo_c1);
    if (!moved && !opt_.paper_mode && learned_) {  // H had learned curvature: retry from the start
      start_curvature();
      free_direction();
      moved = backtrack(direction_, 1, opt_.armijo_c1);
    }
    if (!moved) return Progress::stuck;
    for (int j = 0; j < size(); ++j) {
      s_[j] = a_[movable_[j]] - trial_[movable_[j]];  // trial_ holds the previous angles
      g_old_[j] = g_[movable_[j]];
    }
    have_pair_ = true;
    return Progress::moved;
  }

  int size() const { return static_cast<int>(movable_.size()); }

  // direction_ = -H gf on the free movable angles, 0 elsewhere.
  void free_direction() {
    compact_direction_.noalias() = H_ * gf_;
    compact_direction_ = -compact_direction_.cwiseProduct(mask_);
    for (int j = 0; j < size(); ++j) direction_[movable_[j]] = compact_direction_[j];
  }

  // The first curvature estimate. Paper mode: H = B = I, as the original. Otherwise the
  // diagonal of the Gauss-Newton Hessian J^T J, B = diag(|J_i|^2) and H = B^-1, so the first
  // step already has the right scale per angle (degrees on a 0.2-unit finger and on a 45-unit
  // leg differ by orders of magnitude in effect).
  void start_curvature() {
    fresh_ = false;
    learned_ = false;
    have_pair_ = false;
    H_.setIdentity();
    B_.setIdentity();
    if (opt_.paper_mode || size() == 0) return;
    // Angles that barely move a tip would get a huge 1/d: floor d at a share of the mean.
    double mean = 0;
    for (int i : movable_) mean += J_.col(i).squaredNorm();
    mean /= size();
    for (int j = 0; j < size(); ++j) {
      const double d = std::max(J_.col(movable_[j]).squaredNorm(), kDiagonalFloor * mean);
      if (!(d > 0) || !std::isfinite(d)) continue;
      B_(j, j) = d;
      H_(j, j) = 1 / d;
    }
  }

  // The damped update with the last step s_ and the gradient change y = g - g_old over the
  // movable angles.
  void update() {
    for (int j = 0; j < size(); ++j) y_[j] = g_[movable_[j]] - g_old_[j];
    const double sy = s_.dot(y_);
    learned_ = true;
    Bs_.noalias() = B_ * s_;
    const double sBs = s_.dot(Bs_);
    if (!(sBs > 0)) return;  // s = 0: nothing learned
    const double theta = sy >= 0.2 * sBs ? 1.0 : 0.8 * sBs / (sBs - sy);
    r_update_ = theta * y_ + (1 - theta) * Bs_;
    const double sr = s_.dot(r_update_);
    if (!(sr > 0)) return;
    B_.noalias() -= (Bs_ / sBs) * Bs_.transpose();
    B_.noalias() += (r_update_ / sr) * r_update_.transpose();
    // H <- H - rho (s (H r)' + (H r) s') + (rho^2 r'H r + rho) s s'
    const double rho = 1 / sr;
    Hr_.noalias() = H_ * r_update_;
    const double rHr = r_update_.dot(Hr_);
    H_.noalias() -= (rho * s_) * Hr_.transpose();
    H_.noalias() -= (rho * Hr_) * s_.transpose();
    H_.noalias() += ((rho * rho * rHr + rho) * s_) * s_.transpose();
  }

  static constexpr double kDiagonalFloor = 0.1;  // of the mean |J_i|^2
  std::vector<int> movable_;  // the angles with min < max; H, B and the compact vectors follow its order
  Eigen::MatrixXd H_, B_;
  Eigen::VectorXd direction_;  // over all angles
  Eigen::VectorXd compact_direction_, s_, y_, g_old_, Bs_, r_update_, Hr_, gf_, mask_;
  bool have_pair_ = false;  // s_ and g_old_ hold the last step
  bool fresh_ = true;       // the next iteration starts the curvature estimate
  bool learned_ = false;    // H holds at least one update
};

}  // namespace

std::unique_ptr<Solver> make_bfgs_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<DampedBfgs>(kin, options);
}

}  // namespace ik

// Damped BFGS with gradient projection: p = -H grad E with H the inverse-Hessian estimate, then
// projected Armijo backtracking from alpha = 1. The update is Powell's damped one (PROTOCOL.md):
//   theta = 1 if s'y >= 0.2 s'Bs, else 0.8 s'Bs / (s'Bs - s'y);  r = theta y + (1 - theta) B s
//   B <- B - B s s'B / s'Bs + r r' / s'r,   H <- (I - rho s r') H (I - rho r s') + rho s s',  rho = 1 / s'r
// B and H are both kept (O(n^2) each), so s'Bs needs no solve. Paper mode starts from H = I and
// uses the full gradient. Outside it, H is first scaled by s'y / y'y (Nocedal & Wright 6.20),
// angles that cannot move are left out of the direction, and a failed search restarts from H = I.
#include <memory>

#include "solver.h"

namespace ik {

namespace {

class DampedBfgs final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "bfgs"; }

 private:
  void resize(int /*residuals*/, int n) override {
    H_.resize(n, n);
    B_.resize(n, n);
    for (Eigen::VectorXd* v : {&direction_, &s_, &y_, &g_old_, &Bs_, &r_update_, &Hr_, &gf_}) v->resize(n);
  }

  void reset() override {
    H_.setIdentity();
    B_.setIdentity();
    have_pair_ = false;
    scaled_ = false;
  }

  Progress iterate() override {
    if (have_pair_) update();
    if (opt_.paper_mode) {
      direction_.noalias() = H_ * g_;
      direction_ *= -1;
    } else {
      gf_ = g_.cwiseProduct(free_mask_);
      direction_.noalias() = H_ * gf_;
      direction_ = -direction_.cwiseProduct(free_mask_);
      if (!(direction_.dot(gf_) < 0)) {  // not a descent direction: forget the curvature
        reset();
        direction_ = -gf_;
      }
    }
    bool moved = backtrack(direction_, 1, opt_.armijo_c1);
    if (!moved && !opt_.paper_mode && scaled_) {  // H had learned curvature: retry downhill
      reset();
      direction_ = -gf_;
      moved = backtrack(direction_, 1, opt_.armijo_c1);
    }
    if (!moved) return Progress::stuck;
    s_ = a_ - trial_;  // trial_ holds the previous angles
    g_old_ = g_;
    have_pair_ = true;
    return Progress::moved;
  }

  // The damped update with the last step s_ and the gradient change y = g - g_old.
  void update() {
    y_ = g_ - g_old_;
    const double sy = s_.dot(y_);
    if (!opt_.paper_mode && !scaled_ && sy > 0) {
      const double gamma = sy / y_.squaredNorm();  // H0 = gamma I, B0 = I / gamma
      H_ *= gamma;
      B_ /= gamma;
    }
    scaled_ = true;
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

  Eigen::MatrixXd H_, B_;
  Eigen::VectorXd direction_, s_, y_, g_old_, Bs_, r_update_, Hr_, gf_;
  bool have_pair_ = false;
  bool scaled_ = false;
};

}  // namespace

std::unique_ptr<Solver> make_bfgs_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<DampedBfgs>(kin, options);
}

}  // namespace ik

// Gauss-Newton: p = -pinv(J) r through the SVD of J, then projected backtracking from alpha = 1
// (factor 0.5, sufficient decrease c1 = 1e-3 on the projected point), as the report.
// Outside paper mode the pseudo-inverse comes from the eigen-decomposition of J J^T, at the
// residual size (3 x #effectors), and drops singular values below gn_singular_cutoff times the
// largest (a nearly singular J otherwise sends the step far along its weakest direction). The
// step uses the free angles only (not fixed, not pushed against a bound by grad E); angles on a
// limit that the step would push further out are held and the rest re-solved; and if that
// projected path finds no lower point, every angle the step would take past a limit is fixed on
// it and the rest re-solved, so the step stays inside the box (active_set.h). Either step is
// scaled down to move no angle more than gn_max_step_deg. With soft rows (goals.h) past 48 rows
// the step solves damped normal equations at the angle size instead (angle_size_direction()).
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include "active_set.h"
#include "line_search.h"
#include "size_limits.h"
#include "solver.h"

namespace ik {

namespace {

class GaussNewton final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "gn"; }

 private:
  // The SVD of the whole Jacobian (paper mode, or more than kMaxResiduals residuals) grows with
  // #angles times #residuals squared.
  int angle_limit(int residuals) const override {
    return residuals > kMaxResiduals ? dense_angle_limit(residuals) : kNoAngleLimit;
  }

  void resize(int residuals, int angles) override {
    jac_.resize(residuals, angles);
    svd_ = Eigen::JacobiSVD<Eigen::MatrixXd>(residuals, angles, Eigen::ComputeThinU | Eigen::ComputeThinV);
    projected_.resize(std::min(residuals, angles));
    direction_.resize(angles);
    all_angles_ = Eigen::VectorXd::Ones(angles);
    active_set_.resize(angles);
    rhs_.resize(residuals);
    columns_.resize(angles);
    step_k_.resize(angles);
    if (residuals <= kMaxResiduals) {
      normal_.resize(residuals, residuals);
      projected_m_.resize(residuals);
      y_.resize(residuals);
    } else {
      angle_normal_.resize(angles, angles);
      // Sized by factorising a zero matrix (it stops at the first pivot), so compute() allocates
      // nothing; not by assigning Eigen::LLT<Eigen::MatrixXd>(angles), which copied the info() and
      // norm that Eigen's sizing constructor leaves uninitialised.
      angle_llt_.compute(Eigen::MatrixXd::Zero(angles, angles));
    }
  }

  Progress iterate() override {
    if (opt_.paper_mode) {  // the original: the full J, the step projected by the line search
      if (!gauss_newton_direction(all_angles_, r_)) return fail("the SVD of the Jacobian is not finite");
      return backtrack(direction_, 1, opt_.armijo_c1) ? Progress::moved : Progress::stuck;
    }
    // The free angles only, first along the projected path of the Gauss-Newton step with the
    // angles it would push out of a limit they sit on held there; if no point of that path is
    // lower, with every angle the full step would take past a limit fixed on the limit and the
    // others re-solved for the residual that remains (the step then stays inside the box).
    switch (free_direction(ActiveSet::Fix::on_limit_only)) {
      case ActiveSet::Status::solve_failed: return fail("the SVD of the Jacobian is not finite");
      case ActiveSet::Status::out_of_time: gave_up_for_time(); return Progress::stuck;
      case ActiveSet::Status::done: break;
    }
    Eigen::VectorXd& step = active_set_.step();
    cap_largest_change(step, opt_.gn_max_step_deg);
    if (backtrack(step, 1, opt_.armijo_c1)) return Progress::moved;
    switch (free_direction(ActiveSet::Fix::past_limit)) {
      case ActiveSet::Status::solve_failed: return fail("the SVD of the Jacobian is not finite");
      case ActiveSet::Status::out_of_time: gave_up_for_time(); return Progress::stuck;
      case ActiveSet::Status::done: break;
    }
    cap_largest_change(step, opt_.gn_max_step_deg);
    return backtrack(step, 1, opt_.armijo_c1) ? Progress::moved : Progress::stuck;
  }

  // active_set_.step() on the free angles, fixing the angles `fix` says on their limits; each
  // round solves a system of the rig's size, and the rounds stop when the time budget runs out.
  ActiveSet::Status free_direction(ActiveSet::Fix fix) {
    rhs_ = r_;
    const auto solve_system = [&] { return gauss_newton_direction(active_set_.mask(), rhs_); };
    const auto proposed = [&](int i) { return direction_[i]; };
    const auto take_out = [&](int i, double step) { rhs_.noalias() += step * J_.col(i); };
    return active_set_.run(a_, kin_.lower(), kin_.upper(), free_, num_free_, fix, deadline(), solve_system, proposed,
                           take_out);
  }

  // direction_ = -pinv(J) rhs with the columns of the angles with `mask` 0 zeroed.
  bool gauss_newton_direction(const Eigen::VectorXd& mask, const Eigen::VectorXd& rhs) {
    if (!opt_.paper_mode && m_ <= kMaxResiduals) return residual_size_direction(mask, rhs);
    if (!opt_.paper_mode && goals_.has_soft()) return angle_size_direction(mask, rhs);
    jac_.noalias() = J_ * mask.asDiagonal();
    svd_.compute(jac_);
    // pinv(J) r = V S^+ U^T r; singular values below max(rows, cols) * eps * s_max count as 0
    // (the original's igl::pinv tolerance).
    const auto& s = svd_.singularValues();
    if (!s.allFinite()) return false;
    const double relative = opt_.paper_mode
                                ? std::max(jac_.rows(), jac_.cols()) * std::numeric_limits<double>::epsilon()
                                : opt_.gn_singular_cutoff;
    const double cutoff = relative * s.maxCoeff();
    projected_.noalias() = svd_.matrixU().transpose() * rhs;
    for (Eigen::Index i = 0; i < s.size(); ++i) projected_[i] = s[i] < cutoff || s[i] == 0 ? 0.0 : projected_[i] / s[i];
    direction_.noalias() = svd_.matrixV() * projected_;
    direction_ *= -1;
    return true;
  }

  // Outside paper mode, at the residual size: with J J^T = U diag(s^2) U^T (m x m, symmetric
  // positive semi-definite), pinv(J) rhs = J^T U diag(1 / s^2) U^T rhs over the kept singular
  // values s >= cutoff * s_max: the same step as the SVD of J, for an m x m symmetric
  // eigen-decomposition instead of an m x n SVD. The m x m matrices have a fixed maximum size
  // (kMaxResiduals), so the decomposition's temporaries live on the stack: no allocation. Rigs
  // with more residuals take the SVD of J.
  bool residual_size_direction(const Eigen::VectorXd& mask, const Eigen::VectorXd& rhs) {
    // The columns of the angles in `mask`, side by side (the others would only add zeros).
    int k = 0;
    for (int i = 0; i < n_; ++i)
      if (mask[i] != 0) {
        jac_.col(k) = J_.col(i);
        columns_[k++] = i;
      }
    direction_.setZero();
    if (k == 0) return true;
    const auto jac = jac_.leftCols(k);
    normal_.noalias() = jac * jac.transpose();
    eigen_.compute(normal_);
    if (eigen_.info() != Eigen::Success) return false;
    const auto& s2 = eigen_.eigenvalues();  // ascending, the squared singular values of J
    if (!s2.allFinite()) return false;
    const double cutoff2 = opt_.gn_singular_cutoff * opt_.gn_singular_cutoff * s2[m_ - 1];
    projected_m_.noalias() = eigen_.eigenvectors().transpose() * rhs;
    for (Eigen::Index i = 0; i < s2.size(); ++i)
      projected_m_[i] = s2[i] < cutoff2 || s2[i] <= 0 ? 0.0 : projected_m_[i] / s2[i];
    y_.noalias() = eigen_.eigenvectors() * projected_m_;
    step_k_.head(k).noalias() = jac.transpose() * y_;
    for (int j = 0; j < k; ++j) direction_[columns_[j]] = -step_k_[j];
    return true;
  }

  // With soft rows (goals.h: poles, rest rows, 3 per bone) past kMaxResiduals rows: the damped
  // normal equations at the angle size,
  //   (Jm^T Jm + c^2 tr(Jm^T Jm) I) p = -Jm^T rhs,   c = gn_singular_cutoff,
  // Jm the columns of the angles in `mask`. The shift is at least c^2 s_max^2, so directions the
  // cutoff would drop are damped instead (the rest rows leave few: they give every angle of a
  // chain a singular value of their own). An LLT on matrices sized by resize(): no allocation,
  // where the SVD of the whole Jacobian would allocate at every step.
  bool angle_size_direction(const Eigen::VectorXd& mask, const Eigen::VectorXd& rhs) {
    jac_.noalias() = J_ * mask.asDiagonal();
    angle_normal_.noalias() = jac_.transpose() * jac_;
    const double shift =
        opt_.gn_singular_cutoff * opt_.gn_singular_cutoff * angle_normal_.trace() + std::numeric_limits<double>::min();
    angle_normal_.diagonal().array() += shift;
    angle_llt_.compute(angle_normal_);
    if (angle_llt_.info() != Eigen::Success) return false;
    direction_.noalias() = jac_.transpose() * rhs;
    angle_llt_.solveInPlace(direction_);
    direction_ *= -1;
    return direction_.allFinite();
  }

  static constexpr int kMaxResiduals = 48;  // 16 end effectors
  using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxResiduals, kMaxResiduals>;
  using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxResiduals, 1>;
  SmallMatrix normal_;
  Eigen::SelfAdjointEigenSolver<SmallMatrix> eigen_;  // fixed storage (kMaxResiduals): needs no sizing
  SmallVector projected_m_, y_;
  Eigen::MatrixXd jac_;
  Eigen::MatrixXd angle_normal_;  // angle-size path (soft rows)
  Eigen::LLT<Eigen::MatrixXd> angle_llt_;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd_;
  Eigen::VectorXd projected_, direction_, all_angles_, rhs_;
  ActiveSet active_set_;
  std::vector<int> columns_;  // residual-size path: the angle of each column of jac_
  Eigen::VectorXd step_k_;    // residual-size path: the step over those columns
};

}  // namespace

std::unique_ptr<Solver> make_gn_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<GaussNewton>(kin, options);
}

}  // namespace ik

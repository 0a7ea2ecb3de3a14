// Gauss-Newton: p = -pinv(J) r through the SVD of J, then projected backtracking from alpha = 1
// (factor 0.5, sufficient decrease c1 = 1e-3 on the projected point), as the report.
// Outside paper mode the columns of angles that cannot move (fixed, or pushed against a bound)
// are left out of J, so the step uses the free angles only.
#include <Eigen/SVD>
#include <algorithm>
#include <limits>
#include <memory>

#include "solver.h"

namespace ik {

namespace {

class GaussNewton final : public Solver {
 public:
  using Solver::Solver;
  const char* name() const override { return "gn"; }

 private:
  void resize(int residuals, int angles) override {
    jac_.resize(residuals, angles);
    svd_ = Eigen::JacobiSVD<Eigen::MatrixXd>(residuals, angles, Eigen::ComputeThinU | Eigen::ComputeThinV);
    projected_.resize(std::min(residuals, angles));
    direction_.resize(angles);
  }

  Progress iterate() override {
    if (opt_.paper_mode)
      jac_ = J_;
    else
      jac_.noalias() = J_ * free_mask_.asDiagonal();
    svd_.compute(jac_);
    // pinv(J) r = V S^+ U^T r; singular values below max(rows, cols) * eps * s_max count as 0
    // (the original's igl::pinv tolerance).
    const auto& s = svd_.singularValues();
    if (!s.allFinite()) return fail("the SVD of the Jacobian is not finite");
    const double cutoff = std::max(jac_.rows(), jac_.cols()) * std::numeric_limits<double>::epsilon() * s.maxCoeff();
    projected_.noalias() = svd_.matrixU().transpose() * r_;
    for (Eigen::Index i = 0; i < s.size(); ++i) projected_[i] = s[i] < cutoff || s[i] == 0 ? 0.0 : projected_[i] / s[i];
    direction_.noalias() = svd_.matrixV() * projected_;
    direction_ *= -1;

    return backtrack(direction_, 1, opt_.armijo_c1) ? Progress::moved : Progress::stuck;
  }

  Eigen::MatrixXd jac_;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd_;
  Eigen::VectorXd projected_, direction_;
};

}  // namespace

std::unique_ptr<Solver> make_gn_solver(Kinematics& kin, const SolverOptions& options) {
  return std::make_unique<GaussNewton>(kin, options);
}

}  // namespace ik

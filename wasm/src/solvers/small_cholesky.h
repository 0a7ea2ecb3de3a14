// Cholesky factorisation and solve for small dense symmetric positive definite matrices (the
// residual-size systems of lm, 3 x #effectors): left-looking, one column-major matrix-vector
// product per column, which beats Eigen's blocked LLT by several times at these sizes and the
// plain triple loop by about 1.5 (the avatar's 30 x 30 systems in WebAssembly).
#pragma once

#include <Eigen/Core>

namespace ik {

// Factors the leading n x n block of `a` in place: its lower triangle becomes L with
// a = L L^T (the strict upper triangle is left alone). Returns false, with `a` partly
// overwritten, if the matrix is not numerically positive definite. No allocation.
bool small_cholesky(Eigen::Ref<Eigen::MatrixXd> a, int n);

// Replaces the factor L (from small_cholesky) by that of L L^T - v v^T, a rank-one downdate in
// O(n^2); `v` (n) is overwritten. Returns false, with the factor partly overwritten, if a pivot
// would fall below kDowndateShare of itself (the downdate then loses accuracy: factor the
// matrix afresh) or the result is not positive definite. No allocation.
constexpr double kDowndateShare = 1e-3;
bool small_cholesky_downdate(Eigen::Ref<Eigen::MatrixXd> factor, int n, Eigen::Ref<Eigen::VectorXd> v);

// Solves L L^T x = b in place (`b` becomes x) with the factor from small_cholesky. No allocation.
void small_cholesky_solve(const Eigen::Ref<const Eigen::MatrixXd>& factor, int n, Eigen::Ref<Eigen::VectorXd> b);

}  // namespace ik

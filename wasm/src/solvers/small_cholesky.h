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

// Solves L L^T x = b in place (`b` becomes x) with the factor from small_cholesky. No allocation.
void small_cholesky_solve(const Eigen::Ref<const Eigen::MatrixXd>& factor, int n, Eigen::Ref<Eigen::VectorXd> b);

}  // namespace ik

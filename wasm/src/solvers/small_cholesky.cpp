#include "small_cholesky.h"

#include <cmath>

namespace ik {

bool small_cholesky(Eigen::Ref<Eigen::MatrixXd> a, int n) {
  // Left-looking, a column at a time: column j below the diagonal less the columns before it
  // (one column-major matrix-vector product, contiguous and vectorised), then scaled.
  for (int j = 0; j < n; ++j) {
    const int below = n - j;
    if (j > 0) a.col(j).segment(j, below).noalias() -= a.block(j, 0, below, j) * a.row(j).head(j).transpose();
    const double d = a(j, j);
    if (!(d > 0) || !std::isfinite(d)) return false;
    const double ljj = std::sqrt(d);
    a(j, j) = ljj;
    a.col(j).segment(j + 1, below - 1) /= ljj;
  }
  return true;
}

bool small_cholesky_downdate(Eigen::Ref<Eigen::MatrixXd> factor, int n, Eigen::Ref<Eigen::VectorXd> v) {
  // Column by column a hyperbolic rotation between L's column k and v zeroes v_k; a zero v_k
  // (rows the taken-out column does not move) leaves column k as it is.
  for (int k = 0; k < n; ++k) {
    if (v[k] == 0) continue;
    const double lkk = factor(k, k);
    const double c2 = 1 - (v[k] / lkk) * (v[k] / lkk);  // (new pivot / old)^2
    if (!(c2 > kDowndateShare * kDowndateShare)) return false;
    const double c = std::sqrt(c2), s = v[k] / lkk;
    factor(k, k) = c * lkk;
    const int below = n - k - 1;
    auto l = factor.col(k).segment(k + 1, below);
    auto w = v.segment(k + 1, below);
    l = (l - s * w) * (1 / c);
    w = c * w - s * l;
  }
  return true;
}

void small_cholesky_solve(const Eigen::Ref<const Eigen::MatrixXd>& factor, int n, Eigen::Ref<Eigen::VectorXd> b) {
  const auto L = factor.topLeftCorner(n, n).triangularView<Eigen::Lower>();
  L.solveInPlace(b.head(n));              // L y = b
  L.transpose().solveInPlace(b.head(n));  // L^T x = y
}

}  // namespace ik

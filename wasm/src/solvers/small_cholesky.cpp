#include "small_cholesky.h"

#include <cmath>

namespace ik {

bool small_cholesky(Eigen::Ref<Eigen::MatrixXd> a, int n) {
  for (int j = 0; j < n; ++j) {
    double d = a(j, j);
    for (int k = 0; k < j; ++k) d -= a(j, k) * a(j, k);
    if (!(d > 0) || !std::isfinite(d)) return false;
    const double ljj = std::sqrt(d);
    a(j, j) = ljj;
    for (int i = j + 1; i < n; ++i) {
      double v = a(i, j);
      for (int k = 0; k < j; ++k) v -= a(i, k) * a(j, k);
      a(i, j) = v / ljj;
    }
  }
  return true;
}

void small_cholesky_solve(const Eigen::Ref<const Eigen::MatrixXd>& factor, int n, Eigen::Ref<Eigen::VectorXd> b) {
  for (int i = 0; i < n; ++i) {  // L y = b
    double v = b[i];
    for (int k = 0; k < i; ++k) v -= factor(i, k) * b[k];
    b[i] = v / factor(i, i);
  }
  for (int i = n - 1; i >= 0; --i) {  // L^T x = y
    double v = b[i];
    for (int k = i + 1; k < n; ++k) v -= factor(k, i) * b[k];
    b[i] = v / factor(i, i);
  }
}

}  // namespace ik

#include "damped_system.h"

#include <cmath>

#include "small_cholesky.h"

namespace ik {

void DampedSystem::resize(int m) {
  reduced_.resize(m, m);
  factor_.resize(m, m);
  rhs_.resize(m);
  shift_.resize(m);
  y_.resize(m);
  column_.resize(m);
}

void DampedSystem::begin(const Eigen::MatrixXd& normal, const Eigen::Ref<const Eigen::VectorXd>& rhs) {
  reduced_ = normal;
  rhs_ = rhs;
  factored_ = false;
}

bool DampedSystem::solve() {
  const int m = static_cast<int>(rhs_.size());
  if (!factored_) {
    factor_ = reduced_;
    factor_.diagonal() += shift_;
    if (!small_cholesky(factor_, m)) return false;
    factored_ = true;
  }
  y_ = rhs_;
  small_cholesky_solve(factor_, m, y_);
  return true;
}

void DampedSystem::take_out(const BlockPattern& pattern, const Eigen::MatrixXd& J, int i, double d) {
  pattern.take_out(J, i, d, rhs_, reduced_);
  if (!factored_) return;
  column_.setZero();
  pattern.add(J, i, std::sqrt(pattern.weight(i)), column_);
  factored_ = small_cholesky_downdate(factor_, static_cast<int>(rhs_.size()), column_);
}

}  // namespace ik

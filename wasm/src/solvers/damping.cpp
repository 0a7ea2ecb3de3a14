#include "damping.h"

#include <algorithm>
#include <cmath>

namespace ik {

bool NielsenDamping::accept(double E, double E_trial, double predicted) {
  const double rho = (E - E_trial) / predicted;
  if (std::isfinite(E_trial) && E_trial < E && predicted > 0 && rho > kMinGain) {
    mu_ = std::max(mu_ * std::max(1.0 / 3, 1 - std::pow(2 * rho - 1, 3)), kMinMu);
    nu_ = 2;
    return true;
  }
  mu_ = std::min(mu_ * nu_, kMaxMu);
  nu_ = std::min(2 * nu_, kMaxNu);
  return false;
}

void NielsenDamping::grow_for_indefinite() { mu_ = std::min(4 * std::max(mu_, 1e-6), kMaxMu); }

}  // namespace ik

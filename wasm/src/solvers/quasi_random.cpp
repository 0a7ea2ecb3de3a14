#include "quasi_random.h"

#include <algorithm>
#include <cmath>

namespace ik {

namespace {

// splitmix64: a well-mixed 64-bit value per (seed, index).
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

double fraction(double x) { return x - std::floor(x); }

}  // namespace

QuasiRandom::QuasiRandom(int dimension, std::uint32_t seed) : alpha_(dimension), shift_(dimension) {
  // phi_d: the root > 1 of x^(d+1) = x + 1.
  double phi = 2;
  for (int i = 0; i < 64; ++i) phi = std::pow(1 + phi, 1.0 / (dimension + 1));
  double power = 1;
  for (int i = 0; i < dimension; ++i) {
    power /= phi;
    alpha_[i] = fraction(power);
    shift_[i] = static_cast<double>(mix((static_cast<std::uint64_t>(seed) << 32) + i) >> 11) * 0x1.0p-53;
  }
}

void QuasiRandom::point(long k, Eigen::Ref<Eigen::VectorXd> out) const {
  for (Eigen::Index i = 0; i < alpha_.size(); ++i) out[i] = fraction(shift_[i] + static_cast<double>(k) * alpha_[i]);
}

void point_in_limits(const Eigen::Ref<const Eigen::VectorXd>& unit, const Eigen::Ref<const Eigen::VectorXd>& lower,
                     const Eigen::Ref<const Eigen::VectorXd>& upper, Eigen::Ref<Eigen::VectorXd> out) {
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    const double lo = lower[i], hi = upper[i];
    if (!(lo < hi)) {
      out[i] = lo;
      continue;
    }
    // The whole range when it is at most a turn wide; else the turn within it nearest -180..180.
    const double from = hi - lo <= 360 ? lo : std::clamp(-180.0, lo, hi - 360), to = hi - lo <= 360 ? hi : from + 360;
    out[i] = std::clamp(from + (to - from) * unit[i], lo, hi);
  }
}

}  // namespace ik

// A deterministic low-discrepancy sequence in the unit cube (Roberts' R_d sequence,
// x_k = frac(shift + k * alpha) with alpha_i = 1 / phi_d^(i+1)), randomly shifted by a seed.
// Used for restart points inside the joint limits.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace ik {

class QuasiRandom {
 public:
  // A sequence in `dimension` dimensions; `seed` picks the shift. Allocates.
  QuasiRandom(int dimension, std::uint32_t seed);
  QuasiRandom() = default;

  // Writes point k (k >= 1) of the sequence, each coordinate in [0, 1), to `out` (dimension).
  // No allocation.
  void point(long k, Eigen::Ref<Eigen::VectorXd> out) const;

  int dimension() const { return static_cast<int>(alpha_.size()); }

 private:
  Eigen::VectorXd alpha_, shift_;
};

// A point inside the limits from `unit` (coordinates in [0, 1)): each angle spans its limits when
// they are at most one turn wide (47..313 included: a Jaco2 joint), else one turn of them, the
// one nearest [-180, 180] (unbounded angles: [-180, 180]). Fixed angles take their value.
// `lower`, `upper` and `out` are #angles, degrees. No allocation.
void point_in_limits(const Eigen::Ref<const Eigen::VectorXd>& unit, const Eigen::Ref<const Eigen::VectorXd>& lower,
                     const Eigen::Ref<const Eigen::VectorXd>& upper, Eigen::Ref<Eigen::VectorXd> out);

}  // namespace ik

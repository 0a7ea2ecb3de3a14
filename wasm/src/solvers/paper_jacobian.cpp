#include "paper_jacobian.h"

#include <algorithm>

#include "finite_difference_jacobian.h"

namespace ik {

void paper_jacobian(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles, double h_deg,
                    Eigen::Ref<Eigen::VectorXd> scratch, Eigen::Ref<Eigen::VectorXd> tips_plus,
                    Eigen::Ref<Eigen::VectorXd> tips_minus, Eigen::Ref<Eigen::MatrixXd> jac) {
  finite_difference_jacobian(kin, angles, h_deg, /*clamp_to_limits=*/true, scratch, tips_plus, tips_minus, jac);
  for (int j = 0; j < kin.num_angles(); ++j) {
    const double spread = std::min(angles[j] + h_deg, kin.upper()[j]) - std::max(angles[j] - h_deg, kin.lower()[j]);
    if (spread > 0) jac.col(j) *= spread / h_deg;
  }
}

}  // namespace ik

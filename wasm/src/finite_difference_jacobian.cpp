#include "finite_difference_jacobian.h"

#include <algorithm>

namespace ik {

void finite_difference_jacobian(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles, double h_deg,
                                bool clamp_to_limits, Eigen::Ref<Eigen::VectorXd> scratch,
                                Eigen::Ref<Eigen::VectorXd> tips_plus, Eigen::Ref<Eigen::VectorXd> tips_minus,
                                Eigen::Ref<Eigen::MatrixXd> jac) {
  scratch = angles;
  for (int j = 0; j < kin.num_angles(); ++j) {
    double hi = angles[j] + h_deg, lo = angles[j] - h_deg;
    if (clamp_to_limits) {
      hi = std::min(hi, kin.upper()[j]);
      lo = std::max(lo, kin.lower()[j]);
    }
    if (hi <= lo) {  // a fixed angle: no motion possible
      jac.col(j).setZero();
      continue;
    }
    scratch[j] = hi;
    kin.tips(scratch, tips_plus);
    scratch[j] = lo;
    kin.tips(scratch, tips_minus);
    scratch[j] = angles[j];
    jac.col(j) = (tips_plus - tips_minus) / (hi - lo);
  }
  kin.forward(angles);
}

}  // namespace ik

#include "joint_motion.h"

#include <algorithm>
#include <cmath>

namespace ik {

namespace {

// Bisection steps of limit(): t to within 2^-12 of the largest admissible fraction.
constexpr int kBisections = 12;

}  // namespace

void JointMotion::resize(const Kinematics& kin) {
  heads_.resize(kin.num_bones());
  tips_.resize(kin.num_bones());
}

void JointMotion::note_start(const Kinematics& kin) {
  for (int b = 0; b < kin.num_bones(); ++b) {
    heads_[b] = kin.joint_origin(b);
    tips_[b] = kin.tip(b);
  }
}

double JointMotion::largest_move(const Kinematics& kin) const {
  double worst2 = 0;
  for (int b = 0; b < kin.num_bones(); ++b)
    worst2 = std::max({worst2, (kin.joint_origin(b) - heads_[b]).squaredNorm(), (kin.tip(b) - tips_[b]).squaredNorm()});
  return std::sqrt(worst2);
}

double JointMotion::limit(Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& start,
                          const Eigen::Ref<const Eigen::VectorXd>& end, double bound,
                          Eigen::Ref<Eigen::VectorXd> out) const {
  double low = 0, high = 1;  // largest_move at low is within the bound, at high beyond it
  for (int i = 0; i < kBisections; ++i) {
    const double t = 0.5 * (low + high);
    out = start + t * (end - start);
    kin.forward(out);
    (largest_move(kin) <= bound ? low : high) = t;
  }
  out = start + low * (end - start);
  kin.forward(out);
  return low;
}

}  // namespace ik

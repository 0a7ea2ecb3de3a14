#include "saddle_escape.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "free_set.h"
#include "goal_residual.h"
#include "objective.h"
#include "tip_hessian.h"

namespace ik {

namespace {

// An eigenvalue counts as negative below this share of the largest |eigenvalue| (rounding in H
// is far smaller; a genuine bend direction far larger).
constexpr double kRelativeCurvature = 1e-8;
// Sufficient decrease against the quadratic model lambda |s|^2 / 2.
constexpr double kDecrease = 0.25;
// Halvings of the first step before giving up (30 degrees down to about 1e-7 degrees).
constexpr int kMaxHalvings = 28;

}  // namespace

void SaddleEscape::resize(const Kinematics& kin, int residuals) {
  count_ = 0;  // index_ is cleared below: no angle of the last find() is left to unmark
  position_.assign(kin.num_angles(), -1);
  bones_.resize(kin.num_bones());
  index_.assign(kMaxAngles, -1);
  direction_.resize(kin.num_angles());
  other_trial_.resize(kin.num_angles());
  other_residual_.resize(residuals);
  weights_.resize(kin.num_residuals());
}

void SaddleEscape::choose_angles(const Kinematics& kin, const GoalSet& goals,
                                 const Eigen::Ref<const Eigen::VectorXd>& r) {
  for (int c = 0; c < count_; ++c) position_[index_[c]] = -1;
  count_ = 0;
  const double largest = largest_goal_distance(goals, r);
  if (!(largest > 0)) return;
  for (int e = 0; e < kin.num_effectors(); ++e) {
    if (!goal_off_target(goals, r, e, largest)) continue;
    const std::vector<int>& chain = kin.effector_chain(e);
    for (auto bone = chain.rbegin(); bone != chain.rend(); ++bone)  // distal bones first
      for (int k = 0; k < 3; ++k) {
        const int angle = 3 * *bone + k;
        if (count_ == kMaxAngles) return;
        if (position_[angle] >= 0 || !(kin.lower()[angle] < kin.upper()[angle])) continue;
        position_[angle] = count_;
        index_[count_++] = angle;
      }
  }
}

EscapeResult SaddleEscape::find(Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                                const Eigen::Ref<const Eigen::VectorXd>& r, double E,
                                const Eigen::Ref<const Eigen::MatrixXd>& J, Eigen::Ref<Eigen::VectorXd> trial,
                                Eigen::Ref<Eigen::VectorXd> residual) {
  EscapeResult result;
  choose_angles(kin, goals, r);
  if (count_ == 0) return result;

  hessian_.resize(count_, count_);
  for (int p = 0; p < count_; ++p)
    for (int q = 0; q <= p; ++q) hessian_(p, q) = hessian_(q, p) = J.col(index_[p]).dot(J.col(index_[q]));
  if (goals.plain()) {
    add_weighted_tip_hessian(kin, r, position_, bones_, hessian_);
  } else {
    tip_hessian_weights(goals, r, weights_);
    add_weighted_tip_hessian(kin, weights_, position_, bones_, hessian_);
  }
  if (!hessian_.allFinite()) return result;
  eigen_.compute(hessian_);
  if (eigen_.info() != Eigen::Success) return result;
  const auto& values = eigen_.eigenvalues();  // ascending
  const double lambda = values[0];
  result.curvature = lambda;
  if (!(lambda < -kRelativeCurvature * std::max(std::abs(values[0]), std::abs(values[count_ - 1])))) return result;

  // The eigenvector scattered over the angles, its largest component +1.
  const auto v = eigen_.eigenvectors().col(0);
  Eigen::Index largest = 0;
  v.cwiseAbs().maxCoeff(&largest);
  direction_.setZero();
  for (int p = 0; p < count_; ++p) direction_[index_[p]] = v[p] / v[largest];

  // A sign whose first move the bounds bend to a curvature the test cannot accept (a straight
  // knee's eigenvector bends it both ways; its limit stops one) is not searched: there every
  // halving down to the last was evaluated in vain (26 evaluations of an avatar frame).
  const double passable = kDecrease * lambda;
  double E_plus = 0, E_minus = 0;
  const bool plus = curvature_within_bounds(kin, angles, +1) < passable &&
                    search(kin, goals, angles, E, lambda, +1, trial, residual, E_plus, result.evaluations);
  const bool minus =
      curvature_within_bounds(kin, angles, -1) < passable &&
      search(kin, goals, angles, E, lambda, -1, other_trial_, other_residual_, E_minus, result.evaluations);
  if (!plus && !minus) return result;
  result.found = true;
  if (plus && (!minus || E_plus <= E_minus)) {
    result.E = E_plus;
  } else {
    trial = other_trial_;
    residual = other_residual_;
    result.E = E_minus;
  }
  return result;
}

double SaddleEscape::curvature_within_bounds(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles,
                                             double sign) {
  clipped_.resize(count_);
  for (int p = 0; p < count_; ++p) {
    const int i = index_[p];
    const double d = sign * direction_[i];
    clipped_[p] = pushed_past_limit(angles[i], kin.lower()[i], kin.upper()[i], d) ? 0 : d;
  }
  const double length2 = clipped_.squaredNorm();
  if (!(length2 > 0)) return std::numeric_limits<double>::infinity();
  return clipped_.dot(hessian_ * clipped_) / length2;  // both of at most kMaxAngles: no allocation
}

bool SaddleEscape::search(Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                          double E, double curvature, double sign, Eigen::Ref<Eigen::VectorXd> trial,
                          Eigen::Ref<Eigen::VectorXd> residual, double& E_trial, int& evaluations) {
  double step = sign * kFirstStepDeg;
  for (int i = 0; i <= kMaxHalvings; ++i, step *= 0.5) {
    trial = angles + step * direction_;
    kin.project(trial);
    const double moved2 = (trial - angles).squaredNorm();
    if (moved2 == 0) return false;  // the bounds block this sign
    // E >= 0 everywhere: a step whose required decrease is more than E cannot pass (near the
    // target, where E is small, most of the first steps), and is not evaluated.
    const double required = E + kDecrease * 0.5 * curvature * moved2;
    if (!(required > 0)) continue;
    E_trial = goal_objective(kin, goals, trial, residual);
    ++evaluations;
    if (std::isfinite(E_trial) && E_trial < required) return true;
  }
  return false;
}

}  // namespace ik

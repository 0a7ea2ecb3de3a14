// Leaving a stationary point of E that is not a minimum, along a direction of negative curvature.
//
// A straight limb whose target moves along it towards its root is the everyday case: there
// grad E = J^T r = 0 (the tip can only move across the limb, r points along it), so every
// first-order method stops, yet bending the limb lowers E. The exact Hessian
//   H = J^T J + sum_i r_i Hess x_i      (tip_hessian.h)
// has a negative eigenvalue there, and its eigenvector is the bend (with whatever the other
// joints must do to keep the pinned effectors put, which J^T J charges for).
//
// With orientation goals (goals.h) the orientation rows enter H through J^T J only (Gauss-Newton
// style) and "off target" compares the residual's blocks in rig units (goal_residual.h).
// H is formed only over the movable angles on the chains of the effectors still off target
// (|r_k| >= a tenth of the largest), distal bones first, at most kMaxAngles of them: a negative
// curvature direction of that block is one of the full H (the other angles held). Along the
// unit eigenvector v of the smallest eigenvalue lambda < 0, both signs are searched by projected
// backtracking from a step that turns the largest angle by kFirstStepDeg, accepting
//   E(P(A + t v)) < E(A) + c lambda |P(A + t v) - A|^2 / 2        (c = 1/4)
// and the sign with the lower E is taken (a tie: the sign whose largest component is positive).
// A sign is searched only if the model's curvature along its first move, with the components
// that push an angle already on its limit outward held at 0, can pass that test (< c lambda).
// The step goes only as far as E keeps falling by that much, so the pose does not jump; the
// method then descends from there. No allocation after resize().
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <vector>

#include "goals.h"
#include "kinematics.h"

namespace ik {

struct EscapeResult {
  bool found = false;    // a lower point along negative curvature (trial and residual hold it)
  double E = 0;          // E there
  double curvature = 0;  // the smallest eigenvalue of the Hessian block, rig units^2 per degree^2
  int evaluations = 0;   // E evaluations made (forward kinematics)
};

class SaddleEscape {
 public:
  static constexpr int kMaxAngles = 48;
  static constexpr double kFirstStepDeg = 30;

  // Workspace for `kin`'s sizes and `residuals` residual rows (allocates).
  void resize(const Kinematics& kin, int residuals);

  // From `angles` (#angles, degrees; `kin` posed there), with its residual `r` (x - target),
  // E = `E` and Jacobian `J` (#residuals x #angles, per degree) towards `goals`. On success
  // writes the lower point to `trial` and its residual to `residual`; `kin` is then posed at
  // an arbitrary trial point. No allocation.
  EscapeResult find(Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                    const Eigen::Ref<const Eigen::VectorXd>& r, double E, const Eigen::Ref<const Eigen::MatrixXd>& J,
                    Eigen::Ref<Eigen::VectorXd> trial, Eigen::Ref<Eigen::VectorXd> residual);

 private:
  // The angles H is formed over (index_[0..count_)); position_[angle] is its place or -1.
  void choose_angles(const Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& r);
  // The Hessian block's curvature (rig units^2 per degree^2) along sign * direction_, less
  // the components that push an angle on its limit outward (`angles`, degrees); +inf if none is left.
  double curvature_within_bounds(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& angles, double sign);
  // Backtracking along sign * direction_; the accepted point in `trial` / `residual`.
  bool search(Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles, double E,
              double curvature, double sign, Eigen::Ref<Eigen::VectorXd> trial, Eigen::Ref<Eigen::VectorXd> residual,
              double& E_trial, int& evaluations);

  using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxAngles, kMaxAngles>;
  SmallMatrix hessian_;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxAngles, 1> clipped_;  // scratch of curvature_within_bounds()
  Eigen::SelfAdjointEigenSolver<SmallMatrix> eigen_{kMaxAngles};
  std::vector<int> position_, index_;
  std::vector<int> bones_;  // scratch of the tip Hessian: one effector's chain bones with a chosen angle
  int count_ = 0;
  Eigen::VectorXd direction_, other_trial_, other_residual_, weights_;
};

}  // namespace ik

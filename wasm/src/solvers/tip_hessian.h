// Analytic second derivatives of the end-effector tips with respect to the angles.
//
// For angles j and k on the chain of effector tip p, with j proximal to or equal to k (parent
// bones first, and x, z, x in that order within a bone):
//   d2p / dA_j dA_k = (pi/180)^2 * w_j x (w_k x (p - o_k))
// where w is the world axis of an angle and o the world origin of its joint. Angles off the
// chain contribute 0. Units: rig units per DEGREE^2.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "kinematics.h"

namespace ik {

// After kin.forward(): the Hessians of effector `effector`'s (an index into the effector list)
// tip coordinates x, y and z, each #angles x #angles, written to `hx`, `hy`, `hz`.
void tip_hessian(const Kinematics& kin, int effector, Eigen::Ref<Eigen::MatrixXd> hx, Eigen::Ref<Eigen::MatrixXd> hy,
                 Eigen::Ref<Eigen::MatrixXd> hz);

// After kin.forward(): adds sum_i weights[i] * d2 tips[i] / dA dA to `out` (#angles x #angles),
// with `weights` one per tip coordinate (#residuals). With weights = the residual x(A) - x_b this
// is the part of Hess E that J^T J leaves out. No allocation.
void add_weighted_tip_hessian(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& weights,
                              Eigen::Ref<Eigen::MatrixXd> out);

// The same sum over a subset of the angles: `position` (#angles entries) gives each angle's
// row and column in `out`, or -1 to leave the angle out. `scratch` holds at least #bones entries.
// Costs the subset's size squared, whatever the chains' length. No allocation.
void add_weighted_tip_hessian(const Kinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& weights,
                              const std::vector<int>& position, std::vector<int>& scratch,
                              Eigen::Ref<Eigen::MatrixXd> out);

}  // namespace ik

// The residual of a GoalSet (goals.h), E = 1/2 |r|^2, its analytic Jacobian, and the distances
// the stop tests and the ways out of a stop read from r. Plain goals take the position-only code
// of objective.h, bit for bit.
//
// Orientation rows: perturbing angle j about its world axis a by d radians turns R_tip into
// exp([a] d) R_tip, so e = log(R_target^T R_tip) becomes log(R_target^T R_tip exp([R_tip^T a] d))
// = e + J_r^-1(e) R_tip^T a d + O(d^2) (so3.h). The Jacobian column is therefore
//   w_o L (pi/180) J_r^-1(e) R_tip^T a      (rig units per DEGREE)
// for the angles on the effector's chain, 0 for the others. At |e| = pi the log's axis may flip
// sign between neighbouring poses (E = 1/2 (w_o L pi)^2 is continuous there; it is E's maximum
// over that goal, so the methods descend away from it).
//
// The soft rows follow the hard ones: poles (pole_residual.h, their Jacobian by the chain rule
// through S, M and T) and rest rows (rest_residual.h). With GoalSet::soft_on() false they read 0.
// Every function below that measures distances reads the hard blocks only.
#pragma once

#include <Eigen/Core>

#include "goals.h"
#include "kinematics.h"

namespace ik {

// Poses `kin` at `angles` (#angles, degrees) and writes the residual (goals.rows(), rig units).
// Returns E. No allocation.
double goal_objective(Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                      Eigen::Ref<Eigen::VectorXd> residual);

// After kin.forward(): the Jacobian of the residual (goals.rows() x #angles, rig units per
// degree). With Columns::movable the columns of fixed angles (min >= max) stay 0 except in the
// rest rows (the solvers never read them). No allocation.
void goal_jacobian(const Kinematics& kin, const GoalSet& goals, Eigen::Ref<Eigen::MatrixXd> jac,
                   Kinematics::Columns columns = Kinematics::Columns::all);

// After kin.forward(): the gradient J^T r of E (#angles, rig units^2 per degree) over the hard
// rows of `goals` (soft rows off: GoalSet::soft_on() false; not for plain goals) at `residual`,
// without forming J: a dot per angle and block. Columns as for goal_jacobian. No allocation.
void goal_gradient(const Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual,
                   Eigen::Ref<Eigen::VectorXd> gradient, Kinematics::Columns columns = Kinematics::Columns::all);

// The largest distance of an effector's tip from its position target (rig units, unweighted);
// 0 without position goals.
double largest_tip_distance(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual);

// The largest orientation error over the orientation goals, DEGREES (0 without any).
double largest_orientation_error_deg(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual);

// 1/2 |position rows|^2 (rig units^2): E without the orientation rows.
double position_error(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual);

// The largest |block| of the residual (rig units; orientation blocks scaled by w_o L): the
// measure of "off target" for saddle escapes and chain restarts.
double largest_goal_distance(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual);

// Is effector e off target: one of its blocks at least kOffTargetShare (objective.h) of
// `largest` = largest_goal_distance()?
bool goal_off_target(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual, int e, double largest);

// The weights (3 x #effectors) for add_weighted_tip_hessian (tip_hessian.h) that give the
// position rows' second-order term sum_i r_i Hess r_i: w_p r for an effector's position block,
// 0 without one. Orientation rows get none (their Hessian is left to J^T J, Gauss-Newton style).
void tip_hessian_weights(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual,
                         Eigen::Ref<Eigen::VectorXd> weights);

}  // namespace ik

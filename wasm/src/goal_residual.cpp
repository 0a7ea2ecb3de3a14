#include "goal_residual.h"

#include <algorithm>
#include <cmath>

#include "objective.h"
#include "pole_residual.h"
#include "rest_residual.h"
#include "so3.h"

namespace ik {

double goal_objective(Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& angles,
                      Eigen::Ref<Eigen::VectorXd> residual) {
  if (goals.plain()) return objective(kin, angles, goals.plain_target(), residual);
  kin.forward(angles);
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    const int bone = kin.rig().effectors[g.effector];
    if (g.orientation)
      residual.segment<3>(3 * b) = g.scale * so3_log(g.rotation.transpose() * kin.tip_rotation(bone));
    else
      residual.segment<3>(3 * b) = g.scale * (kin.tip(bone) - g.position);
  }
  const int hard = goals.hard_rows();
  if (!goals.soft_on()) {
    residual.tail(goals.rows() - hard).setZero();
    return 0.5 * residual.squaredNorm();
  }
  for (int p = 0; p < goals.num_poles(); ++p) {
    const GoalSet::Pole& g = goals.pole(p);
    residual.segment<3>(hard + 3 * p) =
        pole_residual(kin.joint_origin(g.parent), kin.joint_origin(g.bone), kin.tip(g.bone), g.point, g.bend_floor,
                      goals.soft_scale() * g.scale);
  }
  rest_residual(goals, angles, residual.tail(3 * goals.num_rest()));
  return 0.5 * residual.squaredNorm();
}

namespace {

// An orientation block's rows' Jacobian is M a for a turn about the world axis a (per degree):
// M = w_o L (pi/180) J_r^-1(e) R_tip^T (the header's derivation).
Eigen::Matrix3d orientation_map(const Kinematics& kin, const GoalSet::Block& g, int bone) {
  const Eigen::Matrix3d R = kin.tip_rotation(bone);
  return g.scale * kRadPerDeg * so3_right_jacobian_inverse(so3_log(g.rotation.transpose() * R)) * R.transpose();
}

}  // namespace

void goal_jacobian(const Kinematics& kin, const GoalSet& goals, Eigen::Ref<Eigen::MatrixXd> jac,
                   Kinematics::Columns columns) {
  if (goals.plain()) {
    kin.current_jacobian(jac, columns);
    return;
  }
  jac.setZero();
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    const int bone = kin.rig().effectors[g.effector];
    const double scale = g.scale * kRadPerDeg;
    if (g.orientation) {
      const Eigen::Matrix3d M = orientation_map(kin, g, bone);
      for (int j : kin.effector_chain(g.effector)) {
        const int filled = kin.columns_of(j, columns);
        for (int a = 0; a < 3; ++a)
          if (filled & (1 << a)) jac.block<3, 1>(3 * b, 3 * j + a) = M * kin.joint_axis(j, a);
      }
    } else {
      const Eigen::Vector3d p = kin.tip(bone);
      for (int j : kin.effector_chain(g.effector)) {
        const int filled = kin.columns_of(j, columns);
        for (int a = 0; a < 3; ++a)
          if (filled & (1 << a))
            jac.block<3, 1>(3 * b, 3 * j + a) = scale * kin.joint_axis(j, a).cross(p - kin.joint_origin(j));
      }
      if (kin.floats()) jac.block<3, 3>(3 * b, kin.root_translation()) = g.scale * Eigen::Matrix3d::Identity();
    }
  }
  if (!goals.soft_on()) return;
  const int hard = goals.hard_rows();
  for (int p = 0; p < goals.num_poles(); ++p) {
    const GoalSet::Pole& g = goals.pole(p);
    const Eigen::Vector3d S = kin.joint_origin(g.parent), M = kin.joint_origin(g.bone), T = kin.tip(g.bone);
    PolePartials d;
    pole_partials(S, M, T, g.point, g.bend_floor, goals.soft_scale() * g.scale, d);
    // Angle a of bone k on the chain turns every point X below it by axis x (X - origin_k) per
    // radian: T below every bone of the chain; S and M below the parent and its ancestors only
    // (the parent turns about S itself, so its S term is 0 anyway).
    for (int k = g.bone; k >= 0; k = kin.rig().bones[k].parent)
      for (int a = 0; a < 3; ++a) {
        if (!(kin.columns_of(k, columns) & (1 << a))) continue;
        const Eigen::Vector3d axis = kin.joint_axis(k, a), origin = kin.joint_origin(k);
        Eigen::Vector3d column = d.wrist * axis.cross(T - origin);
        if (k != g.bone) column += d.shoulder * axis.cross(S - origin) + d.elbow * axis.cross(M - origin);
        jac.block<3, 1>(hard + 3 * p, 3 * k + a) = kRadPerDeg * column;
      }
    // A floating root moves S, M and T alike.
    if (kin.floats()) jac.block<3, 3>(hard + 3 * p, kin.root_translation()) = d.shoulder + d.elbow + d.wrist;
  }
  rest_jacobian(goals, jac.bottomRows(3 * goals.num_rest()));
}

void goal_gradient(const Kinematics& kin, const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual,
                   Eigen::Ref<Eigen::VectorXd> gradient, Kinematics::Columns columns) {
  gradient.setZero();
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    const int bone = kin.rig().effectors[g.effector];
    const Eigen::Vector3d r = residual.segment<3>(3 * b);
    // A column c of the block against r: (M a) . r = a . (M^T r); scale (a x (p - o)) . r =
    // a . (scale (p - o) x r). One vector per block or per joint, then a dot per angle.
    Eigen::Vector3d pulled = Eigen::Vector3d::Zero();
    if (g.orientation) pulled = orientation_map(kin, g, bone).transpose() * r;
    const Eigen::Vector3d p = kin.tip(bone);
    for (int j : kin.effector_chain(g.effector)) {
      const int filled = kin.columns_of(j, columns);
      if (!g.orientation) pulled = g.scale * kRadPerDeg * (p - kin.joint_origin(j)).cross(r);
      for (int a = 0; a < 3; ++a)
        if (filled & (1 << a)) gradient[3 * j + a] += kin.joint_axis(j, a).dot(pulled);
    }
    if (!g.orientation && kin.floats()) gradient.segment<3>(kin.root_translation()) += g.scale * r;
  }
}

double largest_tip_distance(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  if (goals.plain()) return largest_tip_distance(residual);
  double largest = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (!goals.block(b).orientation)
      largest = std::max(largest, residual.segment<3>(3 * b).norm() / goals.block(b).scale);
  return largest;
}

double largest_orientation_error_deg(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  double largest = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (goals.block(b).orientation)
      largest = std::max(largest, residual.segment<3>(3 * b).norm() / goals.block(b).scale);
  return largest / kRadPerDeg;
}

double position_error(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  double sum = 0;
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (!goals.block(b).orientation) sum += residual.segment<3>(3 * b).squaredNorm();
  return 0.5 * sum;
}

double largest_goal_distance(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual) {
  if (goals.plain()) return largest_tip_distance(residual);
  double largest = 0;
  for (int b = 0; b < goals.num_blocks(); ++b) largest = std::max(largest, residual.segment<3>(3 * b).norm());
  return largest;
}

bool goal_off_target(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual, int e, double largest) {
  if (goals.plain()) return off_target(residual, e, largest);
  for (int b = 0; b < goals.num_blocks(); ++b)
    if (goals.block(b).effector == e && residual.segment<3>(3 * b).norm() >= kOffTargetShare * largest) return true;
  return false;
}

void tip_hessian_weights(const GoalSet& goals, const Eigen::Ref<const Eigen::VectorXd>& residual,
                         Eigen::Ref<Eigen::VectorXd> weights) {
  if (goals.plain()) {
    weights = residual;
    return;
  }
  weights.setZero();
  for (int b = 0; b < goals.num_blocks(); ++b) {
    const GoalSet::Block& g = goals.block(b);
    if (!g.orientation) weights.segment<3>(3 * g.effector) = g.scale * residual.segment<3>(3 * b);
  }
}

}  // namespace ik

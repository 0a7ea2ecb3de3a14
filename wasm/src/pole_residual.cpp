// Bend hints as soft rows (pole_residual.h).
//
// Null space or small weight? The pole rows are ordinary least-squares rows with the user's
// weight, not a projection of a pole step into the null space of the hard goals' Jacobian:
// - every method (lm, gn, bfgs, newton, gd) takes them as they take any row, with their bounds
//   handling, line searches and restarts unchanged; a null-space projection would be a second
//   code path per method, and clipping at a joint limit breaks the projection anyway;
// - the swivel rows vanish on the whole bent-towards-the-pole half of the swivel circle, and the
//   reach row within one limb length of the pole, so where the tip goal is reachable with the
//   limb bent that way the weighted sum's minimum lies ON the hard goals' solution set: the pole
//   costs no tip accuracy (soft_goals_test measures it: 0 within the tolerance); the reach row's
//   small weight kappa keeps its cost far under the tolerance where the tip leaves the elbow too
//   little freedom to come within a limb length of the pole;
// - where it cannot (a target at full reach needs a straight limb, an orientation goal pins the
//   swivel), the Solver drops the soft rows when the run stops off target and goes on from there
//   (solver_move_on.cpp), so the hard goals' accuracy is never traded away.
#include "pole_residual.h"

#include <Eigen/Geometry>
#include <cmath>

namespace ik {

namespace {

struct Normalised {
  Eigen::Vector3d value;     // x / n(|x|)
  Eigen::Matrix3d jacobian;  // d value / d x
};

// x / n(|x|) with n(t) = t for t >= delta, (t^2 + delta^2) / (2 delta) below, and its derivative
// I / n - (n'(t) / t) x x^T / n^2, where n'(t) / t = 1 / t above delta and 1 / delta below.
Normalised normalise(const Eigen::Vector3d& x, double delta) {
  const double t = x.norm();
  const double n = t >= delta ? t : (t * t + delta * delta) / (2 * delta);
  const double slope = t >= delta ? 1 / t : 1 / delta;
  Normalised out;
  out.value = x / n;
  out.jacobian = Eigen::Matrix3d::Identity() / n - (slope / (n * n)) * x * x.transpose();
  return out;
}

// Below this |T - S| (a share of delta) the limb has no axis: r = 0.
constexpr double kNoAxisShare = 1e-9;

// beta of pole_residual.h's tilt factor.
constexpr double kTilt = 0.5;

// kappa of pole_residual.h's reach row: its largest value as a share of the swivel rows' scale s.
constexpr double kReach = 0.01;

// The reach row c (pole_residual.h) and its derivative with respect to S, M, T side by side.
struct ReachRow {
  double value = 0;  // rig units
  Eigen::Matrix<double, 1, 9> jacobian = Eigen::Matrix<double, 1, 9>::Zero();
};

// c = s kappa x / (l + x), x = (|M - P| - l)_+, l = |M - S| + |T - M|; where x > 0 its
// derivative is s kappa (l d|M - P| - (l + x) dl) / (l + x)^2 (c^2 is C^1 at x = 0).
ReachRow reach_row(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                   const Eigen::Vector3d& P, double s, bool with_jacobian) {
  ReachRow out;
  const Eigen::Vector3d upper = M - S, lower = T - M, away = M - P;
  const double l = upper.norm() + lower.norm(), distance = away.norm();
  const double x = distance - l;
  if (!(l > 0) || !(x > 0)) return out;
  out.value = s * kReach * x / (l + x);
  if (!with_jacobian) return out;
  // dl = a^T (dM - dS) + b^T (dT - dM), a and b the segments' unit directions (0 for a point).
  const Eigen::Vector3d a = upper.norm() > 0 ? Eigen::Vector3d(upper.normalized()) : Eigen::Vector3d::Zero();
  const Eigen::Vector3d b = lower.norm() > 0 ? Eigen::Vector3d(lower.normalized()) : Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 1, 9> dl, dd;
  dl << -a.transpose(), (a - b).transpose(), b.transpose();
  dd << Eigen::RowVector3d::Zero(), (away / distance).transpose(), Eigen::RowVector3d::Zero();
  out.jacobian = (s * kReach / ((l + x) * (l + x))) * (l * dd - (l + x) * dl);
  return out;
}

// r, and with `out` its partials.
Eigen::Vector3d evaluate(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                         const Eigen::Vector3d& P, double delta, double s, PolePartials* out) {
  const Eigen::Vector3d e = T - S;
  const double length = e.norm();
  if (!(length > kNoAxisShare * delta)) {
    if (out) out->shoulder.setZero(), out->elbow.setZero(), out->wrist.setZero();
    return Eigen::Vector3d::Zero();
  }
  const Eigen::Vector3d u = e / length;
  const Eigen::Vector3d d = M - S, p = P - S;
  const Eigen::Vector3d v = d - d.dot(u) * u, q = p - p.dot(u) * u;
  const Normalised vn = normalise(v, delta), qn = normalise(q, delta);
  const Eigen::Vector3d w = u.cross(qn.value);
  const double tilt = 1 + kTilt * vn.value.dot(w);  // 1 + beta sin(theta), in [0.5, 1.5]
  const double g = std::sqrt(tilt);
  const Eigen::Vector3d diff = qn.value - vn.value;
  const ReachRow reach = reach_row(S, M, T, P, s, out != nullptr);
  const Eigen::Vector3d r = s * g * diff + reach.value * u;  // the swivel rows lie across u: no cancelling
  if (!out) return r;
  // Derivatives with respect to S, M, T side by side (3 x 9). du = Pu de / |e|; for
  // x = y - (y.u) u: dx = Pu dy - (u y^T + (y.u) I) du.
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d Pu = I - u * u.transpose();
  const Eigen::Matrix3d Kv = (u * d.transpose() + d.dot(u) * I) * Pu / length;
  const Eigen::Matrix3d Kp = (u * p.transpose() + p.dot(u) * I) * Pu / length;
  Eigen::Matrix<double, 3, 9> Du, Dv, Dq;
  Du << -Pu / length, Eigen::Matrix3d::Zero(), Pu / length;
  Dv << vn.jacobian * (Kv - Pu), vn.jacobian * Pu, -vn.jacobian * Kv;
  Dq << qn.jacobian * (Kp - Pu), Eigen::Matrix3d::Zero(), -qn.jacobian * Kp;
  // dY for Y = vn . (u x qn): w^T dvn + (vn x u)^T dqn - (vn x qn)^T du.
  const Eigen::Matrix<double, 1, 9> dY =
      w.transpose() * Dv + vn.value.cross(u).transpose() * Dq - vn.value.cross(qn.value).transpose() * Du;
  const Eigen::Matrix<double, 3, 9> D =
      s * (g * (Dq - Dv) + (kTilt / (2 * g)) * diff * dY) + u * reach.jacobian + reach.value * Du;
  out->shoulder = D.leftCols<3>();
  out->elbow = D.middleCols<3>(3);
  out->wrist = D.rightCols<3>();
  return r;
}

}  // namespace

Eigen::Vector3d pole_residual(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                              const Eigen::Vector3d& P, double delta, double s) {
  return evaluate(S, M, T, P, delta, s, nullptr);
}

void pole_partials(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                   const Eigen::Vector3d& P, double delta, double s, PolePartials& out) {
  evaluate(S, M, T, P, delta, s, &out);
}

}  // namespace ik

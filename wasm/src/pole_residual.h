// The residual of a bend hint (goals.h PoleGoal) for a two-bone limb S (shoulder) - M (elbow)
// - T (wrist) and a pole point P, all world points in rig units:
//   u = (T - S) / |T - S|                   the limb's axis
//   v = P_u (M - S),  q = P_u (P - S)       bend and pole, projected off the axis (P_u = I - u u^T)
//   qn = q / n(|q|),  vn = v / n(|v|)       unit directions once beyond delta
//   r = s sqrt(1 + beta vn.(u x qn)) (qn - vn) + c u     3 rows, rig units (s = w L, beta = 0.5)
// with n(t) = t for t >= delta and (t^2 + delta^2) / (2 delta) below it (C^1 at delta), delta
// the "bend floor" (goals.cpp: 5% of the limb's shorter segment), and the reach row
//   c = s kappa x / (l + x),  x = (|M - P| - l)_+,  l = |M - S| + |T - M|  (kappa = 0.01).
// The first term (the swivel rows) lies across u, the second along it, so neither cancels the
// other: |r|^2 = 2 s^2 g^2 (1 - cos theta) + c^2 for bends beyond delta, with theta the swivel
// angle from the pole's side to the bend (about u) and g^2 = 1 + beta sin theta.
//
// Why this form:
// - The swivel rows are 0 whenever the limb bends towards the pole by more than delta, however
//   much it bends: they only pick the swivel about S-T, which a reachable tip goal leaves free, so
//   they never pull the tip off a reachable target (no fight with the hard goals, hence the
//   soft-weight choice over a null-space projection: see pole_residual.cpp).
// - The swivel alone cannot move the elbow of a (nearly) straight limb: a whole turn moves it
//   twice its distance off S-T, and a pole moved along S-T (the knight's hanging arm, its pole
//   dragged up) changes nothing. The reach row pulls M towards P once P is more than one limb
//   length from M, as far as the tip goal leaves the limb free to bend (a hand pivoting about its
//   fingertip, a collarbone): 0 where the page places a pole (one limb length from the joint) and
//   wherever the joint is within that of its pole. Where the freedom ends short of it, the row
//   stays on and trades a little tip accuracy (kappa keeps it far under the page's tolerance:
//   5e-5 of the knight's 1.9e-3); c < s kappa bounds that for a pole however far.
// - At a straight limb (v = 0) r's swivel rows are s q_hat != 0 and dr/dv = -(2 / delta) s P_u:
//   finite, no NaN, and the gradient bends the limb towards the pole.
// - The tilt factor sqrt(1 + beta sin theta) moves |r|^2's maximum along the swivel from the
//   mirrored bend (theta = 180 degrees, where (1 - cos theta) alone is flat) to theta ~ 145
//   degrees on one side: a pole placed in the bend plane on the other side (the usual way to
//   flip a knee) has a slope to descend. Only a bend exactly at that asymmetric maximum stays.
// - A pole on the S-T axis (|q| < delta) weakens the preference (q / n(|q|) shrinks); a limb
//   folded so that T = S gives r = 0 (no axis).
#pragma once

#include <Eigen/Core>

namespace ik {

// The partial derivatives of pole_residual() with respect to S, M and T (3 x 3 each, rig units
// per rig unit): dr = dS_ dS + dM_ dM + dT_ dT (the pole P is fixed).
struct PolePartials {
  Eigen::Matrix3d shoulder, elbow, wrist;
};

// r (3 rows, rig units) for points S, M, T, P (rig units), bend floor `delta` > 0 (rig units),
// scale `s` = w L (rig units). No allocation.
Eigen::Vector3d pole_residual(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                              const Eigen::Vector3d& P, double delta, double s);

// Its partials at the same arguments; writes `out`. No allocation.
void pole_partials(const Eigen::Vector3d& S, const Eigen::Vector3d& M, const Eigen::Vector3d& T,
                   const Eigen::Vector3d& P, double delta, double s, PolePartials& out);

}  // namespace ik

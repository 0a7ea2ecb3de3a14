// The residual-size damped system of lm's step and the strict-priority step,
//   (Jf W Jf^T + D) y = rhs,
// solved pass after pass by the active set (active_set.h), each pass with fewer angles: an angle
// fixed on its limit takes its column out (its known move goes to the right-hand side). The first
// pass factors the matrix; a later one downdates that factor by the column taken out (rank one,
// O(m^2) against the factorisation's O(m^3): lm's steps on the avatar took 2.05 factorisations
// of its 30 x 30 system each). A downdate that would lose the factor's accuracy (a pivot falling
// below kDowndateShare of itself, small_cholesky.h) is not used: the next pass factors the
// reduced matrix afresh. No allocation after resize().
#pragma once

#include <Eigen/Core>

#include "block_pattern.h"

namespace ik {

class DampedSystem {
 public:
  // Workspace for m rows (allocates).
  void resize(int m);

  // A new system: the matrix `normal` (Jf W Jf^T over the free angles, m x m) plus diag(shift())
  // and the right-hand side `rhs` (m). Fill shift() before the first solve().
  void begin(const Eigen::MatrixXd& normal, const Eigen::Ref<const Eigen::VectorXd>& rhs);
  // The diagonal added to the matrix (m; rig units^2 like Jf Jf^T).
  Eigen::VectorXd& shift() { return shift_; }

  // Solves the system as it now stands; y() is the solution. False if the matrix is not
  // numerically positive definite.
  bool solve();
  const Eigen::VectorXd& y() const { return y_; }

  // Angle i (column i of `J`, of sparsity `pattern`) leaves the system having moved by `d`
  // (degrees): the matrix loses w_i J_i J_i^T, the right-hand side gains d J_i.
  void take_out(const BlockPattern& pattern, const Eigen::MatrixXd& J, int i, double d);

 private:
  Eigen::MatrixXd reduced_, factor_;
  Eigen::VectorXd rhs_, shift_, y_, column_;
  bool factored_ = false;  // factor_ holds the Cholesky factor of reduced_ + diag(shift_)
};

}  // namespace ik

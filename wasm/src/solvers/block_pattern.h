// Which residual blocks each angle moves: the sparsity of the Jacobian in 3-row blocks. A column
// of J (an angle of bone b) is non-zero only in the blocks of the goals whose chain holds b: an
// effector's position and orientation blocks, a pole's, a rest bone's (GoalSet::moving_bones()).
// The damped systems at the residual size (lm's step, the strict-priority step) are built from
// these 3x1 blocks only: on a character's 65 bones a finger's column touches one hand's blocks,
// not all 27 rows.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "goals.h"
#include "kinematics.h"

namespace ik {

class BlockPattern {
 public:
  // The pattern of `goals` on `kin` (allocates: set-up only).
  void build(const Kinematics& kin, const GoalSet& goals);

  // The weight of a floating root's translation columns in the damped steps (the solver option
  // root_unit squared: a step's size counts the root's move in units of root_unit); the angles'
  // columns weigh 1. Kept across build().
  void set_root_weight(double weight) { root_weight_ = weight; }
  // Column j's weight w_j: 1 for an angle, the root weight for a floating root's translation.
  double weight(int j) const { return j >= root_start_ ? root_weight_ : 1.0; }

  // Adds w_j J_j J_j^T to the upper block triangle of `normal` (m x m, m = J's rows); call
  // symmetrize() after the last column. No allocation.
  void accumulate(const Eigen::MatrixXd& J, int j, Eigen::MatrixXd& normal) const;
  // Copies the upper block triangle of `normal` onto the lower one.
  void symmetrize(Eigen::MatrixXd& normal) const;
  // Angle i leaves the system having moved by `d` (degrees): `reduced` -= w_i J_i J_i^T (both
  // triangles), `rhs` += d J_i.
  void take_out(const Eigen::MatrixXd& J, int i, double d, Eigen::VectorXd& rhs, Eigen::MatrixXd& reduced) const;
  // J_i . y over the blocks angle i moves.
  double dot(const Eigen::MatrixXd& J, int i, const Eigen::VectorXd& y) const;
  // out += d J_i.
  void add(const Eigen::MatrixXd& J, int i, double d, Eigen::VectorXd& out) const;

 private:
  int blocks_ = 0;
  int root_start_ = 0;  // the first floating-root column (the number of columns without one)
  double root_weight_ = 1.0;
  // Per angle j: the blocks it moves, blocks_of_[start_[j]..start_[j+1]), ascending.
  std::vector<int> start_, blocks_of_;
};

}  // namespace ik

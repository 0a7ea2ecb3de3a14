// Forward kinematics and its derivatives for one rig, with every buffer allocated at set-up.
//
// Angles: a vector A of 3 * #bones values in DEGREES, bone i owns A[3i..3i+2] = (x, z, x).
// The pose transform of bone i is, exactly as PROTOCOL.md composes it,
//   T_i = T_parent * rest_i * Rx(a0) * Rz(a1) * Rx(a2) * rest_i^-1
// and its tip is T_i * rest_i * (length, 0, 0). With a floating root (Rig::floating_root on) A has
// three more values at the end, A[3 #bones..+2], in RIG UNITS: a world translation t of every
// root, T_root = Trans(t) * rest_root * Rx Rz Rx * rest_root^-1. The solvers treat them as angles
// with limits (the root's bounds); off, A and everything computed from it are as without it.
// Tips: a vector of 3 * #effectors values, effector k at [3k..3k+2], in rig units.
//
// Locked angles cost (nearly) nothing: an angle locked at 0 (min == max == 0, as a URDF joint's a1
// and a2, docs/urdf.md) whose value is +-0 skips its rotation in forward() (a rotation by 0 is the
// identity: the pose is the same up to the sign of zero entries), and the solvers' Jacobian
// (Columns::movable) leaves the columns of fixed angles (min >= max) at 0.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "rig.h"

namespace ik {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180.0;

class Kinematics {
 public:
  // Validates the rig (throws RigError) and allocates every buffer.
  explicit Kinematics(Rig rig);

  const Rig& rig() const { return rig_; }
  int num_bones() const { return static_cast<int>(rig_.bones.size()); }
  // Unknowns: 3 per bone, plus 3 for a floating root (its translation, rig units, last).
  int num_angles() const { return 3 * num_bones() + (floats() ? 3 : 0); }
  bool floats() const { return rig_.floating_root.on; }
  // Index of the floating root's x translation in the angles (3 * #bones); -1 without one.
  int root_translation() const { return floats() ? 3 * num_bones() : -1; }
  int num_effectors() const { return static_cast<int>(rig_.effectors.size()); }
  int num_residuals() const { return 3 * num_effectors(); }

  // Replaces the end-effector list (bone indices). Throws RigError if one is not a bone, one is
  // listed twice, or the list is empty or past the limits (size_limits.h).
  void set_effectors(const std::vector<int>& effectors);

  // Poses the rig at `angles` (#angles, degrees). Afterwards pose(), tip(), joint_axis() and
  // joint_origin() describe that pose. No allocation. Angles bit for bit those of the last call
  // keep its pose (a tracked frame's solve starts where the last one ended: its rig is posed).
  void forward(const Eigen::Ref<const Eigen::VectorXd>& angles);

  // After forward(): bone i's pose transform T_i (rest space -> posed world).
  Eigen::Isometry3d pose(int bone) const { return frame_[bone] * rest_inv_[bone]; }
  // After forward(): bone i's tip in world coordinates.
  Eigen::Vector3d tip(int bone) const { return frame_[bone] * Eigen::Vector3d(rig_.bones[bone].length, 0, 0); }
  // After forward(): the world rotation of bone i's frame (canonical bone -> world: its x axis runs
  // along the bone to the tip). Orientation goals (goals.h) target this rotation.
  Eigen::Matrix3d tip_rotation(int bone) const { return frame_[bone].linear(); }
  // After forward(): the world rotation axis (unit) of angle k in {0, 1, 2} of bone i.
  Eigen::Vector3d joint_axis(int bone, int k) const { return axes_[bone].col(k); }
  // After forward(): the world position of bone i's joint (the tail of the bone).
  Eigen::Vector3d joint_origin(int bone) const { return frame_[bone].translation(); }
  // Bones from a root down to end effector k's bone (inclusive), parents first.
  const std::vector<int>& effector_chain(int k) const { return chains_[k]; }

  // Poses the rig and writes the end-effector tips (#residuals) to `tips`.
  void tips(const Eigen::Ref<const Eigen::VectorXd>& angles, Eigen::Ref<Eigen::VectorXd> tips);

  // Poses the rig and writes the tips and the analytic Jacobian d tips / d angles
  // (#residuals x #angles, rig units per DEGREE). No allocation.
  void jacobian(const Eigen::Ref<const Eigen::VectorXd>& angles, Eigen::Ref<Eigen::VectorXd> tips,
                Eigen::Ref<Eigen::MatrixXd> jac);

  // Writes the tips at the current pose (after forward()).
  void current_tips(Eigen::Ref<Eigen::VectorXd> tips) const;
  // Which columns current_jacobian() fills: all of them, or those of the movable angles only
  // (min < max; the columns of fixed angles stay 0: the solvers never read them, free_set.h).
  enum class Columns { all, movable };
  // Writes the Jacobian at the current pose (after forward()). A floating root's columns are the
  // identity in every effector's rows (rig units per rig unit).
  void current_jacobian(Eigen::Ref<Eigen::MatrixXd> jac, Columns columns = Columns::all) const;
  // Bit k (k in {0, 1, 2}) set when bone i's angle k is movable (min < max); 7 with `all`.
  int columns_of(int bone, Columns columns) const { return columns == Columns::all ? 7 : movable_[bone]; }

  // Clamps each angle into its [min, max] limits (degrees; a floating root's bounds, rig units), in place.
  void project(Eigen::Ref<Eigen::VectorXd> angles) const;
  const Eigen::VectorXd& lower() const { return lower_; }  // #angles lower limits, degrees (root: rig units)
  const Eigen::VectorXd& upper() const { return upper_; }  // #angles upper limits, degrees

 private:
  void precompute();
  void precompute_chains();

  Rig rig_;
  std::vector<int> order_;                // bones, parents before children
  std::vector<std::vector<int>> chains_;  // per end effector: root..its bone
  std::vector<Eigen::Isometry3d> rest_;   // rest_i
  std::vector<Eigen::Isometry3d> rest_inv_;
  std::vector<Eigen::Isometry3d> from_parent_;  // rest_parent^-1 * rest_i (rest_i for a root)
  std::vector<Eigen::Isometry3d> frame_;        // T_parent * rest_i * Rx Rz Rx: canonical bone -> world
  Eigen::VectorXd posed_;                       // the angles frame_ and axes_ are posed at
  bool posed_valid_ = false;                    // false until the first forward()
  std::vector<Eigen::Matrix3d> axes_;           // world joint axes (x, z, x) per bone
  std::vector<unsigned char> zero_locked_;      // per bone, bit k: angle k is locked at 0 (min == max == 0)
  std::vector<unsigned char> movable_;          // per bone, bit k: angle k is movable (min < max)
  Eigen::VectorXd lower_, upper_;
};

}  // namespace ik

// The `kdl_nr_jl` method of the native bench: Orocos KDL's own ChainIkSolverPos_NR_JL over its
// ChainIkSolverVel_pinv, run as TRAC-IK's harness runs it for the KDL column of its published
// table (trac_ik_examples/src/ik_tests.cpp, bench-node/tracik.ts): one Newton-Raphson iteration
// per CartToJnt call (maxiter 1), each call from the last one's result, until KDL reports success
// (every component of the twist between the tip's frame and the target within eps) or the time
// budget runs out. No damping, no restarts, no step limit of ours: the library's solver as
// published. Whole poses of a single end effector only (a serial chain: the chain is the rig's
// path from its root to that effector; angles fixed by their limits are fixed segments of it).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "../../src/rig.h"
#include "../../src/solvers/solver_options.h"
#include "kdl_solver.h"

namespace ik::kdl {

class KdlNrJl {
 public:
  // The chain of `rig` to its one end effector (throws std::invalid_argument for another count).
  // Uses of `options`: tip_tolerance (KDL's eps, rig units and radians; 0: 1e-5), max_iterations,
  // time_budget_s, orientation_tolerance_deg (for `reached`).
  KdlNrJl(const Rig& rig, const SolverOptions& options);
  ~KdlNrJl();

  // Solves from `start` (#angles, degrees) towards the pose `target` (3 numbers, rig units) and
  // `orientations` (one rotation: the tip bone's frame, world). Positions alone (no rotation) are
  // refused as invalid_input: KDL's test is on the whole twist. The summary's iterations count
  // CartToJnt calls.
  const KdlSummary& solve(const Eigen::VectorXd& start, const Eigen::VectorXd& target,
                          const std::vector<Eigen::Matrix3d>& orientations);

  const SolverOptions& options() const { return options_; }

 private:
  struct State;
  std::unique_ptr<State> s_;
  SolverOptions options_;
  KdlSummary summary_;
};

}  // namespace ik::kdl

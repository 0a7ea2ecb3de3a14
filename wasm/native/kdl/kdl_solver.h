// The `kdl` method of the native bench: position goals (or whole poses) solved with Orocos KDL's
// tree solvers. Each iteration is one Newton-Raphson step of KDL's TreeIkSolverVel_wdls (damped
// least squares over the stacked 6-row Jacobians of the effectors; for position goals the rotation
// rows are weighted 0 so that only positions count, for pose goals they are weighted L, the core's
// length scale: rig_reach, goals.h), added to the joints and clamped to their limits as
// TreeIkSolverPos_NR_JL does. A step that does not lower E is tried again with more damping (Levenberg-Marquardt's
// rule on KDL's damping factor). The outer loop is ours because KDL's position solvers test convergence in 6D: it tests
// the run's own "on target" (E < error_tolerance, or every tip within tip_tolerance), the time
// budget and the iteration cap, and restarts a stalled run from the core's quasi-random points
// (restarts.h, the same sequence and seed as every other method), keeping the best point.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "../../src/rig.h"
#include "../../src/solvers/solver_options.h"

namespace ik::kdl {

struct KdlSummary {
  Eigen::VectorXd angles;         // best angles found (#angles, degrees, inside the limits)
  double E = 0;                   // 1/2 |tips - targets|^2 at `angles`, rig units^2 (pose goals: plus
                                  // 1/2 L^2 |rotation vectors|^2, as the core's E with orientation goals)
  double gradient_norm = 0;       // |J^T r| at `angles`, rig units^2 per degree
  double tip_distance = 0;        // largest distance of a tip from its target at `angles`, rig units
  double rotation_error_deg = 0;  // pose goals: largest angle of a frame from its target, degrees
  bool reached = false;           // `angles` is on target
  int iterations = 0;             // Newton-Raphson steps (a restart counts as one)
  int function_evaluations = 0, jacobian_evaluations = 0, restarts = 0;
  std::string stop_reason;  // converged_E, zero_step, max_iterations, timeout or invalid_input
  std::string message;      // why, for invalid_input
};

class KdlSolver {
 public:
  // Builds the KDL tree of `rig`. Uses of `options`: error_tolerance, tip_tolerance,
  // max_iterations, time_budget_s, restarts (none with paper_mode, as the core), stall_iterations,
  // seed (the rest is ignored).
  KdlSolver(const Rig& rig, const SolverOptions& options);
  ~KdlSolver();

  // Solves from `start` (#angles, degrees; projected into the limits) towards `targets`
  // (#effectors x 3, rig units). `on_iterate`, if set, sees every iterate's angles (degrees).
  const KdlSummary& solve(const Eigen::VectorXd& start, const Eigen::VectorXd& targets,
                          const std::function<void(const Eigen::VectorXd&)>& on_iterate = {});
  // The same towards whole poses: `orientations` holds per effector the target rotation of its
  // bone frame (world; Kinematics::tip_rotation), or is empty (positions only, as above). On target
  // then also needs every frame within options.orientation_tolerance_deg of its target.
  const KdlSummary& solve(const Eigen::VectorXd& start, const Eigen::VectorXd& targets,
                          const std::vector<Eigen::Matrix3d>& orientations,
                          const std::function<void(const Eigen::VectorXd&)>& on_iterate = {});

  const SolverOptions& options() const { return options_; }
  void set_options(const SolverOptions& options) { options_ = options; }

 private:
  struct State;
  struct Call;
  std::unique_ptr<State> s_;
  SolverOptions options_;
  KdlSummary summary_;
};

}  // namespace ik::kdl

// A solve that starts on a stationary point above the error tolerance: one bone along +x, target
// straight behind it at (-1, 0, 0). At rest grad E = J^T r = 0 (r is along the bone), yet the
// target is reachable by turning 180 degrees. lm's restarts must leave such a start at once.
#include <gtest/gtest.h>

#include "solvers/solver_registry.h"

namespace ik {
namespace {

Rig one_bone() {
  Rig rig;
  rig.bones.resize(1);
  rig.bones[0].length = 1;
  rig.effectors = {0};
  return rig;
}

TEST(StationaryStart, LmRestartsFromAStationaryStart) {
  Kinematics kin(one_bone());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3);
  const Eigen::Vector3d target(-1, 0, 0);

  SolverOptions without;
  without.restarts = 0;
  auto plain = make_solver("lm", kin, without);
  EXPECT_EQ(plain->solve(rest, target).stop_reason, StopReason::converged_grad);
  EXPECT_GT(plain->summary().E, 1.9);

  auto restarting = make_solver("lm", kin, SolverOptions{});
  const SolverSummary& r = restarting->solve(rest, target);
  EXPECT_EQ(r.stop_reason, StopReason::converged_E);
  EXPECT_GE(r.restarts, 1);
  EXPECT_LT(r.E, SolverOptions{}.error_tolerance);
}

TEST(StationaryStart, MethodsWithoutRestartsStillStopThere) {
  Kinematics kin(one_bone());
  auto gd = make_solver("gd", kin, SolverOptions{});
  const SolverSummary& r = gd->solve(Eigen::VectorXd::Zero(3), Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(r.stop_reason, StopReason::converged_grad);
  EXPECT_EQ(r.iterations, 0);
}

}  // namespace
}  // namespace ik

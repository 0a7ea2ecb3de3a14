// A solve that starts on a stationary point above the error tolerance: one bone along +x, target
// straight behind it at (-1, 0, 0). At rest grad E = J^T r = 0 (r is along the bone), yet the
// target is reachable by turning 180 degrees. Restarts (every method) must leave such a start at once.
#include <gtest/gtest.h>

#include <string>

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

class StationaryStart : public ::testing::TestWithParam<std::string> {};

TEST_P(StationaryStart, RestartsLeaveAStationaryStartAndWithoutThemTheSolveStopsThere) {
  Kinematics kin(one_bone());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3);
  const Eigen::Vector3d target(-1, 0, 0);

  SolverOptions without;
  without.restarts = 0;
  auto plain = make_solver(GetParam(), kin, without);
  EXPECT_EQ(plain->solve(rest, target).stop_reason, StopReason::converged_grad);
  EXPECT_EQ(plain->summary().iterations, 0);
  EXPECT_GT(plain->summary().E, 1.9);

  auto restarting = make_solver(GetParam(), kin, SolverOptions{});
  const SolverSummary& r = restarting->solve(rest, target);
  EXPECT_EQ(r.stop_reason, StopReason::converged_E);
  EXPECT_GE(r.restarts, 1);
  EXPECT_LT(r.E, SolverOptions{}.error_tolerance);

  SolverOptions paper;
  paper.paper_mode = true;  // the original had no restarts
  auto original = make_solver(GetParam(), kin, paper);
  EXPECT_EQ(original->solve(rest, target).restarts, 0);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, StationaryStart, ::testing::Values("gd", "bfgs", "gn", "newton", "lm"));

}  // namespace
}  // namespace ik

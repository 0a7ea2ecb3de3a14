// The stop reason describes the point a solve returns, also with restarts, where the returned
// point (the best found) can come from an earlier run than the last: converged_E exactly when
// that point is on target, converged_grad only where its gradient is under the tolerance, and E,
// the gradient norm and the tip distance are those of the returned angles.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "../small_rigs.h"
#include "objective.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// A trunk of two bones and two arms of three, with limits on most angles: restarts and bounds
// both come into play, and targets far out of reach leave runs stopped off target.
Rig branched_rig() {
  Rig rig;
  auto add = [&rig](int parent, const Eigen::Vector3d& at, double length, double limit) {
    return test::add_bone(rig, parent, at, length, limit);
  };
  const int hips = add(-1, {0, 0, 0}, 0.5, 180);
  const int chest = add(hips, {0.5, 0, 0}, 0.5, 30);
  int left = chest, right = chest;
  for (int k = 0; k < 3; ++k) {
    left = add(left, {1.0 + 0.4 * k, 0.1, 0}, 0.4, 90);
    right = add(right, {1.0 + 0.4 * k, -0.1, 0}, 0.4, 120);
  }
  rig.effectors = {left, right};
  return rig;
}

// |grad E| over the free angles, as the gradient test measures it (solver.h).
double free_gradient_norm(Kinematics& kin, const Eigen::VectorXd& angles, const Eigen::VectorXd& target) {
  Eigen::VectorXd r(kin.num_residuals()), g(kin.num_angles());
  Eigen::MatrixXd J(kin.num_residuals(), kin.num_angles());
  objective_and_gradient(kin, angles, target, r, J, g);
  double sum = 0;
  for (int i = 0; i < kin.num_angles(); ++i) {
    const double lo = kin.lower()[i], hi = kin.upper()[i];
    if (lo >= hi || (angles[i] <= lo && g[i] > 0) || (angles[i] >= hi && g[i] < 0)) continue;
    sum += g[i] * g[i];
  }
  return std::sqrt(sum);
}

void expect_consistent(Kinematics& kin, const SolverSummary& s, const Eigen::VectorXd& target, const SolverOptions& o) {
  Eigen::VectorXd r(kin.num_residuals());
  const double E = objective(kin, s.angles, target, r);
  double distance = 0;
  for (int e = 0; e < kin.num_effectors(); ++e) distance = std::max(distance, r.segment<3>(3 * e).norm());
  EXPECT_NEAR(s.E, E, 1e-12 * (1 + E));
  EXPECT_NEAR(s.tip_distance, distance, 1e-9);
  const bool on_target = o.tip_tolerance > 0 ? distance < o.tip_tolerance : E < o.error_tolerance;
  EXPECT_EQ(s.reached, on_target);
  EXPECT_EQ(s.stop_reason == StopReason::converged_E, s.reached) << stop_reason_name(s.stop_reason);
  // With goals given up the gradient is that of the given-up rows within the held ones' freedom
  // (Priority::reduced_gradient_norm, checked in strict_priority_test).
  if (s.goals_given_up == 0) {
    EXPECT_NEAR(s.gradient_norm, free_gradient_norm(kin, s.angles, target), 1e-9 * (1 + s.gradient_norm));
  }
  if (s.stop_reason == StopReason::converged_grad) {
    EXPECT_LT(s.gradient_norm, o.gradient_tolerance);
  }
}

class StopReasonConsistency : public ::testing::TestWithParam<std::string> {};

TEST_P(StopReasonConsistency, TheStopReasonDescribesTheReturnedPoint) {
  Kinematics kin(branched_rig());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (double tip_tolerance : {0.0, 1e-3}) {
    SolverOptions o;
    o.time_budget_s = 0;
    o.restarts = 4;
    o.max_iterations = 400;
    o.stall_iterations = 5;
    o.tip_tolerance = tip_tolerance;
    auto solver = make_solver(GetParam(), kin, o);
    int reached = 0, off = 0;
    for (int k = 0; k < 60; ++k) {
      // Targets in a box of 2.5 around the rig (arms reach about 2.2): some out of reach.
      Eigen::VectorXd target(kin.num_residuals());
      for (int i = 0; i < target.size(); ++i) target[i] = 2.5 * u(rng);
      const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(kin.num_angles()), target);
      SCOPED_TRACE("target " + std::to_string(k));
      expect_consistent(kin, s, target, o);
      (s.reached ? reached : off)++;
    }
    EXPECT_GT(reached, 0);
    EXPECT_GT(off, 0);
  }
}

// The case that used to claim converged_grad with a gradient 92 times the tolerance: a target far
// out of reach, restarts on, so the last run ended elsewhere than the best point.
TEST_P(StopReasonConsistency, AFarTargetWithRestartsClaimsNoStopItDidNotReach) {
  Kinematics kin(branched_rig());
  SolverOptions o;
  o.time_budget_s = 0;
  o.restarts = 20;
  Eigen::VectorXd target(kin.num_residuals());
  target << 1000, 0, 0, 1000, 5, 0;
  auto solver = make_solver(GetParam(), kin, o);
  const SolverSummary& s = solver->solve(Eigen::VectorXd::Zero(kin.num_angles()), target);
  EXPECT_FALSE(s.reached);
  expect_consistent(kin, s, target, o);
}

// A pose of the branched rig (every angle 10 degrees, within the limits) and its tips moved by
// `offset` in every coordinate: a start on target.
struct StartOnTarget {
  Eigen::VectorXd angles, target;
};
StartOnTarget start_on_target(Kinematics& kin, double offset) {
  StartOnTarget s{Eigen::VectorXd::Constant(kin.num_angles(), 10.0), Eigen::VectorXd(kin.num_residuals())};
  kin.project(s.angles);
  kin.tips(s.angles, s.target);
  s.target.array() += offset;
  return s;
}

// min_iterations: a start already on target (the tips' own positions, moved less than the tip
// tolerance) ends at once by default, and takes exactly that many iterations with the option,
// ending on target nearer than it started.
TEST_P(StopReasonConsistency, MinIterationsPolishesAStartOnTarget) {
  Kinematics kin(branched_rig());
  const auto [angles, target] = start_on_target(kin, 0.002);  // within the tip tolerance
  SolverOptions o;
  o.tip_tolerance = 0.01;
  o.restarts = 0;
  auto solver = make_solver(GetParam(), kin, o);
  const SolverSummary& left = solver->solve(angles, target);
  EXPECT_EQ(left.stop_reason, StopReason::converged_E);
  EXPECT_EQ(left.iterations, 0);
  const double start_distance = left.tip_distance;
  o.min_iterations = 1;
  solver->set_options(o);
  const SolverSummary& polished = solver->solve(angles, target);
  EXPECT_EQ(polished.stop_reason, StopReason::converged_E);
  EXPECT_EQ(polished.iterations, 1);
  EXPECT_LT(polished.tip_distance, start_distance);
  expect_consistent(kin, polished, target, o);
}

// lm with min_iterations from a start on its target to round-off (a tracked frame whose targets
// did not move): no step can lower such an error, so none is tried; the solve ends on target
// after the start's one evaluation (it used to try, and reject, lm_max_rejections steps).
TEST(LmRoundOff, AStartOnTargetToRoundOffTriesNoStep) {
  Kinematics kin(branched_rig());
  const auto [angles, target] = start_on_target(kin, 1e-15);  // round-off: a step from here is no better
  SolverOptions o;
  o.tip_tolerance = 0.01;
  o.restarts = 0;
  o.min_iterations = 1;
  auto solver = make_solver("lm", kin, o);
  const SolverSummary& s = solver->solve(angles, target);
  EXPECT_EQ(s.stop_reason, StopReason::converged_E);
  EXPECT_EQ(s.iterations, 0);
  EXPECT_EQ(s.function_evaluations, 1);
  EXPECT_EQ(s.angles, angles);
  expect_consistent(kin, s, target, o);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, StopReasonConsistency, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace ik

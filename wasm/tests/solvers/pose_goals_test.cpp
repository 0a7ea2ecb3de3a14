// Every method reaches pose goals (position and orientation of each effector's tip frame at the
// protocol's incremental angles A_k: reachable by construction) with the limits holding at every
// iterate; a goal of weight 0 changes nothing; paper mode refuses anything but plain goals.
#include <gtest/gtest.h>

#include <cstdio>

#include "../sanitizers.h"
#include "goal_residual.h"
#include "registered_methods.h"
#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

// Position and orientation of every effector's tip frame at `angles`.
Goals pose_goals(Kinematics& kin, const Eigen::VectorXd& angles) {
  kin.forward(angles);
  Goals goals;
  goals.effectors.resize(kin.num_effectors());
  for (int e = 0; e < kin.num_effectors(); ++e) {
    const int bone = kin.rig().effectors[e];
    goals.effectors[e].position_target = kin.tip(bone);
    goals.effectors[e].orientation = true;
    goals.effectors[e].orientation_target = kin.tip_rotation(bone);
  }
  return goals;
}

bool within_limits(const Kinematics& kin, const Eigen::VectorXd& a) {
  return (a.array() >= kin.lower().array()).all() && (a.array() <= kin.upper().array()).all();
}

// start() and step() to the end, checking the limits at every iterate. Returns the summary.
const SolverSummary& stepped_solve(Solver& solver, const Eigen::VectorXd& start, const Goals& goals,
                                   bool& limits_held) {
  solver.start(start, goals);
  limits_held = within_limits(solver.kinematics(), solver.angles());
  while (solver.step()) limits_held = limits_held && within_limits(solver.kinematics(), solver.angles());
  limits_held = limits_held && within_limits(solver.kinematics(), solver.summary().angles);
  return solver.summary();
}

// bfgs and gd need many iterations on A7 beast with every effector's orientation.
int max_iterations(const std::string& method) { return method == "gd" || method == "bfgs" ? 100000 : 500; }

// At most one target missed per method and rig (of the first 6 under the sanitizers).
TEST(PoseGoals, EveryMethodReachesThemOnIncrementalTargets) {
  constexpr int kSamples = test::sanitized_count(12, 6);
  for (const std::string& method : test::kMethods) {
    for (const test::TestRig& r : test::test_rigs()) {
      const std::string name = method + " " + r.label();
      Kinematics kin(r.rig);
      SolverOptions options = test::report_options(r);
      options.max_iterations = max_iterations(method);
      // Tracking a moving goal, as a drag does: no whole-pose restart (with the default 1000, bfgs
      // and gd restart from quasi-random poses after a stall on A7 beast and reach 2 and 4 of 12).
      options.restarts = 0;
      // gd descends so slowly along the orientation rows that the report's (absolute) gradient
      // test fires first, 0.03 to 1.5 degrees off (character: 3 of 12 reached with it).
      if (method == "gd") options.gradient_tolerance *= 1e-3;
      auto solver = make_solver(method, kin, options);
      int reached = 0;
      const auto cases = test::incremental_targets(kin, kSamples, 41);
      for (size_t i = 0; i < cases.size(); ++i) {
        const Goals goals = pose_goals(kin, cases[i].goal);
        bool limits_held = false;
        const SolverSummary& s = stepped_solve(*solver, cases[i].start, goals, limits_held);
        const std::string where = name + " target " + std::to_string(i) + " " + stop_reason_name(s.stop_reason);
        EXPECT_TRUE(limits_held) << where;
        EXPECT_LE(s.E, s.initial_E) << where;
        reached += s.reached;
      }
      std::printf("pose goals: %-8s %-18s reached %d of %d\n", method.c_str(), r.label().c_str(), reached, kSamples);
      EXPECT_GE(reached, kSamples - 1) << name;
    }
  }
}

TEST(PoseGoals, AnOrientationGoalOfWeightZeroIsNoGoal) {
  for (const std::string& method : test::kMethods) {
    for (const test::TestRig& r : test::test_rigs()) {
      Kinematics kin(r.rig);
      SolverOptions options = test::report_options(r);
      options.max_iterations = max_iterations(method);
      auto solver = make_solver(method, kin, options), plain = make_solver(method, kin, options);
      for (const auto& c : test::incremental_targets(kin, 3, 7)) {
        Goals goals = pose_goals(kin, c.goal);
        for (EffectorGoal& g : goals.effectors) g.orientation_weight = 0;
        const SolverSummary& with = solver->solve(c.start, goals);
        const SolverSummary& without = plain->solve(c.start, c.target);
        EXPECT_EQ(with.angles, without.angles) << method << " " << r.label();
        EXPECT_EQ(with.E, without.E) << method << " " << r.label();
        EXPECT_EQ(with.iterations, without.iterations) << method << " " << r.label();
      }
    }
  }
}

TEST(PoseGoals, MixedGoalsAndWeightsAreReached) {
  // Effector e: both goals (e % 3 == 0), orientation only (1), position only (2), weights != 1.
  for (const std::string& method : test::kMethods) {
    for (const test::TestRig& r : test::test_rigs()) {
      Kinematics kin(r.rig);
      SolverOptions options = test::report_options(r);
      options.max_iterations = max_iterations(method);
      auto solver = make_solver(method, kin, options);
      int reached = 0;
      const auto cases = test::incremental_targets(kin, 4, 3);
      for (const auto& c : cases) {
        Goals goals = pose_goals(kin, c.goal);
        for (int e = 0; e < kin.num_effectors(); ++e) {
          goals.effectors[e].position = e % 3 != 1;
          goals.effectors[e].orientation = e % 3 != 2;
          goals.effectors[e].position_weight = 2;
          goals.effectors[e].orientation_weight = 0.5;
        }
        reached += solver->solve(c.start, goals).reached;
      }
      EXPECT_GE(reached, static_cast<int>(cases.size()) - 1) << method << " " << r.label();
    }
  }
}

TEST(PoseGoals, ReachedMeansWithinTheOrientationTolerance) {
  for (const test::TestRig& r : test::rigs_like("ikea-lamp")) {
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.orientation_tolerance_deg = 0.01;
    auto solver = make_solver("lm", kin, options);
    for (const auto& c : test::incremental_targets(kin, 3, 9)) {
      const Goals goals = pose_goals(kin, c.goal);
      const SolverSummary& s = solver->solve(c.start, goals);
      ASSERT_TRUE(s.reached);
      GoalSet set;
      ASSERT_EQ(set.set(kin, goals), "");
      Eigen::VectorXd residual(set.rows());
      goal_objective(kin, set, s.angles, residual);
      EXPECT_LT(largest_orientation_error_deg(set, residual), 0.01);
    }
  }
}

TEST(PoseGoals, PaperModeRefusesOrientationGoalsAndWeights) {
  for (const test::TestRig& r : test::rigs_like("ikea-lamp")) {
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.paper_mode = true;
    auto solver = make_solver("bfgs", kin, options);
    const auto c = test::incremental_targets(kin, 1, 5)[0];
    Goals goals = pose_goals(kin, c.goal);
    EXPECT_EQ(solver->start(c.start, goals), StopReason::invalid_input);
    EXPECT_NE(solver->summary().message.find("paper mode"), std::string::npos) << solver->summary().message;
    for (EffectorGoal& g : goals.effectors) g.orientation = false;
    // Weights are relative: a goal's weight alone (or the same on every goal) is the original
    // objective, unequal ones are not.
    goals.effectors[0].position_weight = 2;
    EXPECT_NE(solver->start(c.start, goals), StopReason::invalid_input) << solver->summary().message;
    goals.effectors.push_back(goals.effectors[0]);
    goals.effectors[1].position_weight = 1;
    kin.set_effectors({kin.rig().effectors[0], kin.num_bones() / 2});
    EXPECT_EQ(solver->start(c.start, goals), StopReason::invalid_input);
    EXPECT_NE(solver->summary().message.find("paper mode"), std::string::npos) << solver->summary().message;
    goals.effectors[0].position_weight = 1;
    EXPECT_NE(solver->start(c.start, goals), StopReason::invalid_input) << solver->summary().message;
  }
}

}  // namespace
}  // namespace ik

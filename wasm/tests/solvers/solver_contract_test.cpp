// What every method promises: iterates inside the limits, stepping equals solving, bad input
// rejected with a message, no allocation while iterating, and a rig whose effectors change.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../allocation_counter.h"
#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

class EveryMethod : public ::testing::TestWithParam<std::string> {};

bool inside_limits(const Kinematics& kin, const Eigen::VectorXd& a) {
  return ((a - kin.lower()).array() >= 0).all() && ((kin.upper() - a).array() >= 0).all();
}

TEST_P(EveryMethod, IteratesStayInsideTheLimits) {
  for (bool paper : {false, true})
    for (const test::TestRig& r : test::test_rigs()) {
      const std::string name = r.label();
      Kinematics kin(r.rig);
      SolverOptions options = test::report_options(r);
      options.paper_mode = paper;
      options.max_iterations = 60;
      auto solver = make_solver(GetParam(), kin, options);
      // Random targets from outside the limits: the start is projected, the bounds get hit.
      for (const test::TargetCase& c : test::random_targets(kin, 3, 61)) {
        const Eigen::VectorXd start = Eigen::VectorXd::Constant(kin.num_angles(), 400.0);
        solver->start(start, c.target);
        do {
          ASSERT_TRUE(inside_limits(kin, solver->angles())) << name << (paper ? " paper" : "");
        } while (solver->step());
        EXPECT_TRUE(inside_limits(kin, solver->summary().angles)) << name;
        EXPECT_NE(solver->summary().stop_reason, StopReason::numerical_failure) << name << solver->summary().message;
      }
    }
}

// Between steps the rig is posed elsewhere (as the page does to draw): no effect on the solve.
void expect_stepping_equals_solving(const std::string& method, const test::TestRig& r) {
  Kinematics kin(r.rig);
  const Eigen::VectorXd elsewhere = Eigen::VectorXd::Constant(kin.num_angles(), 33.0);
  SolverOptions options = test::report_options(r);
  options.max_iterations = 300;
  options.restarts = 0;  // E falls at every iteration within one run; a restart jumps (tested below)
  options.chain_restarts = 0;
  auto stepped = make_solver(method, kin, options);
  auto solved = make_solver(method, kin, options);
  for (const test::TargetCase& c : test::random_targets(kin, 4, 62)) {
    std::vector<double> seen;
    stepped->start(c.start, c.target);
    seen.push_back(stepped->summary().E);
    kin.forward(elsewhere);
    while (stepped->step()) {
      seen.push_back(stepped->summary().E);
      kin.forward(elsewhere);
    }
    const SolverSummary& a = stepped->summary();
    const SolverSummary& b = solved->solve(c.start, c.target);
    EXPECT_EQ(a.stop_reason, b.stop_reason);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.function_evaluations, b.function_evaluations);
    EXPECT_EQ(a.jacobian_evaluations, b.jacobian_evaluations);
    EXPECT_EQ(a.E, b.E);
    EXPECT_EQ(a.angles, b.angles);
    EXPECT_EQ(stepped->error_history(), solved->error_history());
    // The history holds E at the start and after every iteration.
    ASSERT_EQ(solved->error_history().size(), b.iterations + 1);
    EXPECT_EQ(solved->error_history()[0], b.initial_E);
    // (A run with goals given up starts again from the start angles: strict_priority_test.)
    if (b.goals_given_up == 0) {
      for (int k = 1; k <= b.iterations; ++k) EXPECT_LT(solved->error_history()[k], solved->error_history()[k - 1]);
    }
  }
}

TEST_P(EveryMethod, SteppingEqualsSolving) {
  for (const test::TestRig& r : test::rigs_like("knight")) {
    SCOPED_TRACE(r.label());
    expect_stepping_equals_solving(GetParam(), r);
  }
}

void expect_bad_input_rejected(const std::string& method, const Rig& rig) {
  Kinematics kin(rig);
  auto solver = make_solver(method, kin, SolverOptions{});
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(kin.num_angles());
  const Eigen::VectorXd t = Eigen::VectorXd::Zero(kin.num_residuals());
  auto expect_invalid = [&](const Eigen::VectorXd& angles, const Eigen::VectorXd& target, const std::string& mentions) {
    EXPECT_EQ(solver->start(angles, target), StopReason::invalid_input) << mentions;
    EXPECT_NE(solver->summary().message.find(mentions), std::string::npos) << solver->summary().message;
    EXPECT_FALSE(solver->step());
    EXPECT_EQ(solver->solve(angles, target).stop_reason, StopReason::invalid_input);
  };
  Eigen::VectorXd bad = a;
  bad[2] = std::numeric_limits<double>::quiet_NaN();
  expect_invalid(bad, t, "angles[2]");
  bad[2] = std::numeric_limits<double>::infinity();
  expect_invalid(bad, t, "angles[2]");
  Eigen::VectorXd bad_target = t;
  bad_target[1] = -std::numeric_limits<double>::infinity();
  expect_invalid(a, bad_target, "target[1]");
  bad_target[1] = std::numeric_limits<double>::quiet_NaN();
  expect_invalid(a, bad_target, "target[1]");
  const auto wrong_size = [](const char* what, int got, int expected) {
    return std::string(what) + " has " + std::to_string(got) + " values, expected " + std::to_string(expected);
  };
  const int m = kin.num_angles(), r = kin.num_residuals();
  expect_invalid(Eigen::VectorXd::Zero(m + 1), t, wrong_size("angles", m + 1, m));
  expect_invalid(a, Eigen::VectorXd::Zero(r - 1), wrong_size("target", r - 1, r));

  SolverOptions options;
  options.error_tolerance = -1;
  auto with_bad_option = make_solver(method, kin, options);
  EXPECT_EQ(with_bad_option->start(a, t), StopReason::invalid_input);
  EXPECT_NE(with_bad_option->summary().message.find("error_tolerance"), std::string::npos);

  // And a good start after the bad ones works.
  Eigen::VectorXd target(kin.num_residuals());
  kin.tips(Eigen::VectorXd::Constant(kin.num_angles(), 10.0), target);
  EXPECT_NE(solver->solve(a, target).stop_reason, StopReason::invalid_input);
}

TEST_P(EveryMethod, RejectsBadInputWithAMessage) {
  for (const test::TestRig& r : test::rigs_like("ikea-lamp")) {
    SCOPED_TRACE(r.label());
    expect_bad_input_rejected(GetParam(), r.rig);
  }
}

void expect_no_allocation_while_stepping(const std::string& method, const test::TestRig& r) {
  for (bool paper : {false, true}) {
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.paper_mode = paper;
    options.max_iterations = 40;
    options.restarts = 3;  // lm's restarts run inside step() too
    options.stall_iterations = 5;
    auto solver = make_solver(method, kin, options);
    for (const test::TargetCase& c : test::random_targets(kin, 2, 63)) {
      solver->start(c.start, c.target);
      const long before = test::heap_allocations();
      while (solver->step()) {
      }
      EXPECT_EQ(test::heap_allocations() - before, 0)
          << (paper ? "paper mode" : "") << " " << stop_reason_name(solver->summary().stop_reason);
      EXPECT_GT(solver->summary().iterations, 0);
      // A second start with the same sizes allocates nothing either.
      const long again = test::heap_allocations();
      solver->start(c.start, c.target);
      EXPECT_EQ(test::heap_allocations() - again, 0);
    }
  }
}

TEST_P(EveryMethod, AllocatesNothingWhileStepping) {
  for (const test::TestRig& r : test::rigs_like("beast")) {
    SCOPED_TRACE(r.label());
    expect_no_allocation_while_stepping(GetParam(), r);
  }
}

void expect_effector_changes_noticed(const std::string& method, const test::TestRig& r) {
  Kinematics kin(r.rig);
  const std::vector<int> all = r.rig.effectors;
  ASSERT_GE(all.size(), 4u);
  const SolverOptions options = test::report_options(r);
  auto solver = make_solver(method, kin, options);
  const auto cases = test::incremental_targets(kin, 1, 64);
  solver->start(cases[0].start, cases[0].target);
  ASSERT_TRUE(solver->running());
  kin.set_effectors({all[0], all[1]});  // 4 or more effectors -> 2 while the solve runs
  EXPECT_FALSE(solver->step());
  EXPECT_EQ(solver->summary().stop_reason, StopReason::invalid_input);
  EXPECT_NE(solver->summary().message.find("start()"), std::string::npos);
  // The old target no longer fits; a target for the new effectors solves.
  EXPECT_EQ(solver->start(cases[0].start, cases[0].target), StopReason::invalid_input);
  Eigen::VectorXd target(kin.num_residuals());
  kin.tips(cases[0].goal, target);
  const SolverSummary& s = solver->solve(cases[0].start, target);
  EXPECT_TRUE(s.stop_reason == StopReason::converged_E || s.stop_reason == StopReason::converged_grad)
      << stop_reason_name(s.stop_reason);
  // Other effectors, same count: the workspace's structure follows them too.
  kin.set_effectors({all[all.size() - 2], all.back()});
  kin.tips(cases[0].goal, target);
  const SolverSummary& t = solver->solve(cases[0].start, target);
  EXPECT_TRUE(t.stop_reason == StopReason::converged_E || t.stop_reason == StopReason::converged_grad)
      << stop_reason_name(t.stop_reason);
  EXPECT_LT(t.E, options.error_tolerance);
}

TEST_P(EveryMethod, NoticesWhenTheRigsEffectorsChange) {
  for (const test::TestRig& r : test::rigs_like("knight")) {
    SCOPED_TRACE(r.label());
    expect_effector_changes_noticed(GetParam(), r);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryMethod, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

TEST(SolverRegistry, ListsTheFiveMethodsAndRejectsUnknownNames) {
  // The built-in methods, first (toy_method_test.cpp may have registered one after them).
  const std::vector<std::string> names = solver_names();
  ASSERT_GE(names.size(), 5u);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 5),
            (std::vector<std::string>{"lm", "gn", "bfgs", "newton", "gd"}));
  Kinematics kin(test::rigs_like("ikea-lamp").front().rig);  // any rig
  for (const std::string& name : solver_names()) EXPECT_EQ(make_solver(name, kin)->name(), name);
  try {
    make_solver("simplex", kin);
    FAIL() << "no error for an unknown method";
  } catch (const RigError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown solver method \"simplex\" (known: lm, gn, bfgs, newton, gd"),
              std::string::npos)
        << e.what();
  }
}

TEST(StopReasons, HaveTheirEnumeratorNames) {
  EXPECT_STREQ(stop_reason_name(StopReason::running), "running");
  EXPECT_STREQ(stop_reason_name(StopReason::converged_E), "converged_E");
  EXPECT_STREQ(stop_reason_name(StopReason::converged_grad), "converged_grad");
  EXPECT_STREQ(stop_reason_name(StopReason::zero_step), "zero_step");
  EXPECT_STREQ(stop_reason_name(StopReason::max_iterations), "max_iterations");
  EXPECT_STREQ(stop_reason_name(StopReason::timeout), "timeout");
  EXPECT_STREQ(stop_reason_name(StopReason::invalid_input), "invalid_input");
  EXPECT_STREQ(stop_reason_name(StopReason::numerical_failure), "numerical_failure");
}

TEST(SolverOptions, SetOptionsTakesEffectAtTheNextStart) {
  for (const test::TestRig& r : test::rigs_like("beast")) {
    SCOPED_TRACE(r.label());
    Kinematics kin(r.rig);
    auto solver = make_solver("gd", kin, test::report_options(r));
    const auto c = test::random_targets(kin, 1, 66)[0];
    solver->start(c.start, c.target);
    SolverOptions options = test::report_options(r);
    options.max_iterations = 3;
    solver->set_options(options);
    EXPECT_NE(solver->options().max_iterations, 3);  // the running solve keeps its options
    EXPECT_EQ(solver->solve(c.start, c.target).iterations, 3);
    EXPECT_EQ(solver->options().max_iterations, 3);
  }
}

TEST(SolverLimits, MaxIterationsAndHistoryCapacity) {
  for (const test::TestRig& r : test::rigs_like("beast")) {
    SCOPED_TRACE(r.label());
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.max_iterations = 7;
    options.history_capacity = 4;
    auto solver = make_solver("gd", kin, options);
    const auto c = test::random_targets(kin, 1, 65)[0];
    const SolverSummary& s = solver->solve(c.start, c.target);
    EXPECT_EQ(s.stop_reason, StopReason::max_iterations);
    EXPECT_EQ(s.iterations, 7);
    EXPECT_EQ(solver->error_history().size(), 4);  // the first four values are kept
    options.max_iterations = 0;
    EXPECT_EQ(make_solver("lm", kin, options)->solve(c.start, c.target).stop_reason, StopReason::max_iterations);
  }
}

}  // namespace
}  // namespace ik

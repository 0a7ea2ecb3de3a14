// Every method solves the report's incremental targets on the project's rigs and the five A7 rigs
// to the report's tolerances (analytic derivatives; paper mode is compared with the original in
// paper_mode_test).
#include <gtest/gtest.h>

#include "solver_fixtures.h"
#include "solvers/solver_registry.h"

namespace ik {
namespace {

struct Expectation {
  int samples;
  int max_iterations;
  double min_success;  // fraction of solves ending with E < error_tolerance (the rest stop on |g|)
};

Expectation expectation(const std::string& method) {
  if (method == "gd") return {20, 20000, 0.5};  // slow: stops on the gradient test just above E's
  if (method == "bfgs") return {40, 500, 0.95};
  if (method == "gn") return {40, 200, 0.9};  // a few stop on |g| < tolerance above E's
  return {40, 200, 1.0};
}

class IncrementalTargets : public ::testing::TestWithParam<std::string> {};

TEST_P(IncrementalTargets, SolvedToTheReportsTolerances) {
  const std::string method = GetParam();
  const Expectation expect = expectation(method);
  for (const test::TestRig& r : test::test_rigs()) {
    const std::string name = r.label();
    Kinematics kin(r.rig);
    SolverOptions options = test::report_options(r);
    options.max_iterations = expect.max_iterations;
    auto solver = make_solver(method, kin, options);
    int successes = 0;
    const auto cases = test::incremental_targets(kin, expect.samples, 41);
    for (size_t i = 0; i < cases.size(); ++i) {
      const SolverSummary& s = solver->solve(cases[i].start, cases[i].target);
      const std::string where = name + " target " + std::to_string(i) + " " + stop_reason_name(s.stop_reason);
      EXPECT_TRUE(s.stop_reason == StopReason::converged_E || s.stop_reason == StopReason::converged_grad) << where;
      EXPECT_LE(s.E, s.initial_E) << where;
      successes += s.E < options.error_tolerance;
    }
    EXPECT_GE(successes, expect.min_success * cases.size()) << name << ": " << successes << " of " << cases.size();
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, IncrementalTargets, ::testing::ValuesIn(solver_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace ik

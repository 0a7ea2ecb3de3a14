// The option list (solver_options.def) through for_each_option() and check_options(): every
// option is visited once under a unique name, the ranges accept and refuse what they say, and the
// messages name the option and its rule.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <type_traits>

#include "../allocation_counter.h"
#include "solvers/solver_options.h"

namespace ik {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(SolverOptions, EveryOptionHasUniqueCppAndCamelCaseJavaScriptNames) {
  std::set<std::string> names, js_names;
  int count = 0;
  SolverOptions o;
  for_each_option(o, [&](const OptionInfo& info, const auto&) {
    ++count;
    names.insert(info.name);
    js_names.insert(info.js_name);
    const std::string js = info.js_name;
    EXPECT_EQ(js.find('_'), std::string::npos) << js;
    EXPECT_TRUE(js[0] >= 'a' && js[0] <= 'z') << js;
  });
  EXPECT_EQ(names.size(), static_cast<size_t>(count));
  EXPECT_EQ(js_names.size(), static_cast<size_t>(count));
  EXPECT_EQ(count, 32);  // 24, then rest_weight and rest_from_start, strict_priority, max_joint_move, min_iterations,
                         // root_unit, steps_before_budget, soft_iterations
  EXPECT_TRUE(js_names.count("timeBudgetSeconds"));
  EXPECT_TRUE(names.count("time_budget_s"));
}

TEST(SolverOptions, TheVisitorReachesTheStructsFields) {
  SolverOptions o;
  for_each_option(o, [](const OptionInfo& info, auto& field) {
    using T = std::decay_t<decltype(field)>;
    if (std::string(info.name) == "armijo_c1") field = static_cast<T>(0.25);
    if (std::string(info.name) == "max_backtracks") field = static_cast<T>(7);
    if (std::string(info.name) == "escape_saddles") field = static_cast<T>(false);
    if (std::string(info.name) == "seed") field = static_cast<T>(4000000000u);
  });
  EXPECT_EQ(o.armijo_c1, 0.25);
  EXPECT_EQ(o.max_backtracks, 7);
  EXPECT_FALSE(o.escape_saddles);
  EXPECT_EQ(o.seed, 4000000000u);
  // The others keep the list's defaults.
  EXPECT_DOUBLE_EQ(o.gd_initial_step, 180 / 3.14159265358979323846);
  EXPECT_EQ(o.lm_max_rejections, 30);
}

TEST(SolverOptions, TheDefaultsAreValidAndCheckingThemAllocatesNothing) {
  const SolverOptions o;
  EXPECT_EQ(check_options(o), "");
  const long before = test::heap_allocations();
  const std::string problem = check_options(o);
  EXPECT_EQ(test::heap_allocations() - before, 0);
  EXPECT_TRUE(problem.empty());
}

// check_options() with one double option set to `value`.
std::string with_double(const char* name, double value) {
  SolverOptions o;
  for_each_option(o, [&](const OptionInfo& info, auto& field) {
    if constexpr (std::is_same_v<std::decay_t<decltype(field)>, double>)
      if (std::string(info.name) == name) field = value;
  });
  return check_options(o);
}

TEST(SolverOptions, RangesRefuseWhatTheirMessagesSay) {
  // finite_at_least(0): 0 in, below 0, infinity and NaN out.
  EXPECT_EQ(with_double("gradient_tolerance", 0), "");
  EXPECT_EQ(with_double("gradient_tolerance", -1e-300), "option gradient_tolerance must be a number >= 0");
  EXPECT_NE(with_double("gradient_tolerance", kInf), "");
  EXPECT_NE(with_double("gradient_tolerance", kNaN), "");
  // finite_above(0) with a note: error_tolerance 0 can never be met (E < 0 never holds).
  EXPECT_EQ(with_double("error_tolerance", 5e-324), "");
  EXPECT_EQ(with_double("error_tolerance", 0),
            "option error_tolerance must be a number > 0 (0 can never be met: on target means E < it, and E is "
            "never below 0)");
  EXPECT_NE(with_double("error_tolerance", kInf), "");
  // at_least(0) with a note: infinity in (no limit).
  EXPECT_EQ(with_double("time_budget_s", kInf), "");
  EXPECT_EQ(with_double("time_budget_s", -1), "option time_budget_s must be >= 0 (0 or infinity: no limit)");
  EXPECT_NE(with_double("time_budget_s", kNaN), "");
  // finite_above(0): 0 out.
  EXPECT_EQ(with_double("gd_initial_step", 0), "option gd_initial_step must be a number > 0");
  // in_range with a note: paper mode's difference step within kMinFdStepDeg..kMaxFdStepDeg.
  EXPECT_EQ(with_double("fd_step_deg", 1e-9), "");
  EXPECT_EQ(with_double("fd_step_deg", 1), "");
  for (const double step : {0.0, 1e-300, 9e-10, 1.5, 1e308})
    EXPECT_EQ(with_double("fd_step_deg", step),
              "option fd_step_deg must be in 1e-09..1 (degrees: smaller steps are lost to rounding, larger ones miss "
              "the slope)")
        << step;
  // A soft pull's weight: at most kMaxSoftWeight.
  EXPECT_EQ(with_double("rest_weight", 1000), "");
  EXPECT_EQ(with_double("rest_weight", 1e80), "option rest_weight must be in 0..1000 (a soft pull's largest weight)");
  // above(0): infinity in (no cap), 0 out.
  EXPECT_EQ(with_double("gn_max_step_deg", kInf), "");
  EXPECT_EQ(with_double("gn_max_step_deg", 0), "option gn_max_step_deg must be > 0");
  // open_interval(0, 1) and half_open(0, 1).
  EXPECT_EQ(with_double("backtrack_factor", 1), "option backtrack_factor must be in (0, 1)");
  EXPECT_NE(with_double("backtrack_factor", 0), "");
  EXPECT_EQ(with_double("backtrack_factor", 0.999), "");
  EXPECT_EQ(with_double("armijo_c1", 0), "");
  EXPECT_EQ(with_double("armijo_c1", 1), "option armijo_c1 must be in [0, 1)");
}

TEST(SolverOptions, IntegerRangesAndTheFirstProblemInListOrder) {
  SolverOptions o;
  o.history_capacity = kMaxHistory + 1;
  EXPECT_EQ(check_options(o), "option history_capacity must be in 1..1000000");
  o.history_capacity = kMaxHistory;
  EXPECT_EQ(check_options(o), "");
  o.max_backtracks = 0;
  EXPECT_EQ(check_options(o), "option max_backtracks must be in 1..1000");
  o.max_iterations = -1;  // listed before max_backtracks
  EXPECT_EQ(check_options(o), "option max_iterations must be >= 0");
  o = SolverOptions();
  o.lm_max_rejections = 0;
  EXPECT_EQ(check_options(o), "option lm_max_rejections must be >= 1");
  o = SolverOptions();
  o.restarts = 0;
  o.chain_restarts = 0;
  EXPECT_EQ(check_options(o), "");
  o.stall_iterations = 0;
  EXPECT_EQ(check_options(o), "option stall_iterations must be >= 1");
}

TEST(OptionRange, DescribesEachKind) {
  EXPECT_TRUE(any_value().contains(-kInf));
  EXPECT_FALSE(any_value().contains(kNaN));
  EXPECT_EQ(in_range(1, 1000).describe(), "in 1..1000");
  EXPECT_EQ(half_open(0, 0.5).describe(), "in [0, 0.5)");
  EXPECT_EQ(finite_at_least(0, "why").describe(), "a number >= 0 (why)");
  EXPECT_TRUE(in_range(1, 3).contains(3));
  EXPECT_FALSE(half_open(1, 3).contains(3));
  EXPECT_FALSE(open_interval(1, 3).contains(1));
}

}  // namespace
}  // namespace ik

// The solver options: SolverOptions, declared from the list in solver_options.def (name, type,
// default, JavaScript name and valid range of each option, stated once there), the range check
// start() applies, and for_each_option(), through which the bindings read and write them.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "size_limits.h"

namespace ik {

// The values an option accepts: low..high, each end included or not. An infinite end that is
// excluded means "a finite number" (NaN is never inside).
struct OptionRange {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_included = true;
  bool high_included = true;
  const char* note = nullptr;  // appended to the message in parentheses

  bool contains(double x) const {
    return (low_included ? x >= low : x > low) && (high_included ? x <= high : x < high);
  }
  // What a value must be, for messages: "a number >= 0", "> 0", "in 1..1000", "in [0, 1)".
  std::string describe() const;
};

// The ranges solver_options.def uses.
constexpr OptionRange any_value() { return {}; }
// x >= low, infinity included (an integer option's ">= low").
constexpr OptionRange at_least(double low, const char* note = nullptr) {
  return {low, std::numeric_limits<double>::infinity(), true, true, note};
}
// x > low, infinity included.
constexpr OptionRange above(double low) { return {low, std::numeric_limits<double>::infinity(), false, true}; }
// A finite x >= low.
constexpr OptionRange finite_at_least(double low, const char* note = nullptr) {
  return {low, std::numeric_limits<double>::infinity(), true, false, note};
}
// A finite x > low.
constexpr OptionRange finite_above(double low, const char* note = nullptr) {
  return {low, std::numeric_limits<double>::infinity(), false, false, note};
}
// low <= x <= high.
constexpr OptionRange in_range(double low, double high, const char* note = nullptr) {
  return {low, high, true, true, note};
}
// low <= x < high.
constexpr OptionRange half_open(double low, double high) { return {low, high, true, false}; }
// low < x < high.
constexpr OptionRange open_interval(double low, double high) { return {low, high, false, false}; }

struct SolverOptions {
#define IK_SOLVER_OPTION(type, name, default_value, js_name, range) type name = default_value;
#include "solver_options.def"
#undef IK_SOLVER_OPTION
};

// What solver_options.def says about one option besides its type and default.
struct OptionInfo {
  const char* name;     // the C++ field, as C++ messages name it ("error_tolerance")
  const char* js_name;  // camelCase, as JavaScript passes it ("errorTolerance")
  OptionRange range;
};

// Calls visit(info, field) for every option of `options`, in the list's order; `field` is a
// reference to the member (const when `options` is), of the option's type (double, int, bool,
// std::uint32_t).
template <class Options, class Visit>
void for_each_option(Options& options, Visit&& visit) {
#define IK_SOLVER_OPTION(type, name, default_value, js_name, range) \
  visit(OptionInfo{#name, js_name, range}, options.name);
#include "solver_options.def"
#undef IK_SOLVER_OPTION
}

// The first option of `options` outside its range, as "option NAME must be RULE" (the C++ name;
// the bindings swap in the JavaScript one), or an empty string. No allocation when all are valid.
std::string check_options(const SolverOptions& options);

}  // namespace ik

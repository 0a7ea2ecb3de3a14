#include "solver_options.h"

#include <cmath>
#include <sstream>

namespace ik {

namespace {

// A bound as the messages print it: whole numbers without a decimal point.
std::string bound_text(double x) {
  if (x == std::floor(x) && std::abs(x) < 1e15) return std::to_string(static_cast<long long>(x));
  std::ostringstream text;
  text << x;
  return text.str();
}

}  // namespace

std::string OptionRange::describe() const {
  std::string text;
  if (std::isinf(high)) {
    text = std::string(high_included ? "" : "a number ") + (low_included ? ">= " : "> ") + bound_text(low);
  } else if (low_included && high_included) {
    text = "in " + bound_text(low) + ".." + bound_text(high);
  } else {
    text = std::string("in ") + (low_included ? "[" : "(") + bound_text(low) + ", " + bound_text(high) +
           (high_included ? "]" : ")");
  }
  if (note) text += std::string(" (") + note + ")";
  return text;
}

std::string check_options(const SolverOptions& options) {
  std::string problem;
  for_each_option(options, [&](const OptionInfo& info, auto value) {
    if (problem.empty() && !info.range.contains(static_cast<double>(value)))
      problem = std::string("option ") + info.name + " must be " + info.range.describe();
  });
  return problem;
}

}  // namespace ik

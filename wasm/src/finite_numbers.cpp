#include "finite_numbers.h"

#include <cmath>

namespace ik {

std::string non_finite_entry(const double* values, std::size_t n, const char* what) {
  for (std::size_t i = 0; i < n; ++i) {
    const double v = values[i];
    if (std::isfinite(v)) continue;
    const char* shown = std::isnan(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity";
    return std::string(what) + "[" + std::to_string(i) + "] is " + shown + ", not a finite number";
  }
  return {};
}

}  // namespace ik

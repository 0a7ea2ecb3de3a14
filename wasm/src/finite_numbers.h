// The core's check of the numbers a caller hands it (angles, targets): each must be finite. The
// bindings pass them through unchecked (the TypeScript layer checks their type and length only),
// so this is the one place a NaN or an infinity is refused, with a message that names the entry.
#pragma once

#include <cstddef>
#include <string>

namespace ik {

// The first entry of values[0..n) that is not a finite number, as "what[i] is NaN, not a finite
// number" (NaN, Infinity and -Infinity, as JavaScript writes them); an empty string if every
// entry is finite. No allocation then.
std::string non_finite_entry(const double* values, std::size_t n, const char* what);

}  // namespace ik

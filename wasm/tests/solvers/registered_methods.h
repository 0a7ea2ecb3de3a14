// The methods the tests run "for every method": the core's registry (solver_registry.cpp), in
// its order, so that a method added there is tested like the others without a test to edit.
// Read once before main: a method that a test registers for itself (toy_method_test.cpp's "jt")
// is not among them, however the tests are ordered or grouped into processes.
#pragma once

#include <string>
#include <vector>

#include "solvers/solver_registry.h"

namespace ik::test {

inline const std::vector<std::string> kMethods = solver_names();

}  // namespace ik::test

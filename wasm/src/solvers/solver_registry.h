// The IK methods by name: a plain table of factories. Adding a method is one new file that
// defines its factory plus one line in solver_registry.cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "solver.h"

namespace ik {

using SolverFactory = std::unique_ptr<Solver> (*)(Kinematics& kin, const SolverOptions& options);

struct SolverEntry {
  const char* name;         // "gd", "bfgs", "gn", "newton", "lm"
  const char* description;  // one line for menus and --help
  SolverFactory make;
};

// Every registered method, in display order.
const std::vector<SolverEntry>& solver_registry();

// The registered names, in display order.
std::vector<std::string> solver_names();

// A new solver of method `name` on `kin` (which must outlive it). Throws RigError naming the
// known methods if `name` is not one of them.
std::unique_ptr<Solver> make_solver(const std::string& name, Kinematics& kin, const SolverOptions& options = {});

}  // namespace ik

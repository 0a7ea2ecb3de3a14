// The IK methods by name: a table of factories. Adding a method is one new file that defines its
// factory plus one line in solver_registry.cpp (or, from outside the core, one register_solver()
// call: wasm/tests/solvers/toy_method_test.cpp registers a method that way). Every front end
// (the bindings, the page, the widget, the bench) lists the methods from this table.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "solver.h"

namespace ik {

using SolverFactory = std::unique_ptr<Solver> (*)(Kinematics& kin, const SolverOptions& options);

struct SolverEntry {
  const char* name;         // "lm", "gn", ...: the name options, URLs and the bench use
  const char* label;        // a short human name for menus and legends ("Levenberg–Marquardt")
  const char* description;  // one line for tooltips and --help
  SolverFactory make;
};

// Every registered method, in display order (lm, the default, first).
const std::vector<SolverEntry>& solver_registry();

// The registered names, in display order.
std::vector<std::string> solver_names();

// Adds a method at the end of the table. Throws RigError if the name is empty, already taken,
// or the entry has no factory. Not thread-safe: register before solvers are made.
void register_solver(const SolverEntry& entry);

// A new solver of method `name` on `kin` (which must outlive it). Throws RigError naming the
// known methods if `name` is not one of them.
std::unique_ptr<Solver> make_solver(const std::string& name, Kinematics& kin, const SolverOptions& options = {});

}  // namespace ik

#include "solver_registry.h"

namespace ik {

// Each factory is defined in the method's own file.
std::unique_ptr<Solver> make_gd_solver(Kinematics& kin, const SolverOptions& options);
std::unique_ptr<Solver> make_bfgs_solver(Kinematics& kin, const SolverOptions& options);
std::unique_ptr<Solver> make_gn_solver(Kinematics& kin, const SolverOptions& options);
std::unique_ptr<Solver> make_newton_solver(Kinematics& kin, const SolverOptions& options);
std::unique_ptr<Solver> make_lm_solver(Kinematics& kin, const SolverOptions& options);

namespace {

std::vector<SolverEntry>& table() {
  static std::vector<SolverEntry> entries = {
      {"lm", "Levenberg–Marquardt", "Levenberg-Marquardt, error-dependent damping, active set on the bounds (default)",
       make_lm_solver},
      {"gn", "Gauss–Newton",
       "Gauss-Newton, truncated pseudo-inverse step (from J J^T; paper mode: SVD of J), active set on the bounds, "
       "projected backtracking",
       make_gn_solver},
      {"bfgs", "damped BFGS", "damped BFGS with gradient projection and projected Armijo backtracking",
       make_bfgs_solver},
      {"newton", "Newton", "projected Newton, exact Hessian from the tip second derivatives, shifted when indefinite",
       make_newton_solver},
      {"gd", "gradient descent",
       "projected gradient descent, Barzilai-Borwein step lengths, projected Armijo backtracking (paper mode: "
       "from 180/pi, simple decrease)",
       make_gd_solver},
  };
  return entries;
}

}  // namespace

const std::vector<SolverEntry>& solver_registry() { return table(); }

std::vector<std::string> solver_names() {
  std::vector<std::string> names;
  for (const SolverEntry& e : solver_registry()) names.emplace_back(e.name);
  return names;
}

void register_solver(const SolverEntry& entry) {
  if (entry.name == nullptr || entry.name[0] == '\0') throw RigError("a solver method needs a name");
  if (entry.make == nullptr) throw RigError("solver method \"" + std::string(entry.name) + "\" has no factory");
  for (const SolverEntry& e : table())
    if (std::string(entry.name) == e.name)
      throw RigError("solver method \"" + std::string(entry.name) + "\" is already registered");
  SolverEntry copy = entry;
  if (copy.label == nullptr) copy.label = copy.name;
  if (copy.description == nullptr) copy.description = "";
  table().push_back(copy);
}

std::unique_ptr<Solver> make_solver(const std::string& name, Kinematics& kin, const SolverOptions& options) {
  for (const SolverEntry& e : solver_registry())
    if (name == e.name) return e.make(kin, options);
  std::string known;
  for (const SolverEntry& e : solver_registry()) known += (known.empty() ? "" : ", ") + std::string(e.name);
  throw RigError("unknown solver method \"" + name + "\" (known: " + known + ")");
}

}  // namespace ik

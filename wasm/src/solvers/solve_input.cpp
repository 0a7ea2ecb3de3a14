#include "solve_input.h"

#include <cmath>
#include <sstream>

#include "finite_numbers.h"
#include "size_limits.h"

namespace ik {

namespace {

// The first non-finite entry of `v` named `what`, or an empty string.
std::string check_finite(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) {
  return non_finite_entry(v.data(), static_cast<std::size_t>(v.size()), what);
}

static_assert(kMaxCoordinate == 1e9, "check_coordinates' message says 1e9");

// The first entry of `v` named `what` past +-kMaxCoordinate, or an empty string.
std::string check_coordinates(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (std::abs(v[i]) > kMaxCoordinate) {
      std::ostringstream out;
      out << what << "[" << i << "] is " << v[i] << ", past +-1e9 rig units (the largest coordinate the core takes)";
      return out.str();
    }
  return {};
}

}  // namespace

std::string check_solve_input(const Kinematics& kin, const SolverOptions& options, const char* method, int angle_limit,
                              int rows, const Eigen::Ref<const Eigen::VectorXd>& angles,
                              const Eigen::Ref<const Eigen::VectorXd>& target, bool has_target) {
  std::string problem = check_options(options);
  if (!problem.empty()) return problem;
  if (angles.size() != kin.num_angles())
    return "angles has " + std::to_string(angles.size()) + " values, expected " + std::to_string(kin.num_angles()) +
           " (3 per bone)";
  if (has_target && target.size() != kin.num_residuals())
    return "target has " + std::to_string(target.size()) + " values, expected " + std::to_string(kin.num_residuals()) +
           " (3 per end effector)";
  if (kin.num_angles() > angle_limit)
    return std::string(method) + (options.paper_mode ? " in paper mode" : "") + " takes rigs of at most " +
           std::to_string(angle_limit) + " angles (" + std::to_string(angle_limit / 3) + " bones)" +
           (rows > kDenseRows
                ? " with goals of " + std::to_string(rows) + " residual rows (poles and a rest pull add rows)"
                : "") +
           "; this one has " + std::to_string(kin.num_angles()) +
           (options.paper_mode ? ": turn paper mode off" : ": use lm or gd");
  problem = check_finite(angles, "angles");
  if (problem.empty() && has_target) problem = check_finite(target, "target");
  if (problem.empty() && has_target) problem = check_coordinates(target, "target");
  return problem;
}

}  // namespace ik

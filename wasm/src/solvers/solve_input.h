// What start() refuses (invalid_input): the checks of a solve's options and numbers.
#pragma once

#include <Eigen/Core>
#include <string>

#include "kinematics.h"
#include "solver_options.h"

namespace ik {

// The first problem with a solve of method `method` on `kin` with `options`, from `angles`
// (#angles, degrees) towards `target` (#residuals, rig units), as the summary's message; an
// empty string if there is none. In order: an option out of range (check_options), a wrong
// length, a rig with more than `angle_limit` angles (the method's size limit with goals of `rows`
// residual rows), a non-finite
// angle or target, a target coordinate past +-kMaxCoordinate. `has_target` false: there is no
// target vector (goals, checked by GoalSet::set) and `target` is ignored. No allocation when there is no problem.
std::string check_solve_input(const Kinematics& kin, const SolverOptions& options, const char* method, int angle_limit,
                              int rows, const Eigen::Ref<const Eigen::VectorXd>& angles,
                              const Eigen::Ref<const Eigen::VectorXd>& target, bool has_target = true);

}  // namespace ik

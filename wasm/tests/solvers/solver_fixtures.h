// Shared by the solver tests: the report's target sets (PROTOCOL.md) and tolerances.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../a7_fixtures.h"
#include "solvers/solver.h"

namespace ik::test {

// The diagonal of the bounding box of every bone's tip at the rest pose (web/src/rig/tolerances.ts).
inline double rig_size(const Rig& rig) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Bone& b : rig.bones) {
    const Eigen::Vector3d tip = (b.rest * Eigen::Vector4d(b.length, 0, 0, 1)).head<3>();
    lo = lo.cwiseMin(tip);
    hi = hi.cwiseMax(tip);
  }
  return (hi - lo).norm();
}

// The report's stopping tolerances for a rig (web/src/rig/tolerances.ts): A7 beast (0.01, 0.002),
// the other A7 rigs (1e-4, 2e-4), a project rig (1e-4, 2e-4) times its size squared.
inline SolverOptions report_options(const TestRig& r) {
  const double scale = r.a7 ? 1 : std::pow(rig_size(r.rig), 2);
  const bool beast = r.a7 && r.name == "beast";
  SolverOptions o;
  o.gradient_tolerance = beast ? 0.01 : 1e-4 * scale;
  o.error_tolerance = beast ? 0.002 : 2e-4 * scale;
  o.time_budget_s = 0;  // tests never depend on the clock
  return o;
}

// The rig's size: the longest sum of bone lengths from a root to an end effector.
inline double reach(const Kinematics& kin) {
  double reach = 0;
  for (int e = 0; e < kin.num_effectors(); ++e) {
    double length = 0;
    for (int b : kin.effector_chain(e)) length += kin.rig().bones[b].length;
    reach = std::max(reach, length);
  }
  return reach;
}

// One target of a target set: start angles and the goal angles whose tips are the target.
struct TargetCase {
  Eigen::VectorXd start, goal, target;
};

// Incremental targets: A_0 = 0, A_k = clamp(A_{k-1} + 5 U(-1,1)^(3m)); solve k starts at A_{k-1}.
inline std::vector<TargetCase> incremental_targets(Kinematics& kin, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<TargetCase> cases;
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(kin.num_angles());
  for (int k = 0; k < count; ++k) {
    TargetCase c;
    c.start = previous;
    c.goal = previous;
    for (int i = 0; i < c.goal.size(); ++i) c.goal[i] += 5.0 * u(rng);
    kin.project(c.goal);
    c.target.resize(kin.num_residuals());
    kin.tips(c.goal, c.target);
    previous = c.goal;
    cases.push_back(c);
  }
  return cases;
}

// Random targets: A_k = clamp(360 U(-1,1)^(3m)); every solve starts at A = 0.
inline std::vector<TargetCase> random_targets(Kinematics& kin, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<TargetCase> cases;
  for (int k = 0; k < count; ++k) {
    TargetCase c;
    c.start = Eigen::VectorXd::Zero(kin.num_angles());
    c.goal = random_angles(kin, rng);
    c.target.resize(kin.num_residuals());
    kin.tips(c.goal, c.target);
    cases.push_back(c);
  }
  return cases;
}

}  // namespace ik::test

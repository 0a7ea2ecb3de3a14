// Shared by the solver tests: the report's target sets and tolerances (PROTOCOL.md), from
// wasm/native/protocol.h, with the target sets drawn from std::mt19937_64 as the tests were written.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <random>
#include <vector>

#include "../a7_fixtures.h"
#include "solvers/solver.h"

namespace ik::test {

// The report's stopping tolerances for the rig (protocol::report_tolerances), with no time budget.
inline SolverOptions report_options(const TestRig& r) {
  const protocol::Tolerances t = protocol::report_tolerances(r.name, r.a7, protocol::rig_size(r.rig));
  SolverOptions o;
  o.gradient_tolerance = t.gradient;
  o.error_tolerance = t.error;
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

// One solve of a target set: its start angles, the angles A_k of its target, the target x(A_k).
using protocol::TargetCase;

// The incremental target set (protocol.h) drawn from std::mt19937_64(seed): A_0 = 0 (not
// projected, unlike protocol::target_set), A_k = incremental_angles(A_(k-1)); solve k starts at
// A_(k-1). `count` solves; angles in degrees, targets in rig units.
inline std::vector<TargetCase> incremental_targets(Kinematics& kin, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<TargetCase> cases;
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(kin.num_angles());
  for (int k = 0; k < count; ++k) {
    TargetCase c;
    c.start = previous;
    c.goal = protocol::incremental_angles(kin, previous, unit_from(rng));
    c.target.resize(kin.num_residuals());
    kin.tips(c.goal, c.target);
    previous = c.goal;
    cases.push_back(std::move(c));
  }
  return cases;
}

// The random target set (protocol.h) drawn from std::mt19937_64(seed): `count` solves, each from
// A = 0 to the tips of random_angles.
inline std::vector<TargetCase> random_targets(Kinematics& kin, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<TargetCase> cases;
  for (int k = 0; k < count; ++k) {
    TargetCase c;
    c.start = Eigen::VectorXd::Zero(kin.num_angles());
    c.goal = random_angles(kin, rng);
    c.target.resize(kin.num_residuals());
    kin.tips(c.goal, c.target);
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace ik::test

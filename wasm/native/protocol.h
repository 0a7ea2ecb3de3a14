// The report's protocol (PROTOCOL.md) for the native tools and tests: its five rigs, their
// stopping tolerances, and the random and incremental target sets. TypeScript has each fact once
// too: web/src/rig/tolerances.ts (rigs, tolerances, rig size) and bench-node/targets.ts (target
// sets, drawn from the streams of bench-node/prng.ts, mirrored in seeded_stream.h).
// tests/bench/protocol_agreement.test.ts checks that both languages give the same numbers
// (through wasm/tools/protocol_targets.cpp). Angles are degrees.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "kinematics.h"
#include "seeded_stream.h"

namespace ik::protocol {

// Random targets: each angle 360 * U(-1, 1) degrees, then clamped to its limits.
constexpr double kRandomRangeDeg = 360;
// Incremental targets: each angle moves by 5 * U(-1, 1) degrees per step, then is clamped.
constexpr double kIncrementalStepDeg = 5;

// The report's rigs, by file base name: ikea-lamp, robot-arm, knight, chimpanzee-hand, beast.
const std::vector<std::string>& a7_rig_names();

// Stopping tolerances: |grad E| (rig units^2 per degree) and E (rig units^2, also the success test).
struct Tolerances {
  double gradient;
  double error;
};

// The rig's size (rig units): the diagonal of the bounding box of every bone's tip at A = 0.
double rig_size(const Rig& rig);

// Default tolerances of the rig `name` (file base name) of size `size` (rig_size); `a7` says it
// came from an A7 .json file. The report's own for its five rigs (beast 0.01, 0.002; the others
// 1e-4, 2e-4); any other rig gets 1e-4, 2e-4 times (size / 1 rig unit)^2.
Tolerances report_tolerances(const std::string& name, bool a7, double size);

// Angles P(360 * U(-1, 1)^(3m)); `unit` returns numbers in [0, 1), one per angle in order.
template <class Unit>
Eigen::VectorXd random_angles(const Kinematics& kin, Unit&& unit) {
  Eigen::VectorXd a(kin.num_angles());
  for (int i = 0; i < a.size(); ++i) a[i] = kRandomRangeDeg * signed_unit(unit());
  kin.project(a);
  return a;
}

// Angles P(previous + 5 * U(-1, 1)^(3m)); `unit` as for random_angles.
template <class Unit>
Eigen::VectorXd incremental_angles(const Kinematics& kin, const Eigen::VectorXd& previous, Unit&& unit) {
  Eigen::VectorXd a(previous.size());
  for (int i = 0; i < a.size(); ++i) a[i] = previous[i] + kIncrementalStepDeg * signed_unit(unit());
  kin.project(a);
  return a;
}

// One solve of a target set: its start angles, the angles A_k its target was made from, and the
// target x(A_k) (3 per end effector, rig units).
struct TargetCase {
  Eigen::VectorXd start, goal, target;
};

// The first `count` samples of the target set `experiment` ("random" or "incremental") of a run
// seeded with `seed`: the very angles bench-node/targets.ts's generateTargets makes. random: each
// solve from P(0); incremental: A_0 = P(0), solve k from A_(k-1). Throws std::invalid_argument
// for another experiment.
std::vector<TargetCase> target_set(Kinematics& kin, const std::string& experiment, int count, std::uint32_t seed);

}  // namespace ik::protocol

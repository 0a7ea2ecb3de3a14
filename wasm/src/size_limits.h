// The largest problems the core accepts. Each limit keeps one call (a rig build, one solver
// iteration) bounded in memory and time, so that a careless or hostile input gets a clear error
// instead of exhausting the 4 GiB of WebAssembly memory or running for minutes. README "Limits".
#pragma once

namespace ik {

// Bones of one rig (a 10,000-bone chain builds in milliseconds).
constexpr int kMaxBones = 65536;

// End effectors of one rig.
constexpr int kMaxEffectors = 64;

// Numbers in the Jacobian (3 x #effectors rows, 3 x #bones columns), 32 MiB of doubles: bounds
// every solver's workspace and the cost of one iteration (a 10,000-bone rig takes 46 effectors).
constexpr long long kMaxMatrixEntries = 1LL << 22;

// Angles of a rig that newton, bfgs, gn past 16 effectors and paper mode take: they keep
// #angles x #angles matrices, an SVD of the whole Jacobian or a finite-difference Jacobian (2 x
// #angles poses), steps no time check can split; at this size one costs about 10 ms, so a
// budget of 10 ms or more holds within about 2x (128 bones: a Mixamo character has 65).
constexpr int kMaxDenseAngles = 384;

// E values a solver keeps for its error history.
constexpr int kMaxHistory = 1000000;

// Backtracking trials of one line search (outside paper mode).
constexpr int kMaxBacktracks = 1000;

// Largest magnitude of a coordinate, rig units: a bone length, a rest translation, a target, a
// pole, the goals' length scale. The importers' cap (web/src/rig/rig_limits.ts MAX_COORDINATE):
// far past any model in any unit, far below where squared distances (E) overflow.
constexpr double kMaxCoordinate = 1e9;

// Bend hints (poles) of one solve: each adds 3 rows to every iteration, and a pole per limb is
// what a body needs (a character has 4); at this count one iteration on a 150-bone rig stays
// about a millisecond, so a time budget holds.
constexpr int kMaxPoles = 256;

// Largest soft weight: option rest_weight, a bone's stiffness, a pole's weight. A pull that
// strong already swamps the goals (one degree off rest costs like 17 rig lengths); past it the
// soft rows' scale ruins the conditioning of the steps the hard goals need.
constexpr double kMaxSoftWeight = 1e3;

// Option fd_step_deg (paper mode's central difference), degrees. Below the low end a step is
// lost to rounding at angles of 36,000 degrees (ulp 7e-12), and the differences read 0; past
// the high end they no longer tell the slope (at 180 degrees both sides are one pose).
constexpr double kMinFdStepDeg = 1e-9;
constexpr double kMaxFdStepDeg = 1;

// Largest restart index of Rig.restartStart() (a solve uses at most option restarts, an int).
constexpr long long kMaxRestartIndex = 2147483647;

}  // namespace ik

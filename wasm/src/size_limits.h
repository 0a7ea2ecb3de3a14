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

}  // namespace ik

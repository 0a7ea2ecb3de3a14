// The largest problems the core accepts. Each limit keeps one call (a rig build, one solver
// iteration) bounded in memory and time, so that a careless or hostile input gets a clear error
// instead of exhausting the WebAssembly memory (kMaxWasmMemoryBytes) or running for minutes.
// README "Limits".
#pragma once

namespace ik {

// The most memory the WebAssembly module may grow to: 2 GiB. The build is 32-bit WebAssembly
// (wasm32) with -sALLOW_MEMORY_GROWTH=1, and such a memory stops growing at Emscripten's
// MAXIMUM_MEMORY, which wasm/CMakeLists.txt sets to this value (IK_WASM_MAXIMUM_MEMORY; the
// bindings check the two agree). 2 GiB is also Emscripten's default: a wasm32 memory could reach
// 4 GiB, but only with pointers treated as unsigned throughout the JavaScript glue (Emscripten's
// CAN_ADDRESS_2GB), and the limits below keep one call's workspace to tens of MiB anyway. The
// bindings name this cap when an allocation fails (js_arrays.h).
constexpr long long kMaxWasmMemoryBytes = 2LL << 30;

// Bones of one rig (a 10,000-bone chain builds in milliseconds). At this size one iteration of
// lm or gd on a chain (the forward kinematics and Jacobian of every bone) costs a few
// milliseconds, so a time budget of 10 ms holds within 2x; at 65,536 bones it did not.
constexpr int kMaxBones = 16384;

// End effectors of one rig.
constexpr int kMaxEffectors = 64;

// Numbers in the Jacobian (3 x #effectors rows, 3 x #bones columns), 8 MiB of doubles: bounds
// every solver's workspace and the cost of one iteration, the first one's allocation included
// (a 10,000-bone rig takes 11 effectors; a character of 100 bones and 64 effectors needs 58,000).
constexpr long long kMaxMatrixEntries = 1LL << 20;

// Angles of a rig that newton, bfgs and gn past 16 effectors take: they keep #angles x #angles
// matrices or an SVD of the whole Jacobian, steps no time check can split; at this size one costs about 10 ms, so a
// budget of 10 ms or more holds within about 2x (128 bones: a Mixamo character has 65).
constexpr int kMaxDenseAngles = 384;

// Angles of a rig in paper mode: its finite-difference Jacobian poses the whole rig twice per
// angle, a cost that grows with #angles x #bones; at this size it stays a few milliseconds (the
// report's rigs have at most 66 angles, a Mixamo character 201; at 357 a first solve overran a
// 10 ms budget 2.2x).
constexpr int kMaxPaperAngles = 210;

// Residual rows (16 end effectors) up to which newton and gn's dense path take kMaxDenseAngles.
constexpr int kDenseRows = 48;

// The most angles newton and gn's dense path take with `rows` residual rows (poles and a rest
// pull add rows): kMaxDenseAngles up to kDenseRows rows, fewer past them, so that n^3 / 3 +
// 2 n^2 rows + n rows^2 + rows^3 / 3 (newton's factorisation and its projector onto J's row
// space; gn's SVD grows alike) stays at most what it is at kDenseRows rows. A multiple of 3
// (whole bones); 3 when even one bone would cost more (about 500 rows).
constexpr int dense_angle_limit(int rows) {
  const auto cost = [](double n, double m) { return n * n * n / 3 + 2 * n * n * m + n * m * m + m * m * m / 3; };
  int n = kMaxDenseAngles;
  while (n > 3 && cost(n, rows) > cost(kMaxDenseAngles, kDenseRows)) n -= 3;
  return n;
}

// E values a solver keeps for its error history.
constexpr int kMaxHistory = 1000000;

// Backtracking trials of one line search (outside paper mode).
constexpr int kMaxBacktracks = 1000;

// Steps a solve takes before its time budget holds (steps_before_budget): each may run past the
// budget, so a few; a frame needs one.
constexpr int kMaxStepsBeforeBudget = 10;

// Largest magnitude of a coordinate, rig units: a bone length, a rest translation, a target, a
// pole, the goals' length scale. The importers' cap (web/src/rig/rig_limits.ts MAX_COORDINATE):
// far past any model in any unit, far below where squared distances (E) overflow.
constexpr double kMaxCoordinate = 1e9;

// Bend hints (poles) of one solve: each adds 3 rows to every iteration, and a pole per limb is
// what a body needs (a character has 4, a centipede 60); at this count lm's iteration on a
// 128-bone chain with every pole on it stays a few milliseconds, so a time budget holds (at 256
// poles it took 110 ms; newton and gn also take fewer angles with more rows, dense_angle_limit).
constexpr int kMaxPoles = 64;

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

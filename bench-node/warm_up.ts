// Warm-up before timing: V8 compiles WebAssembly and JavaScript lazily and optimises hot code
// later, so a fresh runner's first solves are slower than the rest (the first solve of a fresh
// WebAssembly solver took 2-8 ms against a 35 us median). Each worker therefore solves untimed for
// WARM_UP_MS (--warm-up) with every new runner, on random targets of their own stream (never the benchmark's),
// before timing anything. The native engine is compiled ahead of time and needs none. The warm-up
// lasts that long whatever the solves cost: a fixed 30 solves (about 0.1 ms of work on the lamp)
// left V8's optimising tier unreached, and the lamp's timed median was 2x too slow (9.4 against
// 4.7 us after 300 ms of warm-up, native 2.7 us).
import type { RigSpec } from '#ik/rig_arrays.js';
import type { RotationsFn } from './pose_goals.js';
import { streamFor } from './prng.js';
import type { Runner } from './runner.js';
import { project, type TipsFn } from './target_set.js';
import { randomAngles } from './targets.js';

/** The default warm-up, milliseconds. */
export const WARM_UP_MS = 300;

/**
 * Solves random targets of the warm-up stream with `runner` (on `spec`, forward kinematics `tips`)
 * for `ms` milliseconds, at least once, from the rest pose; the results are dropped. With
 * `rotations` (--goals pose: the effectors' frame rotations) the targets are whole poses.
 */
export function warmUp(runner: Runner, spec: RigSpec, tips: TipsFn, ms: number, rotations?: RotationsFn): void {
  const rand = streamFor(0, 'warm-up');
  const m = spec.lower.length;
  const rest = project(spec, new Float64Array(m));
  const deadline = performance.now() + ms;
  // At least one solve; then as many as fit before the deadline.
  do {
    const goal = randomAngles(spec, rand);
    runner.solve({ start: rest, target: tips(goal), orientations: rotations?.(goal) ?? null, dragged: -1 });
  } while (performance.now() < deadline);
}

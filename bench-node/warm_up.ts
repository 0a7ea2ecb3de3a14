// Warm-up before timing: V8 compiles WebAssembly and JavaScript lazily and optimises hot code
// later, so a fresh runner's first solves are slower than the rest (the first solve of a fresh
// WebAssembly solver took 2-8 ms against a 35 us median). Each worker therefore solves untimed for
// WARM_UP_MS with every new runner, on random targets of their own stream (never the benchmark's),
// before timing anything. The native engine is compiled ahead of time and needs none. The warm-up
// lasts that long whatever the solves cost: a fixed 30 solves (about 0.1 ms of work on the lamp)
// left V8's optimising tier unreached, and the lamp's timed median was 2x too slow (9.4 against
// 4.7 us after 300 ms of warm-up, native 2.7 us).
import type { RigSpec } from '../web/src/ik/rig_spec.js';
import { signedUnit, streamFor } from './prng.js';
import type { Runner } from './runner.js';
import { project, type TipsFn } from './targets.js';

export const WARM_UP_MS = 300;

export function warmUp(runner: Runner, spec: RigSpec, tips: TipsFn): void {
  const rand = streamFor(0, 'warm-up');
  const m = spec.lower.length;
  const rest = project(spec, new Float64Array(m));
  const deadline = performance.now() + WARM_UP_MS;
  // At least one solve; then as many as fit before the deadline.
  do {
    const a = project(spec, Float64Array.from({ length: m }, () => 360 * signedUnit(rand)));
    runner.solve({ start: rest, target: tips(a), dragged: -1 });
  } while (performance.now() < deadline);
}

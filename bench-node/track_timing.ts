// The track experiment's timing of one clip (track.ts): TIMED_RUNS runs of its inputs, each from a
// new avatar, taken one at a time (run()) so that the runs of several clips interleave. A frame's
// time is its median over the runs. Interleaved, a clip's runs lie seconds apart: this machine's
// slow spells (another tenant on the shared cores: a fixed JavaScript loop took 1.3-8x its usual
// time for 0.1-1 s at a time) then slow one run of a frame, not all of them, as they did when a
// clip's runs followed each other (the same build's medians read 31-70 µs from one command to the
// next; a frame's work is the same every run, the avatar being deterministic).
import v8 from 'node:v8';
import { runInNewContext } from 'node:vm';

import { AvatarSolver, type AvatarInput } from '#avatar/avatar_solver.js';
import type { IkCoreModule } from '#ik/module.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import type { HumanoidMap } from '#rig/humanoid/humanoid_roles.js';
import { BenchError } from './errors.js';
import { median } from './statistics.js';
import type { TimedRuns } from './track_measures.js';

/** Timed runs of each clip (median_us and p99_us take each frame's median over them). */
export const TIMED_RUNS = 7;

/** The rig an avatar is made of: a humanoid's spec and its mapping. */
export interface AvatarRig {
  spec: RigSpec;
  humanoid: HumanoidMap;
}

export class ClipTiming {
  private readonly numAngles: number;
  private readonly solved: Float64Array;
  private readonly plantedLog: Float64Array;
  private readonly runTimes: Float64Array[] = [];

  /**
   * The timing of clip `name`'s `inputs`; its first run goes through `avatar` (whose poses and
   * planted feet are kept), the others through new avatars of `rig`.
   */
  constructor(
    private readonly ik: IkCoreModule,
    private readonly rig: AvatarRig,
    private readonly avatar: AvatarSolver,
    private readonly inputs: readonly AvatarInput[],
    private readonly name: string,
  ) {
    this.numAngles = avatar.angles.length;
    this.solved = new Float64Array(inputs.length * this.numAngles);
    this.plantedLog = new Float64Array(inputs.length * 6);
  }

  /**
   * One run: update() and nothing else that allocates between the frames (the poses and planted
   * feet go into arrays made beforehand), after a full garbage collection. A run that gives
   * another pose than the first throws a BenchError naming the clip and frame.
   */
  run(): void {
    const run = this.runTimes.length,
      first = run === 0,
      n = this.numAngles;
    const times = new Float64Array(this.inputs.length);
    const runner = first ? this.avatar : new AvatarSolver(this.ik, this.rig.spec, this.rig.humanoid);
    try {
      collectGarbage();
      for (let f = 0; f < this.inputs.length; f++) {
        const t0 = performance.now();
        runner.update(this.inputs[f]);
        times[f] = (performance.now() - t0) * 1000;
        if (first) {
          this.solved.set(runner.angles, f * n);
          runner.plantedFeet().forEach((p, i) => this.plantedLog.set(p ?? [NaN, NaN, NaN], 6 * f + 3 * i));
        } else if (!runner.angles.every((a, i) => a === this.solved[f * n + i]))
          throw new BenchError(
            `track: ${this.name} frame ${f} gave another pose on run ${run + 1} (the avatar is not deterministic)`,
            1,
          );
      }
    } finally {
      if (!first) runner.dispose();
    }
    this.runTimes.push(times);
  }

  /** The first run's poses and planted feet, and each frame's median time (µs) over the runs so far. */
  result(): TimedRuns {
    const times = Float64Array.from({ length: this.inputs.length }, (_, f) => median(this.runTimes.map((t) => t[f])));
    return { numAngles: this.numAngles, solved: this.solved, plantedLog: this.plantedLog, times };
  }
}

/**
 * A full garbage collection now, so that the clip's inputs and the last clip's measures, made
 * before the timed run, are not collected inside it (V8's collector pauses 0.5-8 ms: one in a
 * clip of 181 frames is its p99). What update() itself allocates is still collected in the run.
 */
let gc: (() => void) | null = null;
function collectGarbage(): void {
  if (!gc) {
    v8.setFlagsFromString('--expose-gc');
    gc = runInNewContext('gc') as () => void;
  }
  gc();
}

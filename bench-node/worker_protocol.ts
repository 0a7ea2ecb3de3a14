// Messages between the main thread (run_wasm.ts) and the worker threads (worker.ts).
import type { RigSpec } from '#ik/rig_arrays.js';
import type { FlipLimb } from './flips.js';
import type { SolveResult } from './metrics.js';
import type { RunSettings } from './runner.js';

/** What a worker gets at start: the WebAssembly module, compiled once by the main thread, and the warm-up time. */
export interface WorkerInit {
  wasmModule: WebAssembly.Module;
  /** Untimed solving with each new runner, milliseconds (warm_up.ts). */
  warmUpMs: number;
}

/** A batch of solves: samples of a target set, whole drag paths only. */
export interface WorkerTask {
  kind: 'task';
  id: number;
  /** Identifies the rig, so a worker builds each rig's solver once. */
  rigKey: string;
  spec: RigSpec;
  settings: RunSettings;
  count: number;
  numAngles: number;
  numResiduals: number;
  starts: Float64Array;
  targets: Float64Array;
  /** --goals pose: 4 per effector per sample (quaternions); else null. */
  orientations: Float64Array | null;
  chained: Uint8Array;
  dragged: Int32Array;
  /**
   * Drag, reach, gestures: the rig's limbs whose flips count (flips.ts; empty: none), and then each
   * step's joint move and flip are measured (step_measures.ts); null: nothing measured.
   */
  limbs: FlipLimb[] | null;
}

export type WorkerReply =
  | { kind: 'ready' }
  | { kind: 'progress'; id: number; solved: number }
  | { kind: 'done'; id: number; results: SolveResult[] }
  | { kind: 'failed'; id: number; message: string };

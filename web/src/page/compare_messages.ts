// What the page and its compare worker (compare_worker.ts) say to each other. A compare is sent as
// plain data (a rig spec, effectors, targets, goals, a start pose, settings), so the worker builds
// its own WebAssembly session; rows come back one per method as each finishes.
import type { RigSpec } from '../ik/rig_arrays.js';
import { EffectorGoals } from '../live/effector_goals.js';
import type { IkSession } from '../live/session.js';
import type { SolveOutcome, SolveSettings } from '../live/method_solver.js';

/** One method's result in the compare table. */
export interface CompareRow {
  method: string;
  outcome: SolveOutcome | null;
  /** E before the first iteration and after each one. */
  history: Float64Array | null;
  error: string | null;
}

/** An effector's goals as plain arrays (EffectorGoals' fields). */
export interface GoalsData {
  position: Uint8Array;
  orientation: Uint8Array;
  rotations: Float64Array;
  poleBones: Int32Array;
  polePoints: Float64Array;
}

/** How a compare ended. */
export type CompareEnd = 'done' | 'cancelled' | 'failed';

/** The page asks for a compare. */
export interface CompareRequest {
  id: number;
  spec: RigSpec;
  /** End effectors' bone indices. */
  effectors: Int32Array;
  /** 3 per effector, rig units. */
  targets: Float64Array;
  goals: GoalsData;
  /** Every method starts here: 3 angles per bone, degrees. */
  start: Float64Array;
  methods: string[];
  settings: SolveSettings;
}

/** The worker reports: a method started, a row finished, the compare ended, or it could not run. */
export type CompareReply =
  | { type: 'started'; id: number; method: string; index: number }
  | { type: 'row'; id: number; row: CompareRow }
  | { type: 'done'; id: number }
  | { type: 'failed'; id: number; message: string };

/** A compare of `session`'s problem from `start` with `methods`, as data for the worker. */
export function compareRequest(
  id: number,
  session: IkSession,
  start: Float64Array,
  methods: readonly string[],
  settings: SolveSettings,
): CompareRequest {
  const g = session.goals;
  return {
    id,
    spec: session.spec,
    effectors: session.effectors().slice(),
    targets: session.targets.slice(),
    goals: {
      position: g.position.slice(),
      orientation: g.orientation.slice(),
      rotations: g.rotations.slice(),
      poleBones: g.poleBones.slice(),
      polePoints: g.polePoints.slice(),
    },
    start: start.slice(),
    methods: [...methods],
    settings: { ...settings },
  };
}

/** Sets `session` up as the request describes: its effectors, targets and goals. */
export function applyRequest(session: IkSession, request: CompareRequest): void {
  session.setEffectors(Array.from(request.effectors));
  session.targets = request.targets.slice();
  const goals = new EffectorGoals(request.effectors.length);
  goals.position.set(request.goals.position);
  goals.orientation.set(request.goals.orientation);
  goals.rotations.set(request.goals.rotations);
  goals.setPoles(request.goals.poleBones, request.goals.polePoints);
  session.goals = goals;
}

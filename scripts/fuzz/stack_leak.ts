// The stack-leak check: many solves refused in a loop must leave the module working. A binding
// that throws out of WebAssembly without restoring its stack pointer leaks stack on every throw
// and traps after ~1e5. The refusal used is one only the core can make (an option out of range:
// the TypeScript layer checks types, the core ranges), so each one goes into the module.
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import { IkSolver } from '#ik/solver.js';
import { straightLimb } from '../rig_files/rig_builder.js';
import { canaryProblem } from './canary.js';
import { classifyThrown } from './classify_error.js';

export interface StackLeakResult {
  /** Refused solves done before the loop stopped. */
  throws: number;
  /** Did the core itself report the refusal (the module's takeError() was read, or the error came through WebAssembly frames)? */
  reachesWasm: boolean;
  /** The refusal's message. */
  message: string;
  /** undefined when every solve was refused clearly and a valid solve works afterwards. */
  problem?: string;
}

/** Runs `solve` once, telling whether the core reported its error. */
function refusedByCore(ik: IkCoreModule, solve: () => void): { reachesWasm: boolean; message: string } {
  const core = ik as { takeError?: () => string };
  const takeError = core.takeError;
  let read = false;
  if (takeError) core.takeError = () => ((read = true), takeError.call(ik));
  try {
    solve();
    return { reachesWasm: false, message: 'accepted' };
  } catch (e) {
    return { reachesWasm: read || /wasm/.test((e as Error).stack ?? ''), message: (e as Error).message };
  } finally {
    if (takeError) core.takeError = takeError;
  }
}

/**
 * `count` times solver.solve() with an out-of-range option (errorTolerance -1) on a fresh
 * two-bone rig in `ik`, then the canary. Stack traces are switched off during the loop (it
 * measures the module, not Error.captureStackTrace).
 */
export function stackLeakCheck(ik: IkCoreModule, count: number): StackLeakResult {
  const rig = new IkRig(ik, straightLimb());
  const solver = new IkSolver(rig, 'lm', { errorTolerance: -1, timeBudgetSeconds: 1 });
  const angles = new Float64Array(6),
    target = Float64Array.of(1, 1, 0);
  const first = refusedByCore(ik, () => solver.solve(angles, target));
  const limit = Error.stackTraceLimit;
  Error.stackTraceLimit = 0;
  let k = 0,
    problem: string | undefined;
  try {
    for (; k < count && !problem; k++) {
      try {
        solver.solve(angles, target);
        problem = `solve ${k} accepted errorTolerance -1`;
      } catch (e) {
        const c = classifyThrown(e);
        if (c.kind !== 'clear') problem = `refused solve ${k} threw ${c.message}`;
      }
    }
  } finally {
    Error.stackTraceLimit = limit;
  }
  problem ??= canaryProblem(ik);
  if (!problem) {
    solver.dispose();
    rig.dispose();
  }
  return { throws: k, ...first, problem };
}

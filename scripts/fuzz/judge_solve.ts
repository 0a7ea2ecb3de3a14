// The outcome of a solve that returned: clean, silently wrong, or a reported numerical failure.
import type { RigSpec } from '#ik/rig_arrays.js';
import type { SolverResult } from '#ik/solver.js';
import { OK, type Outcome } from './outcome.js';
import { solveProblem } from './result_checks.js';

/**
 * `result` judged by solveProblem(); a numerical_failure that explains itself in `message` is a
 * clear error (the solver reported it), one without a message is wrong.
 */
export function judgeSolve(
  result: SolverResult,
  spec: RigSpec,
  given?: { start: Float64Array; target: Float64Array },
): Outcome {
  const problem = solveProblem(result, spec, given);
  if (problem) return { kind: 'wrong', message: problem };
  if (result.stopReason !== 'numerical_failure') return OK;
  return result.message
    ? { kind: 'clear', message: `numerical_failure: ${result.message}` }
    : { kind: 'wrong', message: 'numerical_failure without a message' };
}

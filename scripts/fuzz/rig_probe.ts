// What a loaded rig must do: build in the core (else the loader let a bad rig through, and the
// core's error does not name the file), give the reference tips, and solve cleanly.
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import { IkSolver } from '#ik/solver.js';
import { attempt } from './attempt.js';
import type { BudgetSample } from './case_id.js';
import { classifyThrown } from './classify_error.js';
import { judgeSolve } from './judge_solve.js';
import { OK, worse, type Outcome } from './outcome.js';
import type { Rand } from './random.js';
import { randomAngles } from './random_rig.js';
import { clampToLimits, closeProblem, numbersProblem, referenceTips, rigScale } from './result_checks.js';

/** Time budget of the probe's solve, seconds. */
const PROBE_BUDGET_SECONDS = 0.02;

/** Builds `spec` (loaded from `file`) in `ik`, checks its tips at rest and one solve to a reachable target. */
export function probeLoadedRig(
  ik: IkCoreModule,
  spec: RigSpec,
  file: string,
  r: Rand,
  budgets: BudgetSample[],
): Outcome {
  let rig: IkRig;
  try {
    rig = new IkRig(ik, spec);
  } catch (e) {
    const c = classifyThrown(e, file);
    return { kind: c.kind, message: `the loader accepted it, the core refused the rig: ${c.message}` };
  }
  let solver: IkSolver | undefined;
  try {
    const start = clampToLimits(spec, new Float64Array(3 * spec.parents.length));
    const atRest = attempt(
      'must',
      () => rig.tips(start),
      (tips) =>
        numbersProblem('tips', tips, 3 * spec.effectors.length) ??
        closeProblem('tips', tips, referenceTips(spec, start), rigScale(spec)),
    );
    const target = referenceTips(spec, randomAngles(r, spec));
    let solved: Outcome = OK,
      judged: Outcome = OK;
    const made = attempt(
      'either',
      () => (solver = new IkSolver(rig, 'lm', { timeBudgetSeconds: PROBE_BUDGET_SECONDS, seed: r.int(1000) })),
      () => undefined,
    );
    if (solver) {
      const s = solver,
        wall = performance.now();
      solved = attempt(
        'must',
        () => s.solve(start, target),
        (result) => {
          budgets.push({
            budgetSeconds: PROBE_BUDGET_SECONDS,
            elapsedSeconds: result.elapsedSeconds,
            wallSeconds: (performance.now() - wall) / 1000,
          });
          judged = judgeSolve(result, spec, { start, target });
          return undefined;
        },
      );
    }
    return [atRest, made, solved, judged].reduce(worse);
  } finally {
    solver?.dispose();
    rig.dispose();
  }
}

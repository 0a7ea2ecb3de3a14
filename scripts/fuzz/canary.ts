// The canary: after every case, a small fresh rig must still solve cleanly, or the case left the
// module unusable (a crash even if the case itself looked fine).
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import { IkSolver } from '#ik/solver.js';
import { straightLimb } from '../rig_files/rig_builder.js';
import { solveProblem } from './result_checks.js';

/** undefined when a two-bone rig builds, solves to its target and is freed; else what went wrong. */
export function canaryProblem(ik: IkCoreModule): string | undefined {
  const spec = straightLimb();
  const start = new Float64Array(6),
    target = Float64Array.of(1, 1, 0);
  try {
    const rig = new IkRig(ik, spec);
    const solver = new IkSolver(rig, 'lm', { timeBudgetSeconds: 1, restarts: 0 });
    const result = solver.solve(start, target);
    solver.dispose();
    rig.dispose();
    if (result.stopReason !== 'converged_E') return `the canary solve stopped with ${result.stopReason}`;
    return solveProblem(result, spec, { start, target });
  } catch (e) {
    return `the canary threw ${e instanceof Error ? `${e.name}: ${e.message}` : String(e)}`;
  }
}

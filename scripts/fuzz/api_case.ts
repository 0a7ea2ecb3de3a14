// An API case: a random rig and solver, then one to six calls with careless or hostile arguments.
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import { IkSolver, type SolverOptions } from '#ik/solver.js';
import { MAX_BONES, MAX_EFFECTORS, MAX_JACOBIAN_ENTRIES, maxEffectors } from '#rig/rig_limits.js';
import { API_OPS } from './api_ops.js';
import type { ApiState } from './api_state.js';
import type { BudgetSample } from './case_id.js';
import { classifyThrown } from './classify_error.js';
import { saneOptions } from './hostile_options.js';
import { OK, worse, type Outcome } from './outcome.js';
import type { Rand } from './random.js';
import { randomRig } from './random_rig.js';

/** The most bones a rig with MAX_EFFECTORS end effectors may have (the Jacobian cap). */
const LARGEST_WITH_64_EFFECTORS = Math.floor(MAX_JACOBIAN_ENTRIES / (9 * MAX_EFFECTORS));

/** The methods that hold an n x n matrix of the angles (bfgs's inverse Hessian, newton's Hessian): drawn on rigs of at most 1024 angles only. */
const DENSE_METHODS: ReadonlySet<string> = new Set(['bfgs', 'newton']);

/**
 * Runs one API case drawn from `r` on module `ik`. `note` gets each part of the description as
 * it is drawn (so a hang still says how far the case got); `budgets` gets the budgeted solves.
 */
export function runApiCase(r: Rand, ik: IkCoreModule, note: (text: string) => void, budgets: BudgetSample[]): Outcome {
  // The largest rigs the core takes are drawn too: MAX_BONES bones, and 64 effectors on the most
  // bones the Jacobian cap allows them (the time budget's promise covers them).
  const bones = r.weighted<() => number>([
    [6, () => r.intIn(1, 8)],
    [2, () => r.intIn(20, 200)],
    [1, () => r.intIn(500, 3000)],
    [0.3, () => r.pick([MAX_BONES, LARGEST_WITH_64_EFFECTORS])],
  ])();
  const spec = randomRig(r, bones, bones > 300 ? Math.min(maxEffectors(bones), bones >= 1800 ? 64 : 20) : 4);
  const methods = IkSolver.methods(ik);
  const method = r.pick(3 * bones <= 1024 ? methods : methods.filter((m) => !DENSE_METHODS.has(m)));
  const options = saneOptions(r);
  if (bones > 300) options.timeBudgetSeconds = r.pick([1e-6, 1e-3, 0.01, 0.03]);
  note(`${bones}-bone rig, ${spec.effectors.length} effectors, ${method} ${JSON.stringify(options)}`);
  const rig = new IkRig(ik, spec);
  const s: ApiState = {
    ik,
    spec,
    rig,
    solver: new IkSolver(rig, method, options as SolverOptions),
    started: false,
    optionsOutOfRange: false,
    owned: [],
    budgets,
  };
  s.owned.push(rig, s.solver);
  let outcome: Outcome = OK;
  for (let k = r.intIn(1, 6); k > 0; k--) {
    const step = r.weighted(API_OPS)(r, s);
    note(step.text);
    const o = step.run();
    outcome = worse(outcome, { kind: o.kind, message: `${step.text}: ${o.message}` });
  }
  for (const o of s.owned.reverse()) {
    try {
      o.dispose();
    } catch (e) {
      const c = classifyThrown(e);
      outcome = worse(outcome, { kind: c.kind, message: `dispose at the end: ${c.message}` });
    }
  }
  return outcome;
}

// What an API case works on: one rig, its current solver, and what the fuzzer knows about them.
import type { IkCoreModule } from '#ik/module.js';
import type { IkRig } from '#ik/rig.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import type { IkSolver } from '#ik/solver.js';
import type { BudgetSample } from './case_id.js';

export interface ApiState {
  ik: IkCoreModule;
  /** The rig's spec, its effectors kept equal to the rig's own. */
  spec: RigSpec;
  rig: IkRig;
  solver: IkSolver;
  /** A start() or solve() succeeded on `solver`, so its result and angles describe a solve. */
  started: boolean;
  /** The solver's options for the next solve hold an out-of-range value: start() and solve() must refuse. */
  optionsOutOfRange: boolean;
  /** Objects made along the way, disposed (newest first) at the end of the case. */
  owned: { dispose(): void }[];
  budgets: BudgetSample[];
}

/** Sets the rig's effectors and, when that succeeds, the spec's. Throws what setEffectors throws. */
export function changeEffectors(s: ApiState, bones: ArrayLike<number>): void {
  s.rig.setEffectors(bones);
  s.spec = { ...s.spec, effectors: s.rig.effectors() };
}

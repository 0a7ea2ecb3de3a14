// Naming a case and what the worker reports about it.
import type { Outcome } from './outcome.js';

export const FUZZ_KINDS = ['a7', 'gltf', 'api', 'pose'] as const;
export type FuzzKind = (typeof FUZZ_KINDS)[number];

/** One case: replayed alone by `npm run fuzz -- --seed <seed> --kind <kind> --case <index>`. */
export interface CaseId {
  kind: FuzzKind;
  seed: number;
  index: number;
}

/** A solve with a finite time budget: how long it took against the budget. */
export interface BudgetSample {
  budgetSeconds: number;
  elapsedSeconds: number;
  wallSeconds: number;
}

export interface CaseReport {
  id: CaseId;
  /** One line: the base input and the mutations or calls. */
  description: string;
  outcome: Outcome;
  budgets: BudgetSample[];
  /** Wall time of the case in its worker, seconds (the canary included). */
  seconds: number;
}

/** The command line that replays `id`. */
export function replayCommand(id: CaseId): string {
  return `npm run fuzz -- --seed ${id.seed} --kind ${id.kind} --case ${id.index}`;
}

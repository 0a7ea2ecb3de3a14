// What one fuzz case came to. Severe outcomes fail the run; an unclear error is reported but
// tolerated (it is a worse message, not a broken module or a wrong answer).

export type OutcomeKind = 'ok' | 'clear' | 'unclear' | 'wrong' | 'crash' | 'hang' | 'outside';

export interface Outcome {
  kind: OutcomeKind;
  /** What happened: the error message, or the problem with an ok-looking result. */
  message: string;
}

/** The outcome kinds from mild to severe, with their names in reports. */
export const OUTCOME_LABELS: Record<OutcomeKind, string> = {
  ok: 'ok',
  clear: 'clear error',
  unclear: 'unclear error',
  wrong: 'silent wrong',
  crash: 'crash',
  hang: 'hang',
  outside: 'read outside',
};

const ORDER = Object.keys(OUTCOME_LABELS) as OutcomeKind[];

/** The kinds that fail a run (exit code 1, test failure). */
export const SEVERE: readonly OutcomeKind[] = ['wrong', 'crash', 'hang', 'outside'];

/** The more severe of two outcomes (the first one on a tie). */
export function worse(a: Outcome, b: Outcome): Outcome {
  return ORDER.indexOf(b.kind) > ORDER.indexOf(a.kind) ? b : a;
}

export const OK: Outcome = { kind: 'ok', message: '' };

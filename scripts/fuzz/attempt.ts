// Running one call of a case and judging what it did.
import { classifyThrown } from './classify_error.js';
import type { Acceptance } from './hostile_args.js';
import { OK, type Outcome } from './outcome.js';

/** The combined acceptance of several arguments: one refused argument makes the call refused. */
export function both(...accepts: Acceptance[]): Acceptance {
  if (accepts.includes('mustNot')) return 'mustNot';
  return accepts.includes('either') ? 'either' : 'must';
}

/**
 * Calls `call`. A throw is classified (crash, unclear or clear error); a return is wrong when the
 * input must be refused, else `check` (undefined: clean) decides. `file` as for classifyThrown.
 */
export function attempt<T>(
  accept: Acceptance,
  call: () => T,
  check: (value: T) => string | undefined,
  file?: string,
): Outcome {
  let value: T;
  try {
    value = call();
  } catch (e) {
    return classifyThrown(e, file);
  }
  if (accept === 'mustNot') return { kind: 'wrong', message: 'accepted it (no error)' };
  const problem = check(value);
  return problem ? { kind: 'wrong', message: problem } : OK;
}

// What a solve's outcome means to a user, in words, for the page's stats and the widget's status
// line. The words never claim more than was reached: "on target" only when every end effector
// is within the tip tolerance of its target and, where it has an orientation goal, within the
// solver's orientation tolerance of it (the core's `reached`). The same outcome always gets the
// same object, so the per-frame path builds no strings and can compare words by identity.

export interface StatusWords {
  /** A few words: on target, out of reach (closest point), stuck, time budget, ... */
  text: string;
  /** One sentence for a tooltip, with the solver's stop reason code. */
  title: string;
  /** For styling and tests: on-target, out-of-reach, stuck, budget, solving, failed. */
  kind: 'on-target' | 'out-of-reach' | 'stuck' | 'budget' | 'solving' | 'failed';
}

function wordsFor(reached: boolean, code: string, paperMode: boolean): StatusWords {
  const words = (text: string, kind: StatusWords['kind'], why: string): StatusWords => ({ text, kind, title: `${why} (stop reason: ${code})` });
  if (reached) return words('on target', 'on-target', 'every end effector is within the tolerance of its target (and of its orientation goal, if any)');
  switch (code) {
    case 'running':
      return words('solving', 'solving', 'the solve has not stopped yet');
    case 'max_iterations':
    case 'timeout':
      return words('time budget', 'budget', 'the per-solve iteration or time budget ran out; the next frame goes on');
    case 'converged_grad':
      return paperMode
        ? words('stuck (stationary point)', 'stuck', 'the gradient vanished off target; paper mode does not look for a way out')
        : words('out of reach (closest point)', 'out-of-reach', 'no move of the joints brings the effectors closer from here');
    case 'zero_step':
      return words('stuck', 'stuck', 'no step lowered the error although the gradient is not zero');
    default:
      return words('failed', 'failed', 'the solve failed');
  }
}

/** Words made so far: [reached, off target, off target in paper mode], by stop reason. */
const made = [new Map<string, StatusWords>(), new Map<string, StatusWords>(), new Map<string, StatusWords>()];

/**
 * Words for an outcome. `reached`: every effector within the tip tolerance; `stopReason`: the
 * solver's code; `paperMode`: the report's algorithms, which have no escape from stationary points
 * (a stationary point off target may then be a saddle rather than a closest point).
 */
export function statusWords(reached: boolean, stopReason: string, paperMode = false): StatusWords {
  const code = stopReason || 'running';
  const cache = made[reached ? 0 : paperMode ? 2 : 1];
  let words = cache.get(code);
  if (!words) {
    words = wordsFor(reached, code, paperMode);
    cache.set(code, words);
  }
  return words;
}

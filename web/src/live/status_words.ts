// What a solve's outcome means to a user, in words, for the page's stats and the widget's status
// line. The words never claim more than was reached: "on target" only when every end effector
// is within the tip tolerance of its target and, where it has an orientation goal, within the
// solver's orientation tolerance of it (the core's `reached`). "Out of reach" when the core says
// a position goal could not be met and the returned pose is its closest point with every goal
// that can be met on target (strict priority: outOfReach); "orientation out of reach" when only an
// orientation goal could not be met, every position held. The same outcome always gets the same
// object, so the per-frame path builds no strings and can compare words by identity.

export interface StatusWords {
  /** A few words: on target, out of reach (closest point), stuck, time budget, ... */
  text: string;
  /** One sentence for a tooltip, with the solver's stop reason code. */
  title: string;
  /** For styling and tests: on-target, out-of-reach, orientation-out-of-reach, stuck, budget, solving, failed. */
  kind: 'on-target' | 'out-of-reach' | 'orientation-out-of-reach' | 'stuck' | 'budget' | 'solving' | 'failed';
}

/** What the words are made from: the core's result fields (SolverResult). */
export interface StatusFacts {
  reached: boolean;
  stopReason: string;
  /** A position goal could not be met: the pose is its closest point (SolverResult.outOfReach). */
  outOfReach?: boolean;
  /** Only an orientation goal could not be met, every position on target (SolverResult.orientationOutOfReach). */
  orientationOutOfReach?: boolean;
}

type Reach = 'none' | 'position' | 'orientation';

function wordsFor(reached: boolean, code: string, paperMode: boolean, reach: Reach): StatusWords {
  const words = (text: string, kind: StatusWords['kind'], why: string): StatusWords => ({
    text,
    kind,
    title: `${why} (stop reason: ${code})`,
  });
  if (reached)
    return words(
      'on target',
      'on-target',
      'every end effector is within the tolerance of its target (and of its orientation goal, if any)',
    );
  const closest = code === 'converged_grad' || code === 'zero_step';
  if (reach === 'position' && closest)
    return words(
      'out of reach (closest point)',
      'out-of-reach',
      'a target is out of reach: its effector is as close as it gets, every target that can be reached is on target',
    );
  if (reach === 'orientation' && closest)
    return words(
      'orientation out of reach',
      'orientation-out-of-reach',
      'every position is on target; an orientation goal cannot be met with them and is as close as it gets',
    );
  switch (code) {
    case 'running':
      return words('solving', 'solving', 'the solve has not stopped yet');
    case 'not_started':
      return words(
        'not solved yet: press S',
        'solving',
        'step mode: the targets moved and no iteration has run towards them; each S takes one',
      );
    case 'joint_speed':
      return words(
        'catching up',
        'solving',
        'the nearest pose on target is farther than the joints may move in one frame: the body moves there over a few frames',
      );
    case 'max_iterations':
    case 'timeout':
      return words('time budget', 'budget', 'the per-solve iteration or time budget ran out; the next frame goes on');
    case 'converged_grad':
      return paperMode
        ? words(
            'stuck (stationary point)',
            'stuck',
            'the gradient vanished off target; paper mode does not look for a way out',
          )
        : words(
            'out of reach (closest point)',
            'out-of-reach',
            'no move of the joints brings the effectors closer from here',
          );
    case 'zero_step':
      return words('stuck', 'stuck', 'no step lowered the error although the gradient is not zero');
    default:
      return words('failed', 'failed', 'the solve failed');
  }
}

const REACH: readonly Reach[] = ['none', 'position', 'orientation'];
/** Words made so far: by [reached, off target, off target in paper mode], then by reach, then by stop reason. */
const made = [0, 1, 2].map(() => REACH.map(() => new Map<string, StatusWords>()));

/**
 * Words for an outcome: `facts` are the solver's result fields (reached, its stop reason code and
 * the out-of-reach flags); `paperMode`: the report's algorithms, which have no escape from
 * stationary points (a stationary point off target may then be a saddle rather than a closest point).
 */
export function statusWords(facts: StatusFacts, paperMode = false): StatusWords {
  const code = facts.stopReason || 'running';
  const r = facts.outOfReach ? 1 : facts.orientationOutOfReach ? 2 : 0;
  const cache = made[facts.reached ? 0 : paperMode ? 2 : 1][r];
  let words = cache.get(code);
  if (!words) {
    words = wordsFor(facts.reached, code, paperMode, REACH[r]);
    cache.set(code, words);
  }
  return words;
}

// --goals position|pose: which runs can take pose goals (pose_goals.ts). Position goals are the
// protocol's and every method, experiment and mode takes them; pose goals need target angles
// (random, incremental), the solvers' modern mode (paper mode is position-only) and a method that
// solves orientations (three.js CCD moves tips only).
import { BenchError } from './errors.js';
import type { GoalsKind } from './pose_goals.js';
import type { Experiment } from './target_set.js';

/** Methods that solve tip positions only: refused with --goals pose, and left out of its --methods default. */
export const positionOnlyMethods: readonly string[] = ['three-ccd'];

/** Experiments whose targets are tip frames at target angles A_k, so they can be whole poses (tracik: always). */
const poseExperiments: readonly Experiment[] = ['random', 'incremental', 'tracik'];

const usage = (message: string): BenchError => new BenchError(message, 2);

/**
 * Checks a run with `goals`; returns its methods (with --goals pose and no --methods given,
 * `methodsGiven` false, the default without the position-only methods). Throws a usage error
 * (one line) for a combination pose goals do not support.
 */
export function checkGoals(
  goals: GoalsKind,
  methods: string[],
  methodsGiven: boolean,
  experiments: readonly Experiment[],
  paper: boolean,
  compare = false,
): string[] {
  if (goals === 'position') return methods;
  if (paper) throw usage('--goals pose: paper mode (--paper) solves tip positions only; leave out one of them');
  if (compare)
    throw usage("--goals pose: --compare sets the report's position-only figures beside these; leave out one of them");
  const dragging = experiments.find((e) => !poseExperiments.includes(e));
  if (dragging !== undefined)
    throw usage(
      `--goals pose: the ${dragging} experiment has tip positions only; pose goals run with ${poseExperiments.join(', ')}`,
    );
  if (!methodsGiven) return methods.filter((m) => !positionOnlyMethods.includes(m));
  const refused = methods.find((m) => positionOnlyMethods.includes(m));
  if (refused !== undefined)
    throw usage(`--goals pose: ${refused} solves tip positions only; leave it out of --methods`);
  return methods;
}

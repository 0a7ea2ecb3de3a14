// Default stopping tolerances of a rig, by the same rule as the benchmark (bench-node/rigs.ts):
// the report's values for its five A7 rigs (beast: gradient 0.01, E 0.002; the others: 0.0001,
// 0.0002); for any other rig both scale with the square of the rig's size (the diagonal of the
// bounding box of every bone tip at the rest pose) relative to 1 rig unit.
import type { IkRig } from '../ik/rig.js';

const REPORT: Record<string, { gradientTolerance: number; errorTolerance: number }> = {
  beast: { gradientTolerance: 0.01, errorTolerance: 0.002 },
  'ikea-lamp': { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
  'robot-arm': { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
  knight: { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
  'chimpanzee-hand': { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
};

/** Diagonal of the bounding box of all bone tips (3 numbers per bone). */
export function tipsDiagonal(tips: ArrayLike<number>): number {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < tips.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], tips[i]);
    hi[i % 3] = Math.max(hi[i % 3], tips[i]);
  }
  return tips.length ? Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) : 1;
}

/** Tolerances for `rig` named `name`; `a7` says whether it came from an A7 .json file. */
export function defaultTolerances(rig: IkRig, name: string, a7: boolean): { gradientTolerance: number; errorTolerance: number } {
  const report = a7 ? REPORT[name] : undefined;
  if (report) return { ...report };
  const scale = tipsDiagonal(rig.boneTips(new Float64Array(rig.numAngles))) ** 2;
  return { gradientTolerance: 1e-4 * scale, errorTolerance: 2e-4 * scale };
}

// How far a clip's pose leaves the joint limits (bench-node/clip_limits.ts), on the character: 0
// at rest and for a turn within a bone's range, the overshoot for a turn past it.
import { resolve } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import { limitExcessDeg } from '../../bench-node/clip_limits.js';
import { loadBenchRig, type BenchRig } from '../../bench-node/rigs.js';
import { invertAffine, multiply } from '../../web/src/rig/mat4.js';

let rig: BenchRig;
beforeAll(async () => {
  rig = await loadBenchRig(resolve(import.meta.dirname, '../../web/public/models/character.glb'));
});

/** The motion (16 row-major numbers per bone) that turns bone `bone` and everything below it by `degrees` about its own swing axis. */
function swung(bone: number, degrees: number): Float64Array {
  const spec = rig.spec,
    n = spec.parents.length,
    motion = new Float64Array(16 * n);
  for (let b = 0; b < n; b++) motion.set([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], 16 * b);
  const rest = spec.rest.subarray(16 * bone, 16 * bone + 16),
    inverse = invertAffine(rest)!;
  const a = (degrees * Math.PI) / 180,
    c = Math.cos(a),
    s = Math.sin(a);
  const turn = multiply(multiply(rest, [c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]), inverse); // Rz in the bone's frame
  const below = (b: number): boolean => b === bone || (spec.parents[b] >= 0 && below(spec.parents[b]));
  for (let b = 0; b < n; b++) if (below(b)) motion.set(turn, 16 * b);
  return motion;
}

describe('a clip pose against the joint limits', () => {
  it('is within them at rest and for a swing inside the range, and past them by the overshoot', () => {
    const knee = rig.humanoid!.bones.leftLowerLeg!; // its swing (Z) runs 0..150 degrees
    expect(rig.spec.upper[3 * knee + 1]).toBeCloseTo(150, 6);
    expect(limitExcessDeg(rig.spec, swung(knee, 0), knee)).toBeLessThan(1e-6);
    expect(limitExcessDeg(rig.spec, swung(knee, 90), knee)).toBeLessThan(1e-6);
    expect(limitExcessDeg(rig.spec, swung(knee, 170), knee)).toBeCloseTo(20, 3);
    expect(limitExcessDeg(rig.spec, swung(knee, -10), knee)).toBeCloseTo(10, 3);
  });
});

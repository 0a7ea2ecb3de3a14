// The selected joint's bend and twist from rest (web/src/page/selection.ts bendAndTwist): 0 and 0 at
// rest however the XZX angles split a straight bone's twist, and equal to the swing-twist
// decomposition of Rx(a0) Rz(a1) Rx(a2) about the bone (x) for any angles.
import { Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';

import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { bendAndTwist, describeHinge, isHinge } from '../../web/src/page/selection.js';

const X = new Vector3(1, 0, 0),
  Z = new Vector3(0, 0, 1),
  RAD = Math.PI / 180;

/** Rx(a0) Rz(a1) Rx(a2), degrees. */
function xzx(a0: number, a1: number, a2: number): Quaternion {
  return new Quaternion()
    .setFromAxisAngle(X, a0 * RAD)
    .multiply(new Quaternion().setFromAxisAngle(Z, a1 * RAD))
    .multiply(new Quaternion().setFromAxisAngle(X, a2 * RAD));
}

/** The bend (degrees between x and q x) and the twist (q's turn about x once the swing is taken out, in (-180, 180]). */
function swingTwist(q: Quaternion): { bend: number; twist: number } {
  const bend = X.clone().applyQuaternion(q).angleTo(X) / RAD;
  // Twist: the projection of q onto rotations about x, normalised.
  const t = new Quaternion(q.x, 0, 0, q.w).normalize();
  let twist = (2 * Math.atan2(t.x, t.w)) / RAD;
  twist -= 360 * Math.ceil((twist - 180) / 360);
  return { bend, twist };
}

describe('a joint read as bend and twist from rest', () => {
  it('reads 0 and 0 at rest, whatever a0 and a2 are (a straight spine at rest: a0 75, a2 -75)', () => {
    expect(bendAndTwist(75, 0, -75)).toEqual({ bend: 0, twist: 0 });
    expect(bendAndTwist(-170, 0, 170)).toEqual({ bend: 0, twist: 0 });
  });

  it('matches the swing-twist decomposition of the joint rotation for any angles', () => {
    let seed = 7;
    const rand = (lo: number, hi: number): number => (
      (seed = (seed * 1103515245 + 12345) % 2147483648),
      lo + ((hi - lo) * seed) / 2147483648
    );
    for (let i = 0; i < 200; i++) {
      const a0 = rand(-180, 180),
        a1 = rand(-150, 150),
        a2 = rand(-180, 180);
      const want = swingTwist(xzx(a0, a1, a2)),
        got = bendAndTwist(a0, a1, a2);
      expect(got.bend).toBeCloseTo(want.bend, 6);
      // The same twist up to a whole turn (a twist of +-180 reads either way).
      expect(Math.abs(((got.twist - want.twist + 540) % 360) - 180)).toBeLessThan(1e-6);
    }
  });
});

describe('hinges (a URDF joint: a0 moves, a1 and a2 fixed at 0)', () => {
  const spec = {
    parents: Int32Array.of(-1, 0, 1),
    lower: Float64Array.of(-166, 0, 0, -180, 0, 0, -30, -40, 0),
    upper: Float64Array.of(166, 0, 0, 180, 0, 0, 30, 40, 0),
  } as unknown as RigSpec;

  it('tells a hinge from a bone of two or three angles', () => {
    expect([0, 1, 2].map((i) => isHinge(spec, i))).toEqual([true, true, false]);
  });

  it('reads its one angle and its limits', () => {
    expect(describeHinge(spec, 0, Float64Array.of(12.345, 0, 0, 0, 0, 0, 0, 0, 0))).toBe(
      'angle about its axis (a0): 12.3° in [-166.0°, 166.0°]',
    );
  });
});

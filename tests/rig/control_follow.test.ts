// Control bones named as a foot or hand follow their limb's end in the pose written to the mesh
// (web/src/rig/humanoid/control_follow.ts): which bones follow which, and the poses they get.
import { describe, expect, it } from 'vitest';

import { followLimbEnds, limbEndFollowers } from '../../web/src/rig/humanoid/control_follow.js';
import { fromTRS, invertAffine, multiply } from '../../web/src/rig/mat4.js';

/** names and parents of `bones` (name, parent name), listed parents first. */
function tree(bones: [string, string?][]): { names: string[]; parents: number[] } {
  const names = bones.map(([n]) => n);
  return { names, parents: bones.map(([, p]) => (p === undefined ? -1 : names.indexOf(p))) };
}
const body: [string, string?][] = [
  ['Bone'],
  ['Body', 'Bone'],
  ['Hips', 'Body'],
  ['UpperLegL', 'Body'],
  ['LowerLegL', 'UpperLegL'],
  ['UpperLegR', 'Body'],
  ['LowerLegR', 'UpperLegR'],
];

/** A rigid pose: a turn of `deg` about the unit `axis`, then a move by `t` (row-major 4x4). */
function rigid(axis: [number, number, number], deg: number, t: [number, number, number]): Float64Array {
  const h = (deg * Math.PI) / 360;
  return fromTRS(t, [...axis.map((v) => v * Math.sin(h)), Math.cos(h)], [1, 1, 1]);
}

describe('limbEndFollowers', () => {
  it('pairs a foot off the root with the end of its leg, with the bones below it, and leaves poles and body feet alone', () => {
    const { names, parents } = tree([
      ...body,
      ['FootL', 'Bone'],
      ['ToeCtrlL', 'FootL'],
      ['FootR', 'Bone'],
      ['PoleTargetL', 'Bone'],
    ]);
    const follow = limbEndFollowers(names, parents).map((f) => [names[f.bone], names[f.end], names[f.control]]);
    expect(follow).toEqual([
      ['FootL', 'LowerLegL', 'FootL'],
      ['ToeCtrlL', 'LowerLegL', 'FootL'],
      ['FootR', 'LowerLegR', 'FootR'],
    ]);
    // A foot at the end of its leg is the leg's own: nothing follows.
    const own = tree([...body, ['FootL', 'LowerLegL'], ['FootR', 'LowerLegR']]);
    expect(limbEndFollowers(own.names, own.parents)).toEqual([]);
  });
});

describe('followLimbEnds', () => {
  it('gives a control the pose of its limb end, a bone below it its pose relative to the control, and keeps the rest', () => {
    const { names, parents } = tree([...body, ['FootL', 'Bone'], ['ToeCtrlL', 'FootL']]);
    const n = names.length;
    const poses = new Float64Array(16 * n);
    for (let b = 0; b < n; b++) poses.set(rigid([0, 0, 1], 7 * b, [0.1 * b, -0.05 * b, 0.02]), 16 * b);
    const [lower, foot, toe] = ['LowerLegL', 'FootL', 'ToeCtrlL'].map((s) => names.indexOf(s));
    poses.set(rigid([1, 0, 0], 50, [0, 0.3, 0.1]), 16 * lower);
    const input = poses.slice();
    const followed = followLimbEnds(limbEndFollowers(names, parents));
    const out = followed(poses);
    const at = (m: ArrayLike<number>, b: number) => Array.from(m).slice(16 * b, 16 * b + 16);
    expect(Array.from(poses)).toEqual(Array.from(input)); // its input is left as it was
    for (const [i, v] of at(out, foot).entries()) expect(v).toBeCloseTo(at(poses, lower)[i], 12);
    const toeWant = multiply(multiply(at(poses, lower), invertAffine(at(poses, foot))!), at(poses, toe));
    for (const [i, v] of at(out, toe).entries()) expect(v).toBeCloseTo(toeWant[i], 12);
    for (let b = 0; b < n; b++) if (b !== foot && b !== toe) expect(at(out, b)).toEqual(at(poses, b));
  });

  it('passes the poses through on a rig without such controls', () => {
    const { names, parents } = tree(body);
    const poses = new Float64Array(16 * names.length).fill(0.5);
    expect(followLimbEnds(limbEndFollowers(names, parents))(poses)).toBe(poses);
  });
});

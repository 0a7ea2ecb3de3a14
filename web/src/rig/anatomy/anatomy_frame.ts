// Which way a humanoid stands and faces in its rest pose, from its own skeleton: up from the hips
// to the head; forward from the feet (heel to toes), else the head's forward lean, else the
// sides (forward = left x up), else glTF's +Z. left = up x forward.
import type { RigSpec } from '../../ik/rig_arrays.js';
import { add, cross, norm, reject, restAxis, restOrigin, sub, unit, type Vec3 } from './anatomy_vec.js';
import type { HumanoidMap, HumanoidRole } from '../humanoid/humanoid_roles.js';

export type FacingSource = 'toes' | 'feet' | 'head' | 'sides' | 'glTF +Z';

export interface BodyFrame {
  up: Vec3;
  forward: Vec3;
  /** The character's own left. */
  left: Vec3;
  /** What told the forward direction. */
  facingFrom: FacingSource;
}

/** Smallest share of a direction across `up` that counts as pointing somewhere horizontally. */
const HORIZONTAL_SHARE = 0.25;

/** The sum of vectors' parts across `up`, or null if that is too small a share of their lengths. */
function horizontal(vectors: Vec3[], up: Vec3): Vec3 | null {
  if (vectors.length === 0) return null;
  const across = vectors.reduce<Vec3>((s, v) => add(s, reject(v, up)), [0, 0, 0]);
  const total = vectors.reduce((s, v) => s + norm(v), 0);
  return norm(across) >= HORIZONTAL_SHARE * total ? unit(across) : null;
}

/** The character's up, forward and left directions in rig space (unit, orthogonal). */
export function bodyFrame(spec: RigSpec, map: HumanoidMap): BodyFrame {
  const bone = (role: HumanoidRole): number | undefined => map.bones[role];
  const has = (...roles: HumanoidRole[]): boolean => roles.every((r) => bone(r) !== undefined);
  const at = (role: HumanoidRole): Vec3 => restOrigin(spec, bone(role)!);

  const up = (has('hips', 'head') && unit(sub(at('head'), at('hips')))) || ([0, 1, 0] as Vec3);
  const sides = ['left', 'right'] as const;
  const candidates: [FacingSource, () => Vec3 | null][] = [
    [
      'toes',
      () =>
        horizontal(
          sides.filter((s) => has(`${s}Foot`, `${s}Toes`)).map((s) => sub(at(`${s}Toes`), at(`${s}Foot`))),
          up,
        ),
    ],
    [
      'feet',
      () =>
        horizontal(
          sides.filter((s) => has(`${s}Foot`)).map((s) => restAxis(spec, bone(`${s}Foot`)!, 0)),
          up,
        ),
    ],
    ['head', () => (has('head') ? horizontal([restAxis(spec, bone('head')!, 0)], up) : null)],
    [
      'sides',
      () => {
        const pairs = (['UpperLeg', 'UpperArm'] as const).filter((p) => has(`left${p}`, `right${p}`));
        const left = pairs.reduce<Vec3>((s, p) => add(s, sub(at(`left${p}`), at(`right${p}`))), [0, 0, 0]);
        return pairs.length ? unit(reject(cross(left, up), up)) : null;
      },
    ],
  ];
  const frame = (forward: Vec3, facingFrom: FacingSource): BodyFrame => ({
    up,
    forward,
    left: cross(up, forward),
    facingFrom,
  });
  for (const [facingFrom, find] of candidates) {
    const forward = find();
    if (forward) return frame(forward, facingFrom);
  }
  // +Z across up; a character lying along Z faces -Y instead.
  return frame(unit(reject([0, 0, 1], up)) ?? unit(reject([0, -1, 0], up))!, 'glTF +Z');
}

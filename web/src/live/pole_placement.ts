// Where a limb's pole handle starts, and the limb's three points at a pose. Poses are IkRig.poses():
// 16 row-major numbers per bone, each bone's transform T_i from its rest frame to its current one
// (the bone's frame in the rig is T_i * rest_i, as rig_view.ts draws it). Rig units throughout.
import type { RigSpec } from '../ik/rig_arrays.js';
import { add, norm, reject, restAxis, restOrigin, scale, sub, unit, type Vec3 } from '../rig/anatomy/anatomy_vec.js';
import type { PoleLimb } from './pole_limbs.js';

/**
 * A joint nearer the root-tip line than this share of the limb's shorter segment counts as
 * straight: the pole residual's bend floor (goals.cpp kBendFloorShare, pole_residual.h's delta),
 * below which the residual counts the limb as not yet bent (it asks for at least that bend). The
 * knight's elbows sit 4.6% of the forearm (2.1% of the arm) off that line, sideways: a modelling
 * kink across the way they bend. A pole placed along it turned the elbow outwards as soon as the
 * arm bent; now it goes behind the elbow, the way the elbow bends.
 */
const STRAIGHT_SHARE = 0.05;

/** The limb's root (its upper bone's head: shoulder, hip), joint (elbow, knee) and tip (wrist, ankle), rig units. */
export interface LimbPoints {
  root: Vec3;
  joint: Vec3;
  tip: Vec3;
}

/** Row-major 4x4 transform `i` of `poses` applied to point `p` (w = 1) or, `w` = 0, to direction `p`. */
function transform(poses: ArrayLike<number>, i: number, p: Vec3, w: 0 | 1): Vec3 {
  const o = 16 * i;
  const row = (r: number): number =>
    poses[o + 4 * r] * p[0] + poses[o + 4 * r + 1] * p[1] + poses[o + 4 * r + 2] * p[2] + w * poses[o + 4 * r + 3];
  return [row(0), row(1), row(2)];
}

/** Limb `bone`'s three points (see LimbPoints) at `poses`. */
export function limbPoints(spec: RigSpec, poses: ArrayLike<number>, bone: number): LimbPoints {
  const upper = spec.parents[bone];
  const head = restOrigin(spec, bone);
  return {
    root: transform(poses, upper, restOrigin(spec, upper), 1),
    joint: transform(poses, bone, head, 1),
    tip: transform(poses, bone, add(head, scale(restAxis(spec, bone, 0), spec.lengths[bone])), 1),
  };
}

/**
 * Where limb `limb`'s pole starts at `poses`: one limb length (upper plus lower part) from the
 * joint, where its reach row is zero (pole_residual.h), the way the joint already bends off the
 * root-tip line; for a straight limb (see STRAIGHT_SHARE) the way it bends (its rest bend
 * direction turned with the lower bone), else the rig's facing (+Z), up (+Y) or +X, whichever
 * first lies well across the limb.
 */
export function initialPole(spec: RigSpec, poses: ArrayLike<number>, limb: PoleLimb): Vec3 {
  const { root, joint, tip } = limbPoints(spec, poses, limb.bone);
  const upper = norm(sub(joint, root)),
    lower = norm(sub(tip, joint));
  const length = upper + lower;
  const line = unit(sub(tip, root)) ?? unit(sub(joint, root)) ?? ([1, 0, 0] as Vec3);
  const off = reject(sub(joint, root), line);
  let dir = norm(off) > STRAIGHT_SHARE * (Math.min(upper, lower) || length) ? unit(off) : null;
  for (const d of [transform(poses, limb.bone, limb.restBend, 0), [0, 0, 1], [0, 1, 0], [1, 0, 0]] as Vec3[]) {
    if (dir) break;
    const across = reject(d, line);
    if (norm(across) > 0.3 * norm(d)) dir = unit(across);
  }
  return add(joint, scale(dir!, length)); // one of the three axes always lies well across the line
}

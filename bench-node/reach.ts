// The reach experiment's paths: a dragged target moving in a straight line away from where its
// end effector rests, every other effector pinned at its rest tip.
//
// Per draggable effector (effectors.ts) three paths of REACH_PATH_STEPS equal steps, each starting
// at the rest pose P(0) (angles 0 clamped into the limits; straight limbs on most characters):
// first from the effector's tip at P(0) towards its chain root point, then along two directions
// perpendicular to that one and to each other. Each path is REACH_SHARE of the distance from the
// tip to the chain root point long. The chain root point is the base (joint) of the top bone of
// the effector's unbranched chain (chainRootBone), at rest: the translation of its rest transform.
// An effector whose tip lies on that point has no direction and no paths. Paths are chained: each
// step starts from the previous step's solution. Nothing makes these targets reachable (a step
// sideways from a straight limb leaves its reach): reachability.ts decides that per step.
import type { RigSpec } from '#ik/rig_arrays.js';
import { chainRootBone, draggableEffectors } from './effectors.js';
import type { TargetSet } from './target_set.js';

/** Steps per reach path. */
export const REACH_PATH_STEPS = 40;
/** Path length as a share of the distance from the effector's rest tip to its chain root point. */
export const REACH_SHARE = 0.4;

export type Vec3 = [number, number, number];

export interface ReachPath {
  /** The dragged effector, an index into spec.effectors. */
  effector: number;
  /** Unit vector the target moves along. */
  direction: Vec3;
  /** Rig units, covered in REACH_PATH_STEPS equal steps. */
  length: number;
}

/** Where `bone` is jointed to its parent at rest: the translation of its rest transform (rig units). */
export function restBase(spec: RigSpec, bone: number): Vec3 {
  const o = 16 * bone;
  return [spec.rest[o + 3], spec.rest[o + 7], spec.rest[o + 11]];
}

/**
 * Three orthonormal vectors: `d` normalised (d must not be 0), then the world axis least aligned
 * with it (the first on ties) made perpendicular to it, then their cross product.
 */
export function orthonormalFrame(d: Vec3): [Vec3, Vec3, Vec3] {
  const norm = Math.hypot(...d);
  const u = d.map((x) => x / norm) as Vec3;
  const k = [1, 2].reduce((best, i) => (Math.abs(u[i]) < Math.abs(u[best]) ? i : best), 0);
  const v = u.map((x, i) => (i === k ? 1 : 0) - u[k] * x) as Vec3;
  const vNorm = Math.hypot(...v);
  v.forEach((x, i) => (v[i] = x / vNorm));
  const w: Vec3 = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  return [u, v, w];
}

/**
 * The reach paths of a rig in sample order: per draggable effector whose tip is off its chain root
 * point, towards the root, then the two perpendiculars. `restTips`: effector tips at P(0).
 */
export function reachPaths(spec: RigSpec, restTips: ArrayLike<number>): ReachPath[] {
  const paths: ReachPath[] = [];
  for (const effector of draggableEffectors(spec)) {
    const root = restBase(spec, chainRootBone(spec, spec.effectors[effector]));
    const toRoot = root.map((x, i) => x - restTips[3 * effector + i]) as Vec3;
    const distance = Math.hypot(...toRoot);
    if (!(distance > 0)) continue;
    for (const direction of orthonormalFrame(toRoot))
      paths.push({ effector, direction, length: REACH_SHARE * distance });
  }
  return paths;
}

/**
 * Fills the samples of `set` (set.count <= paths.length * REACH_PATH_STEPS) with the paths' steps:
 * targets, starts (`rest` = P(0), used by each path's first step), chained flags, dragged effector
 * and path index. `restTips`: effector tips at `rest`.
 */
export function fillReach(
  set: TargetSet,
  paths: readonly ReachPath[],
  rest: Float64Array,
  restTips: Float64Array,
): void {
  const m = set.numAngles,
    r = set.numResiduals;
  for (let k = 0; k < set.count; k++) {
    const path = Math.floor(k / REACH_PATH_STEPS),
      t = (k % REACH_PATH_STEPS) + 1;
    const { effector, direction, length } = paths[path];
    const target = set.targets.subarray(k * r, (k + 1) * r);
    target.set(restTips);
    for (let i = 0; i < 3; i++) target[3 * effector + i] += (t / REACH_PATH_STEPS) * length * direction[i];
    set.starts.set(rest, k * m);
    set.chained[k] = t > 1 ? 1 : 0;
    set.dragged[k] = effector;
    set.group[k] = path;
  }
}

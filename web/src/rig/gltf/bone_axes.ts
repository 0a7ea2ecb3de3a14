// Each bone's axis in a glTF rig: its direction and length from its joint at rest, toward
// extras.ik.tail, its chain child (chain_child.ts) or the joint's local +Y (docs/gltf-ik-extras.md).
// A step of importGltfRig (gltf_rig.ts).
import { chooseChainChild } from '../chain_child.js';
import { shown } from './gltf_json.js';
import { nodeLabel, type GltfNode } from './gltf_nodes.js';
import type { IkExtras } from './ik_extras.js';
import { invertAffine, transformDirection, transformPoint, type Mat4 } from '../mat4.js';
import { failIn } from '../rig_format_error.js';
import { norm, sub, type Vec3 } from '../anatomy/anatomy_vec.js';

/** The joints at rest, from which the bones' directions and lengths are measured. */
export interface RestJoints {
  /** The joint nodes, one per bone, parents first. */
  order: GltfNode[];
  /** Each bone's parent bone, -1 for a root. */
  parents: Int32Array;
  /** Rest world matrix of every node (by node index, row-major, glTF scene space). */
  world: Mat4[];
  /** Each bone's child bones. */
  children: number[][];
  /** How many bones lie below each bone. */
  descendants: Int32Array;
  /** Joints closer than this (scene units) stand at the same point. */
  eps: number;
}

/**
 * The bones `order` (parents first, `parents` their parent bones) at rest (`world`: each node's
 * rest world matrix by node index), with their children, how many bones lie below each, and the
 * distance under which two joints coincide.
 */
export function restJoints(order: GltfNode[], parents: Int32Array, world: Mat4[]): RestJoints {
  const count = order.length;
  const children: number[][] = order.map(() => []);
  parents.forEach((p, b) => p >= 0 && children[p].push(b));
  const descendants = new Int32Array(count);
  for (let b = count - 1; b >= 0; b--) if (parents[b] >= 0) descendants[parents[b]] += descendants[b] + 1;
  return { order, parents, world, children, descendants, eps: coincidence({ order, world }) };
}

/**
 * The distance (scene units) under which two of the joints stand at the same point: 1e-9 of
 * their bounding box's diagonal, or 1e-9 when they all stand at one point.
 */
function coincidence(joints: Pick<RestJoints, 'order' | 'world'>): number {
  let lo: Vec3 = [Infinity, Infinity, Infinity],
    hi: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let b = 0; b < joints.order.length; b++) {
    const p = jointOrigin(joints, b);
    lo = lo.map((v, k) => Math.min(v, p[k])) as Vec3;
    hi = hi.map((v, k) => Math.max(v, p[k])) as Vec3;
  }
  return 1e-9 * (norm(sub(hi, lo)) || 1);
}

/** Bone `b`'s joint position at rest (scene units). */
export function jointOrigin(joints: Pick<RestJoints, 'order' | 'world'>, b: number): Vec3 {
  const m = joints.world[joints.order[b].index];
  return [m[3], m[7], m[11]];
}

/** True when the joints of bones `a` and `b` lie more than `joints.eps` apart at rest. */
function apart(joints: RestJoints, a: number, b: number): boolean {
  return norm(sub(jointOrigin(joints, a), jointOrigin(joints, b))) > joints.eps;
}

/**
 * Bone `b`'s direction (a world unit vector) and length (scene units) from its joint at `p`:
 * toward extras.ik.tail, else toward its chain child (extras.ik.length, in the joint's local
 * units, may set the length), else along the joint's local +Y with extras.ik.length or half its
 * parent's length (`lengths`: the bones placed so far). Throws for an extras.ik.child that is no
 * child joint of `b`.
 */
export function boneAxis(
  joints: RestJoints,
  b: number,
  p: Vec3,
  ex: IkExtras | undefined,
  lengths: Float64Array,
  file: string,
): { unit: Vec3; length: number } {
  const W = joints.world[joints.order[b].index];
  let dir: Vec3 = transformDirection(W, [0, 1, 0]); // local +Y: the bone axis of Blender and Mixamo
  let length: number;
  if (ex?.tail) {
    const d = sub(transformPoint(W, ex.tail), p);
    length = norm(d);
    if (length > joints.eps) dir = d;
    else length = 0;
  } else {
    const child = pickChild(joints, b, ex, file);
    if (child !== undefined) {
      dir = sub(jointOrigin(joints, child), p);
      length = norm(dir);
      if (ex?.length !== undefined) length = worldLength(W, ex.length, transformDirection(invertAffine(W)!, dir));
    } else if (ex?.length !== undefined) length = worldLength(W, ex.length, [0, 1, 0]);
    else length = joints.parents[b] >= 0 ? 0.5 * lengths[joints.parents[b]] : 0;
  }
  const dn = norm(dir);
  return { unit: [dir[0] / dn, dir[1] / dn, dir[2] / dn], length };
}

/** How long `localLength` units along the local direction `u` of `W` are in the world (scene units). */
function worldLength(W: Mat4, localLength: number, u: Vec3): number {
  return (localLength * norm(transformDirection(W, u))) / norm(u);
}

/**
 * The child bone bone `b` points at: the one extras.ik.child names (undefined when it stands on
 * `b`'s joint; throws when `b` has no such child joint), else the chain child (chain_child.ts)
 * among the children away from `b`'s joint, undefined when there is none.
 */
function pickChild(joints: RestJoints, b: number, ex: IkExtras | undefined, file: string): number | undefined {
  const { order, children, descendants } = joints;
  const kids = children[b];
  if (ex?.child !== undefined) {
    const want = ex.child;
    const found = kids.find((c) => (typeof want === 'number' ? order[c].index === want : order[c].name === want));
    if (found === undefined)
      failIn(file, `${nodeLabel(order[b])}: extras.ik.child ${shown(want)} is not one of its child joints`);
    return apart(joints, found, b) ? found : undefined;
  }
  const candidates = kids
    .filter((c) => apart(joints, c, b))
    .map((c) => ({ bone: c, name: order[c].name, descendants: descendants[c] }));
  return candidates.length ? chooseChainChild(candidates).bone : undefined;
}

// The rig's rest pose from the skins' bind pose (docs/gltf-ik-extras.md, "Rest pose"), and the
// file's own pose as start angles from that rest.
//
// A skin's inverse bind matrices hold the pose the mesh was bound in: joint j's bind world matrix is
// B * ibm(j)^-1 for one matrix B (the mesh's bind space) per skin. B cancels between two joints
// of one skin: joint j sits at ibm(a) * ibm(j)^-1 in the frame of its nearest joint above, a. So
// the rest is built from the top down: a skin's top joint (no joint of that skin above it) stays
// where its node is (B is taken from it), and every joint below takes its ROTATION from the bind
// pose relative to the joint above. Its offset and scale stay the node's own: posing (the page's
// "save posed model" among others) turns joints and never moves or scales them, and the two are
// checked to agree within 1e-4 of the skeleton's size. So the nodes' pose differs from the rest
// by joint rotations only, which XZX start angles carry exactly.
//
// Nodes that are not joints of any skin (an Armature above the skeleton, a helper between two
// joints) have no bind matrix: they follow their parent's rest (bind) transform with their own
// local TRS, as they follow their parent in any pose. A joint no skin relates to the joint above
// it (a root, or a joint of another skin than its parent's) does the same.
//
// A skin whose bind matrices do not describe the nodes' skeleton up to joint rotations (identity
// matrices, which put every joint at one point; bones of other lengths; a mirror) cannot give the
// rest: its joints keep the nodes' pose, as do the joints of a skin without inverse bind matrices.
// Where the bind rotation agrees with the node's (within 1e-5), the node's own matrix is kept bit
// for bit, so a file saved in its bind pose imports exactly as its nodes say.
import { xzxWithinLimits } from '../xzx_angles.js';
import type { RigSpec } from '../../ik/rig_arrays.js';
import { failIn } from '../rig_format_error.js';
import { nodeLabel, type GltfSkin, type GltfTree } from './gltf_nodes.js';
import {
  det3,
  invertAffine,
  maxAbs,
  maxAbsDiff,
  multiply,
  polarRotation,
  transformDirection,
  type Mat4,
} from '../mat4.js';
import { fromRotation } from '../quat.js';

/** Offsets and scales of the bind pose and the nodes agree within this share of the skeleton's size. */
const SHAPE_TOLERANCE = 1e-4;
/** A bind rotation within this (rotation matrix entries) of the node's keeps the node's own matrix. */
const SAME_ROTATION = 1e-5;
/** Start angles moved by more than this (rotation matrix entries) to fit the limits are reported. */
const CLAMP_REPORTED = 1e-6;

/** The rest pose of every glTF node. */
export interface RestPose {
  /** Rest local matrix of every node (row-major, relative to its glTF parent): the node's own, or with its rotation from the bind pose. */
  local: Mat4[];
  /** Rest world matrix of every node (glTF scene space). */
  world: Mat4[];
  /** Joints (node indices, tree order) whose rest rotation is the bind pose's and differs from the node's. */
  rebound: number[];
  /** Skins (indices) without inverse bind matrices: their joints keep the nodes' pose. */
  unbound: number[];
  /** Skins (indices) whose bind matrices are no rotation of the nodes' skeleton: their joints keep the nodes' pose. */
  unusable: number[];
}

/**
 * Checks a skin's inverse bind matrices (row-major, 16 per joint, finite: readMat4Accessor) and
 * returns their inverses, the joints' bind matrices in the mesh's bind space. Throws RigFormatError
 * naming `where` ("skins[0].inverseBindMatrices") and the joint for a matrix that is not affine or not invertible.
 */
export function bindMatrices(ibm: Float64Array, skin: GltfSkin, tree: GltfTree, where: string, file: string): Mat4[] {
  return skin.joints.map((j, k) => {
    const m = ibm.subarray(16 * k, 16 * k + 16);
    const joint = `${where}: matrix ${k}, of joint ${nodeLabel(tree.nodes[j])},`;
    if (Math.abs(m[12]) + Math.abs(m[13]) + Math.abs(m[14]) + Math.abs(m[15] - 1) > 1e-6)
      failIn(file, `${joint} is not affine (its last row is not 0 0 0 1)`);
    const inv = invertAffine(m);
    if (inv === null) failIn(file, `${joint} is not invertible (a zero scale?)`);
    return inv;
  });
}

const linearOf = (m: ArrayLike<number>): Float64Array =>
  Float64Array.of(m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]);
function mul3(a: ArrayLike<number>, b: ArrayLike<number>): Float64Array {
  const out = new Float64Array(9);
  for (let r = 0; r < 3; r++)
    for (let c = 0; c < 3; c++) out[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
  return out;
}
const transpose3 = (a: ArrayLike<number>): Float64Array =>
  Float64Array.of(a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]);

/**
 * The rest pose of every node of `tree` from the skins' bind pose (see the top of this file).
 * `binds[s]` is skin s's bindMatrices, or undefined when it has none; `current` the nodes' world
 * matrices (worldMatrices), joints non-singular; `isJoint` the joints of every skin.
 */
export function restFromBindPose(
  tree: GltfTree,
  skins: GltfSkin[],
  binds: (Mat4[] | undefined)[],
  current: Mat4[],
  isJoint: Set<number>,
): RestPose {
  const skeleton: BindSkeleton = {
    tree,
    skins,
    binds,
    isJoint,
    above: jointsAbove(tree, isJoint),
    size: skeletonSize(isJoint, current),
    slots: skins.map((s) => new Map(s.joints.map((j, k) => [j, k]))),
  };
  const { rest, usable } = restOfUsableSkins(skeleton);
  rest.unusable = skins.flatMap((_, t) => (binds[t] !== undefined && !usable[t] ? [t] : []));
  return rest;
}

/** The skins and nodes restFromBindPose reads, with what it works out from them once. */
interface BindSkeleton {
  tree: GltfTree;
  skins: GltfSkin[];
  /** Per skin, its bind matrices (bindMatrices), or undefined when it has none. */
  binds: (Mat4[] | undefined)[];
  /** The joints of every skin (node indices). */
  isJoint: Set<number>;
  /** The nearest joint strictly above each node, -1 for none. */
  above: Int32Array;
  /** The skeleton's size: the diagonal of its joints' bounding box (scene units). */
  size: number;
  /** Per skin, each of its joints' slot (index in its joints) by node. */
  slots: Map<number, number>[];
}

/** The nearest joint (of `isJoint`) strictly above each node of `tree`, -1 for none. */
function jointsAbove(tree: GltfTree, isJoint: Set<number>): Int32Array {
  const { nodes, order } = tree;
  const above = new Int32Array(nodes.length).fill(-1);
  for (const i of order) {
    const p = nodes[i].parent;
    if (p >= 0) above[i] = isJoint.has(p) ? p : above[p];
  }
  return above;
}

/** The diagonal of the bounding box of the joints `isJoint` as they stand (`current` world matrices), scene units; 1 when that is 0. */
function skeletonSize(isJoint: Set<number>, current: Mat4[]): number {
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (const j of isJoint)
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], current[j][4 * k + 3]);
      hi[k] = Math.max(hi[k], current[j][4 * k + 3]);
    }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
}

/**
 * The rest pose built from the skins that pass the shape check, and which skins (true) those are.
 * A skin that fails the shape check anywhere is set aside whole, and the rest built again
 * without it (the rest above a joint changes with the skins set aside, so this repeats, a few
 * times at most; a joint where a skin still fails after that keeps its node's pose).
 */
function restOfUsableSkins(skeleton: BindSkeleton): { rest: RestPose; usable: boolean[] } {
  const usable = skeleton.skins.map((_, s) => skeleton.binds[s] !== undefined);
  let { rest, failed } = buildRest(skeleton, usable);
  for (let pass = 0; failed.size > 0 && pass < 3; pass++) {
    failed.forEach((s) => (usable[s] = false));
    ({ rest, failed } = buildRest(skeleton, usable));
  }
  if (failed.size > 0) {
    failed.forEach((s) => (usable[s] = false));
    ({ rest, failed } = buildRest(skeleton, usable));
    failed.forEach((s) => (usable[s] = false)); // where it still fails, a joint keeps its node's pose
  }
  return { rest, usable };
}

/**
 * The rest pose with the rotations of the skins marked `usable` (its `unusable` left empty), top
 * down, and the skins that failed the shape check at some joint.
 */
function buildRest(skeleton: BindSkeleton, usable: boolean[]): { rest: RestPose; failed: Set<number> } {
  const { nodes, order } = skeleton.tree;
  const local = new Array<Mat4>(nodes.length),
    world = new Array<Mat4>(nodes.length);
  const rebound: number[] = [];
  const failed = new Set<number>();
  for (const i of order) {
    const p = nodes[i].parent;
    let L = nodes[i].local;
    const chosen = chooseBind(skeleton, usable, i, world, failed);
    if (chosen && maxAbsDiff(chosen.Qb, chosen.Qn) > SAME_ROTATION) {
      L = reboundLocal(chosen, L);
      rebound.push(i);
    }
    local[i] = L;
    world[i] = p === -1 ? L : multiply(world[p], L);
  }
  const unbound = skeleton.skins.flatMap((_, t) => (skeleton.binds[t] === undefined ? [t] : []));
  return { rest: { local, world, rebound, unbound, unusable: [] }, failed };
}

/**
 * A joint's local matrix split by a skin's bind pose: the bind rotation Qb, the node's own
 * rotation Qn and the node's stretch Pn (its local linear part = Qn Pn), 9 numbers each, row-major.
 */
interface BindFit {
  Qb: Float64Array;
  Qn: Float64Array;
  Pn: Float64Array;
}

/**
 * The bind pose of node `i` (its parents' rest `world` matrices already built) from the first
 * skin marked `usable` that relates joint i to the joint above and passes the shape check, or
 * undefined when none does. Every such skin is checked (so one pass finds all the skins that fail
 * here); those that fail are added to `failed`.
 */
function chooseBind(
  skeleton: BindSkeleton,
  usable: boolean[],
  i: number,
  world: Mat4[],
  failed: Set<number>,
): BindFit | undefined {
  const { isJoint, skins, slots } = skeleton;
  const a = skeleton.above[i];
  let chosen: BindFit | undefined;
  for (let s = 0; isJoint.has(i) && a >= 0 && s < skins.length; s++) {
    if (!usable[s] || !slots[s].has(i) || !slots[s].has(a)) continue;
    const fit = bindFit(skeleton, s, i, a, world);
    if (!fit) failed.add(s);
    else chosen ??= fit;
  }
  return chosen;
}

/**
 * Joint `i`'s bind pose by skin `s`, placed by its rest joint above `a` (`world`: the rest world
 * matrices built so far), when its offset and scale agree with the node's within SHAPE_TOLERANCE
 * and neither mirrors the other; undefined when they do not.
 */
function bindFit(skeleton: BindSkeleton, s: number, i: number, a: number, world: Mat4[]): BindFit | undefined {
  const { nodes } = skeleton.tree;
  const p = nodes[i].parent,
    L = nodes[i].local;
  // Joint i's bind world matrix, placed by its rest joint above: world(a) * ibm(a) * ibm(i)^-1.
  const bind = skeleton.binds[s]!,
    slot = skeleton.slots[s];
  const bindWorld = multiply(multiply(world[a], invertAffine(bind[slot.get(a)!])!), bind[slot.get(i)!]);
  const Lb = multiply(invertAffine(world[p])!, bindWorld);
  const Qb = polarRotation(Lb),
    Qn = polarRotation(L);
  const Pb = mul3(transpose3(Qb), linearOf(Lb)),
    Pn = mul3(transpose3(Qn), linearOf(L));
  const moved = transformDirection(world[p], [Lb[3] - L[3], Lb[7] - L[7], Lb[11] - L[11]]);
  const sameShape =
    Math.hypot(...moved) <= SHAPE_TOLERANCE * skeleton.size &&
    maxAbsDiff(Pb, Pn) <= SHAPE_TOLERANCE * maxAbs(Pn) &&
    det3(Lb) * det3(L) > 0;
  return sameShape ? { Qb, Qn, Pn } : undefined;
}

/** The local matrix `L` with the bind rotation `fit.Qb` in place of its own, its offset and scale (stretch Pn) kept. */
function reboundLocal(fit: BindFit, L: Mat4): Mat4 {
  const R = mul3(fit.Qb, fit.Pn);
  return Float64Array.of(R[0], R[1], R[2], L[3], R[3], R[4], R[5], L[7], R[6], R[7], R[8], L[11], 0, 0, 0, 1);
}

/** A middle XZX angle this close to 0 or 180 degrees (its sine, radians) is taken as exactly that. */
const STRAIGHT = 1e-6;

/**
 * `r` (9 numbers, row-major) as an exact Rx(t) or Rx(t) Rz(180) when its middle XZX angle lies
 * within STRAIGHT of 0 or 180 degrees. There only a0 + a2 (or a0 - a2) is defined, and the
 * rounding of the bind matrices (float32) leaves a bend of about 1e-7 that would make
 * xzxWithinLimits read a0 and a2 apart from that noise, and clamp them each, instead of splitting
 * their sum within the limits (a forearm twisted straight, with a0 fixed at 0).
 */
function straightened(r: Float64Array): Float64Array {
  if (Math.hypot(r[3], r[6]) >= STRAIGHT) return r;
  if (r[0] > 0) {
    const t = Math.atan2(r[7], r[4]);
    return Float64Array.of(1, 0, 0, 0, Math.cos(t), -Math.sin(t), 0, Math.sin(t), Math.cos(t));
  }
  const t = Math.atan2(-r[7], -r[4]);
  return Float64Array.of(-1, 0, 0, 0, -Math.cos(t), -Math.sin(t), 0, -Math.sin(t), Math.cos(t));
}

/** Rx(a0) Rz(a1) Rx(a2), angles in degrees, as 9 row-major numbers. */
function xzxRotation(a: ArrayLike<number>, at: number): Float64Array {
  const [a0, a1, a2] = [a[at], a[at + 1], a[at + 2]].map((v) => (v * Math.PI) / 180);
  const rx = (t: number): Float64Array =>
    Float64Array.of(1, 0, 0, 0, Math.cos(t), -Math.sin(t), 0, Math.sin(t), Math.cos(t));
  const rz = Float64Array.of(Math.cos(a1), -Math.sin(a1), 0, Math.sin(a1), Math.cos(a1), 0, 0, 0, 1);
  return mul3(mul3(rx(a0), rz), rx(a2));
}

/**
 * The XZX angles (3 per bone, degrees) that pose `spec` (rest frames from `restWorld`) as the
 * nodes stand (`current`): bone i's motion from its rest is T_i = current_i * restWorld_i^-1 (the
 * write-back's posed world = T_i * restWorld_i), and its angles are those of the rotation
 * rest_i^-1 T_p^-1 T_i rest_i (README "Conventions"), read by xzxWithinLimits (the decomposition
 * nearest the spec's limits, then clamped into them). `clamped` lists the bones the limits moved.
 */
export function startAngles(
  spec: RigSpec,
  boneNodes: ArrayLike<number>,
  restWorld: Mat4[],
  current: Mat4[],
): { angles: Float64Array; clamped: number[] } {
  const n = spec.parents.length;
  const angles = new Float64Array(3 * n);
  const clamped: number[] = [];
  const motion = Array.from({ length: n }, (_, b) =>
    multiply(current[boneNodes[b]], invertAffine(restWorld[boneNodes[b]])!),
  );
  for (let b = 0; b < n; b++) {
    const rest = spec.rest.subarray(16 * b, 16 * b + 16);
    const p = spec.parents[b];
    const T = p < 0 ? motion[b] : multiply(invertAffine(motion[p])!, motion[b]);
    const R = straightened(polarRotation(multiply(multiply(invertAffine(rest)!, T), rest)));
    const [x, y, z, w] = fromRotation(R);
    const q = { x, y, z, w };
    xzxWithinLimits(q, spec.lower.subarray(3 * b, 3 * b + 3), spec.upper.subarray(3 * b, 3 * b + 3), angles, 3 * b);
    if (maxAbsDiff(xzxRotation(angles, 3 * b), R) > CLAMP_REPORTED) clamped.push(b);
  }
  return { angles, clamped };
}

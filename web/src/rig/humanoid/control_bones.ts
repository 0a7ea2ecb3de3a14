// Control bones (docs/gltf-ik-extras.md, "Defaults"): IK targets, poles and the like that a rig
// (a Blender one above all) hangs off its root or its armature, above the body. They move with
// the root alone, so an end effector on one swings the whole body: they are never default end
// effectors nor humanoid bones. Two kinds, both read from names and checked against the tree:
// - a bone with a control word (ik, fk, pole, target, ctrl, ctl, control, controller, mch) whose
//   whole subtree has one too ("PoleTargetL", "foot_ik.L");
// - a bone named as a limb's end (foot, ankle / hand, wrist, palm) and sided, outside every limb
//   chain of its kind, while a limb of that kind and side lies deeper in the body ("FootL" next to
//   "UpperLegL > LowerLegL"). A foot at the end of its leg is never one.
// Either kind must hang above the body: be a root, or the child of a root that is not the hips
// (a bone off a root named hips, hip or pelvis is a body part, a look-alike at most).
import { nameSide, nameTokens, type Side } from '../bone_names.js';
import { chooseChainChild } from '../chain_child.js';
import type { HumanoidRole } from './humanoid_roles.js';

export type Limb = 'leg' | 'arm';
export const LIMBS: readonly Limb[] = ['leg', 'arm'];

export interface ControlBone {
  bone: number;
  /** 'named': a control word says so; 'limbEnd': named as a hand or foot but outside the limbs. */
  kind: 'named' | 'limbEnd';
  /** The side its name states. */
  side: Side;
  /** For a 'limbEnd': the limb whose end it is named as. */
  limb?: Limb;
}

const CONTROL_WORDS = new Set(['ik', 'fk', 'pole', 'target', 'ctrl', 'ctl', 'control', 'controller', 'mch']);
const HIPS_WORDS = new Set(['hips', 'hip', 'pelvis']);
/** Words of a bone in a limb chain (above its end). */
const LIMB_WORDS: Record<Limb, ReadonlySet<string>> = {
  leg: new Set(['leg', 'upleg', 'upperleg', 'lowerleg', 'thigh', 'shin', 'calf', 'knee']),
  arm: new Set(['arm', 'upperarm', 'lowerarm', 'forearm', 'elbow']),
};
/** Words of a limb's end. */
const END_WORDS: Record<Limb, ReadonlySet<string>> = {
  leg: new Set(['foot', 'ankle']),
  arm: new Set(['hand', 'wrist', 'palm']),
};
/** Words of a part of a hand or foot: such a bone is no limb end. */
const PART_WORDS = new Set([
  'thumb',
  'index',
  'middle',
  'ring',
  'pinky',
  'little',
  'finger',
  'fingers',
  'toe',
  'toes',
  'ball',
  'heel',
]);

/** What the control-bone rules read of a rig: each bone's words, side, depth and limb membership. */
interface NameFacts {
  tokens: string[][];
  side: Side[];
  depth: Int32Array;
  control: boolean[];
  /** Per limb, whether each bone is named as a bone of that limb's chain (and is no control). */
  inLimb: Record<Limb, boolean[]>;
  /** Per limb, whether some bone strictly below each bone is in that limb's chain. */
  limbBelow: Record<Limb, boolean[]>;
}

function nameFacts(names: readonly string[], parents: ArrayLike<number>): NameFacts {
  const n = names.length;
  const tokens = names.map(nameTokens);
  const side = tokens.map(nameSide);
  const depth = new Int32Array(n);
  for (let b = 0; b < n; b++) if (parents[b] >= 0) depth[b] = depth[parents[b]] + 1;
  const control = tokens.map((t) => t.some((w) => CONTROL_WORDS.has(w)));
  const inLimb = {} as Record<Limb, boolean[]>;
  const limbBelow = {} as Record<Limb, boolean[]>;
  for (const limb of LIMBS) {
    inLimb[limb] = tokens.map((t, b) => !control[b] && t.some((w) => LIMB_WORDS[limb].has(w)));
    const below = new Array<boolean>(n).fill(false);
    for (let b = n - 1; b >= 0; b--) if (parents[b] >= 0 && (inLimb[limb][b] || below[b])) below[parents[b]] = true;
    limbBelow[limb] = below;
  }
  return { tokens, side, depth, control, inLimb, limbBelow };
}

/**
 * The control bones of a rig (ascending): `names` and `parents` of its bones, parents first
 * (depth-first). Linear time.
 */
export function controlBones(names: readonly string[], parents: ArrayLike<number>): ControlBone[] {
  const f = nameFacts(names, parents);
  const n = names.length;
  // Whether every bone of each bone's subtree has a control word.
  const allControl = [...f.control];
  for (let b = n - 1; b >= 0; b--) if (parents[b] >= 0 && !allControl[b]) allControl[parents[b]] = false;
  // Per limb and side, whether a bone of that limb's chain lies deeper than a root's child.
  const deepLimb = new Set<string>();
  for (const limb of LIMBS)
    for (let b = 0; b < n; b++) if (f.inLimb[limb][b] && f.depth[b] >= 2) deepLimb.add(`${limb} ${f.side[b]}`);

  const hangsAbove = (b: number): boolean => {
    const p = parents[b];
    return p < 0 || (parents[p] < 0 && !f.tokens[p].some((w) => HIPS_WORDS.has(w)));
  };
  const found: ControlBone[] = [];
  for (let b = 0; b < n; b++) {
    if (!hangsAbove(b)) continue;
    if (f.control[b]) {
      if (allControl[b]) found.push({ bone: b, kind: 'named', side: f.side[b] });
      continue;
    }
    const side = f.side[b];
    if (side === 'none' || f.tokens[b].some((w) => PART_WORDS.has(w))) continue;
    const p = parents[b];
    const limb = LIMBS.find(
      (l) =>
        f.tokens[b].some((w) => END_WORDS[l].has(w)) &&
        !f.inLimb[l][b] &&
        !f.limbBelow[l][b] &&
        (p < 0 || !f.inLimb[l][p]) &&
        deepLimb.has(`${l} ${side}`),
    );
    if (limb) found.push({ bone: b, kind: 'limbEnd', side, limb });
  }
  return found;
}

/**
 * The end of the `limb` chain on `side` found by name: the child of its last bone (a bone named
 * for the limb with none below it; the deepest, then the first), or that bone itself when it has
 * no child; a child that is a control bone is passed over. Undefined when there is no such chain,
 * or its end moves with the root alone. Linear time.
 */
export function limbChainEnd(
  names: readonly string[],
  parents: ArrayLike<number>,
  limb: Limb,
  side: Side,
  controls: ReadonlySet<number>,
): number | undefined {
  const f = nameFacts(names, parents);
  let last = -1;
  for (let b = 0; b < names.length; b++)
    if (f.inLimb[limb][b] && f.side[b] === side && !f.limbBelow[limb][b] && (last < 0 || f.depth[b] > f.depth[last]))
      last = b;
  if (last < 0) return undefined;
  const descendants = new Int32Array(names.length);
  for (let b = names.length - 1; b >= 0; b--) if (parents[b] >= 0) descendants[parents[b]] += descendants[b] + 1;
  const children: { bone: number; name: string; descendants: number }[] = [];
  for (let b = last + 1; b < names.length && f.depth[b] > f.depth[last]; b++)
    if (parents[b] === last && !controls.has(b))
      children.push({ bone: b, name: names[b], descendants: descendants[b] });
  const end = children.length ? chooseChainChild(children).bone : last;
  return f.depth[end] >= 2 ? end : undefined;
}

/** The humanoid roles of a limb's lower bone and end on a side: ('leg', 'left') -> leftLowerLeg, leftFoot. */
export function limbRoles(limb: Limb, side: 'left' | 'right'): { lower: HumanoidRole; end: HumanoidRole } {
  return limb === 'leg'
    ? { lower: `${side}LowerLeg`, end: `${side}Foot` }
    : { lower: `${side}LowerArm`, end: `${side}Hand` };
}

/** A limb's own end standing in for a control bone named as that end. */
export interface EndStandIn {
  /** The control bone (a 'limbEnd' one). */
  control: number;
  /** The bone whose tip is the limb's end effector instead. */
  end: number;
}

/**
 * For a humanoid mapping (role -> bone) that lacks a hand or foot on a side where a control bone
 * is named as one: its lower arm or leg, whose tip then is the limb's end effector.
 */
export function lowerLimbStandIns(
  bones: Partial<Record<HumanoidRole, number>>,
  controls: readonly ControlBone[],
): EndStandIn[] {
  const out: EndStandIn[] = [];
  for (const c of controls) {
    if (c.kind !== 'limbEnd' || c.side === 'none' || !c.limb) continue;
    const { lower, end } = limbRoles(c.limb, c.side);
    const low = bones[lower];
    if (bones[end] === undefined && low !== undefined && !out.some((s) => s.end === low))
      out.push({ control: c.bone, end: low });
  }
  return out;
}

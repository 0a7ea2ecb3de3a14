// The naming conventions humanoid recognition reads (docs/gltf-ik-extras.md, "Humanoid
// recognition"): Mixamo, Unreal's mannequin, Blender metarig/Rigify, 3ds Max Biped and generic
// names. A name is split into words (bone_names.ts); its side words are set aside and its last
// words are looked up, longest first, so that any prefix ("mixamorig9:", "DEF-", "Bip01 ",
// "Character1_") is skipped: "mixamorig:LeftForeArm" -> left + "forearm" -> lowerArm.
import { isSideToken, nameSide, nameTokens, type Side } from '../bone_names.js';
import type { HumanoidSource } from './humanoid_roles.js';

/** A body part a name can state; with a side it is a HumanoidRole ("left" + "upperArm"). */
export type BodyPart =
  'hips' | 'neck' | 'head' | 'shoulder' | 'upperArm' | 'lowerArm' | 'hand' | 'upperLeg' | 'lowerLeg' | 'foot' | 'toes';

/** The parts without a side (the head, neck and hips lie on the body's midline). */
export const MIDLINE_PARTS: readonly BodyPart[] = ['hips', 'neck', 'head'];

export type NameSource = Exclude<HumanoidSource, 'vrm0' | 'vrm1'>;

export interface Convention {
  source: NameSource;
  /** Per part, the names it takes: the last words of a bone's name, side words removed, joined. */
  names: Record<BodyPart, string[]>;
  /** Names taken for a part only when no bone has one of its `names`. */
  fallbacks?: Partial<Record<BodyPart, string[]>>;
  /**
   * True: a name whose last word carries a number glued to it ("Palm2L", "Hand01_L") is also
   * read without the number, after the names without one ("PalmL" before "Palm2L").
   */
  numbered?: boolean;
}

/** The conventions, in the order that breaks a tie between two that map as many core roles. */
export const CONVENTIONS: readonly Convention[] = [
  {
    source: 'mixamo',
    names: {
      hips: ['hips'],
      neck: ['neck'],
      head: ['head'],
      shoulder: ['shoulder'],
      upperArm: ['arm'],
      lowerArm: ['forearm'],
      hand: ['hand'],
      upperLeg: ['upleg'],
      lowerLeg: ['leg'],
      foot: ['foot'],
      toes: ['toebase'],
    },
  },
  {
    source: 'unreal',
    names: {
      hips: ['pelvis'],
      neck: ['neck01', 'neck'],
      head: ['head'],
      shoulder: ['clavicle'],
      upperArm: ['upperarm'],
      lowerArm: ['lowerarm'],
      hand: ['hand'],
      upperLeg: ['thigh'],
      lowerLeg: ['calf'],
      foot: ['foot'],
      toes: ['ball'],
    },
  },
  {
    // The metarig's spine chain: spine (the hips), spine.001-.003, spine.004 (neck), spine.006 (head).
    source: 'rigify',
    names: {
      hips: ['hips', 'pelvis'],
      neck: ['neck'],
      head: ['head'],
      shoulder: ['shoulder'],
      upperArm: ['upperarm'],
      lowerArm: ['forearm'],
      hand: ['hand'],
      upperLeg: ['thigh'],
      lowerLeg: ['shin'],
      foot: ['foot'],
      toes: ['toe'],
    },
    fallbacks: { hips: ['spine'], neck: ['spine004'], head: ['spine006'] },
  },
  {
    source: 'biped',
    names: {
      hips: ['pelvis'],
      neck: ['neck'],
      head: ['head'],
      shoulder: ['clavicle'],
      upperArm: ['upperarm'],
      lowerArm: ['forearm'],
      hand: ['hand'],
      upperLeg: ['thigh'],
      lowerLeg: ['calf'],
      foot: ['foot'],
      toes: ['toe0'],
    },
  },
  {
    source: 'generic',
    names: {
      hips: ['hips', 'hip', 'pelvis'],
      neck: ['neck'],
      head: ['head'],
      shoulder: ['shoulder', 'clavicle', 'collar', 'collarbone'],
      upperArm: ['upperarm', 'armupper', 'arm'],
      lowerArm: ['lowerarm', 'armlower', 'forearm', 'elbow'],
      hand: ['hand', 'palm', 'wrist'],
      upperLeg: ['upperleg', 'legupper', 'upleg', 'thigh'],
      lowerLeg: ['lowerleg', 'leglower', 'shin', 'calf', 'knee'],
      foot: ['foot', 'ankle'],
      toes: ['toes', 'toe', 'toebase', 'ball'],
    },
    numbered: true,
  },
];

// A name with one of these words is a control or helper, not a deforming body bone.
const HELPER_WORDS = new Set(['ik', 'fk', 'ctrl', 'control', 'target', 'pole', 'twist', 'roll', 'mch']);

// Words that only say "this is a joint" ("LeftHand_jnt", "hand_l_bind"), set aside like the side.
const JOINT_WORDS = new Set(['jnt', 'joint', 'bind', 'bone']);

/** Most words of a looked-up name ("upper arm", "toe base", "spine 004"). */
const MAX_NAME_WORDS = 2;

/** What recognition reads of one bone name. */
export interface BoneName {
  side: Side;
  /** The last 1..MAX_NAME_WORDS words (side and joint words removed), joined, longest first. */
  endings: string[];
  /**
   * When the last of those words is a number glued to the word before it in the name ("Palm2L",
   * not "thigh.L.001"): the endings without it, for conventions that read numbered names.
   */
  unnumbered?: string[];
}

/** The last 1..MAX_NAME_WORDS of `words`, joined, longest first. */
function endingsOf(words: string[]): string[] {
  const endings: string[] = [];
  for (let n = Math.min(MAX_NAME_WORDS, words.length); n >= 1; n--) endings.push(words.slice(-n).join(''));
  return endings;
}

// The name's last run of digits and the character before it (a letter when the number is glued on).
const LAST_NUMBER = /([A-Za-z]?)[0-9]+[^0-9]*$/;

/** The readable parts of a bone name, or null for a helper bone (ik, twist, ctrl...) or an empty name. */
export function readBoneName(name: string): BoneName | null {
  const tokens = nameTokens(name);
  if (tokens.length === 0 || tokens.some((t) => HELPER_WORDS.has(t))) return null;
  const words = tokens.filter((t) => !isSideToken(t) && !JOINT_WORDS.has(t));
  const read: BoneName = { side: nameSide(tokens), endings: endingsOf(words) };
  // Side and joint words hold no digits, so a number last among the words is the name's last number.
  if (
    words.length >= 2 &&
    /^[0-9]+$/.test(words[words.length - 1]) &&
    /^[a-z]/.test(words[words.length - 2]) &&
    LAST_NUMBER.exec(name)?.[1]
  )
    read.unnumbered = endingsOf(words.slice(0, -1));
  return read;
}

/** One convention's name table, ready for lookups: ending -> part and rank (0 = name, 1 = fallback). */
export type NameTable = Map<string, { part: BodyPart; rank: number }>;

/** The lookup table of a convention. */
export function nameTable(c: Convention): NameTable {
  const table: NameTable = new Map();
  for (const [rank, names] of [c.names, c.fallbacks ?? {}].entries())
    for (const [part, list] of Object.entries(names) as [BodyPart, string[]][])
      for (const n of list) if (!table.has(n)) table.set(n, { part, rank });
  return table;
}

/**
 * The part (and rank) a bone name states in a convention: its longest ending found in the table;
 * with `numbered`, else its longest ending without a glued number, ranked after the others.
 */
export function namedPart(
  name: BoneName,
  table: NameTable,
  numbered = false,
): { part: BodyPart; rank: number } | undefined {
  for (const ending of name.endings) {
    const hit = table.get(ending);
    if (hit) return hit;
  }
  if (numbered)
    for (const ending of name.unnumbered ?? []) {
      const hit = table.get(ending);
      if (hit) return { part: hit.part, rank: hit.rank + 2 };
    }
  return undefined;
}

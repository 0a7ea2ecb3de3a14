// Rig files built in memory for the loader tests (the trees of a parent list are in
// scripts/rig_files/tree_rigs.ts): what loading one says, humanoids in each naming style, robots.
import { loadRig, RigFormatError } from '../../web/src/rig/load_rig.js';
import { nodeIndex, packGlb, unpackGlb } from '../../scripts/rig_files/glb.js';

/** The message of the RigFormatError that loading `bytes` as `file` gives; fails the test on success or another error. */
export async function loadError(bytes: Uint8Array | string, file: string): Promise<string> {
  const data = typeof bytes === 'string' ? new TextEncoder().encode(bytes) : bytes;
  const error = await loadRig(data, file).then(
    () => new Error(`${file} loaded without an error`),
    (e: unknown) => e as Error,
  );
  if (!(error instanceof RigFormatError)) throw error;
  if (!error.message.startsWith(`${file}: `))
    throw new Error(`the message does not start with the file name: ${error.message}`);
  return error.message;
}

// Humanoids named in one naming style each, and robot-style rigs whose feet are control bones
// (tests/rig/naming_styles.test.ts, control_bones.test.ts): joint lists for skeletonGlb.
import type { HumanoidRole } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { humanoidJoints } from '../helpers/named_humanoid.js';
import type { SkeletonJoint } from '../helpers/skeleton_glb.js';

/** The limb parts a naming style names, in the test humanoid's role words. */
type StyledLimb = 'Shoulder' | 'UpperArm' | 'LowerArm' | 'Hand' | 'UpperLeg' | 'LowerLeg' | 'Foot' | 'Toes';
const STYLED_LIMBS: StyledLimb[] = ['Shoulder', 'UpperArm', 'LowerArm', 'Hand', 'UpperLeg', 'LowerLeg', 'Foot', 'Toes'];

/** The naming styles of styledHumanoid. */
export const NAMING_STYLES = ['mixamo', 'CamelSuffix', 'dotSuffix', 'lowerSnake', 'snakeSuffix', 'sidePrefix'] as const;
export type NamingStyle = (typeof NAMING_STYLES)[number];

/** The limb words of each style that differ from the role's own (UpperArm, LowerLeg...). */
const STYLE_WORDS: Record<NamingStyle, Partial<Record<StyledLimb, string>>> = {
  mixamo: { UpperArm: 'Arm', LowerArm: 'ForeArm', UpperLeg: 'UpLeg', LowerLeg: 'Leg', Toes: 'ToeBase' },
  CamelSuffix: { Hand: 'Palm' },
  dotSuffix: {},
  lowerSnake: {},
  snakeSuffix: { Hand: 'Wrist' },
  sidePrefix: { Hand: 'Palm' },
};

/** One bone name in a style: `word` (CamelCase) on side 'L', 'R' or none. */
function styledName(style: NamingStyle, word: string, side: 'L' | 'R' | ''): string {
  switch (style) {
    case 'mixamo':
      return `mixamorig:${side === 'L' ? 'Left' : side === 'R' ? 'Right' : ''}${word}`;
    case 'CamelSuffix': // UpperLegL
      return `${word}${side}`;
    case 'dotSuffix': // UpperLeg.L
      return side ? `${word}.${side}` : word;
    case 'lowerSnake': // upperleg_l
      return side ? `${word.toLowerCase()}_${side.toLowerCase()}` : word.toLowerCase();
    case 'snakeSuffix': // UpperLeg_L
      return side ? `${word}_${side}` : word;
    case 'sidePrefix': // L_UpperLeg
      return side ? `${side}_${word}` : word;
  }
}

/** The role -> bone name map of a humanoid named in `style` (hips, spine, chest, neck, head and both sides' limbs). */
export function styledRoles(style: NamingStyle): Partial<Record<HumanoidRole, string>> {
  const roles: Partial<Record<HumanoidRole, string>> = {
    hips: styledName(style, 'Hips', ''),
    spine: styledName(style, 'Spine', ''),
    chest: styledName(style, style === 'mixamo' ? 'Spine1' : 'Chest', ''),
    neck: styledName(style, 'Neck', ''),
    head: styledName(style, 'Head', ''),
  };
  for (const [side, L] of [
    ['left', 'L'],
    ['right', 'R'],
  ] as const)
    for (const limb of STYLED_LIMBS)
      roles[`${side}${limb}` as HumanoidRole] = styledName(style, STYLE_WORDS[style][limb] ?? limb, L);
  return roles;
}

/** The joints of the test humanoid named in `style`, with finger and end bones as real files have. */
export function styledHumanoid(style: NamingStyle): SkeletonJoint[] {
  const roles = styledRoles(style);
  return humanoidJoints({
    roles,
    extra: [
      { name: styledName(style, 'HeadTop_End', ''), parent: 'head', offset: [0, 0.2, 0] },
      { name: styledName(style, 'Index1', 'L'), parent: 'leftHand', offset: [0.08, 0, 0.02] },
      { name: styledName(style, 'Index1', 'R'), parent: 'rightHand', offset: [-0.08, 0, 0.02] },
    ],
  });
}

export interface RobotOptions {
  /** The feet: 'controls' hang off the root bone (Blender IK targets), 'legs' end the legs. */
  feet: 'controls' | 'legs';
  /** With control feet: true (default), each lower leg has an end bone (LowerLegL_end); false, the lower leg ends the leg. */
  legEnds?: boolean;
  /** True (default): PoleTargetL/R hang off the root bone. */
  poles?: boolean;
}

/**
 * A stylised robot named like three.js's RobotExpressive: a root bone "Bone" holding the body
 * (Body > Hips > Abdomen > Torso > Neck > Head, ShoulderL > UpperArmL > LowerArmL > Palm2L with
 * Palm1L and Palm3L beside it and fingers, UpperLegL > LowerLegL > FootL with feet: 'legs') or,
 * with feet: 'controls', legs ending at LowerLegL [> LowerLegL_end] and FootL/FootR beside the
 * body as IK targets; PoleTargetL/R as poles.
 */
export function robotRig(options: RobotOptions): SkeletonJoint[] {
  const { feet, legEnds = true, poles = true } = options;
  const joints: SkeletonJoint[] = [
    { name: 'Bone', head: [0, 0, 0] },
    { name: 'Body', parent: 'Bone', head: [0, 1, 0] },
    { name: 'Hips', parent: 'Body', head: [0, 1.05, 0] },
    { name: 'Abdomen', parent: 'Hips', head: [0, 1.15, 0] },
    { name: 'Torso', parent: 'Abdomen', head: [0, 1.3, 0] },
    { name: 'Neck', parent: 'Torso', head: [0, 1.55, 0] },
    { name: 'Head', parent: 'Neck', head: [0, 1.65, 0] },
  ];
  for (const [L, x] of [
    ['L', 1],
    ['R', -1],
  ] as const) {
    const at = (px: number, y: number, z = 0): [number, number, number] => [x * px, y, z];
    joints.push(
      { name: `Shoulder${L}`, parent: 'Torso', head: at(0.1, 1.5) },
      { name: `UpperArm${L}`, parent: `Shoulder${L}`, head: at(0.25, 1.5) },
      { name: `LowerArm${L}`, parent: `UpperArm${L}`, head: at(0.5, 1.5, -0.02) },
      { name: `Palm2${L}`, parent: `LowerArm${L}`, head: at(0.75, 1.5) },
      { name: `Middle1${L}`, parent: `Palm2${L}`, head: at(0.85, 1.5) },
      { name: `Palm1${L}`, parent: `LowerArm${L}`, head: at(0.75, 1.5, 0.03) },
      { name: `Thumb${L}`, parent: `Palm1${L}`, head: at(0.8, 1.5, 0.06) },
      { name: `Palm3${L}`, parent: `LowerArm${L}`, head: at(0.75, 1.5, -0.03) },
      { name: `Ring1${L}`, parent: `Palm3${L}`, head: at(0.85, 1.5, -0.03) },
      { name: `UpperLeg${L}`, parent: 'Hips', head: at(0.12, 1) },
      { name: `LowerLeg${L}`, parent: `UpperLeg${L}`, head: at(0.12, 0.55, 0.02) },
    );
    if (feet === 'legs') joints.push({ name: `Foot${L}`, parent: `LowerLeg${L}`, head: at(0.12, 0.1) });
    else if (legEnds) joints.push({ name: `LowerLeg${L}_end`, parent: `LowerLeg${L}`, head: at(0.12, 0.1) });
  }
  if (feet === 'controls')
    joints.push(
      { name: 'FootL', parent: 'Bone', head: [0.12, 0.05, 0] },
      { name: 'FootR', parent: 'Bone', head: [-0.12, 0.05, 0] },
    );
  if (poles)
    joints.push(
      { name: 'PoleTargetL', parent: 'Bone', head: [0.12, 0.55, 0.5] },
      { name: 'PoleTargetR', parent: 'Bone', head: [-0.12, 0.55, 0.5] },
    );
  return joints;
}

/** A turn of a node about one of its own (local) axes, degrees. */
export interface NodeTurn {
  axis: [number, number, number];
  deg: number;
}

/**
 * `bytes` (.glb) with the named nodes turned about their local axes (rotation := rotation * turn),
 * every other byte kept: a file saved posed, whose inverse bind matrices still hold the unposed rest.
 */
export function turnedGlb(bytes: Uint8Array, turns: Record<string, NodeTurn>): Uint8Array {
  const { json, bin } = unpackGlb(bytes);
  for (const [name, { axis, deg }] of Object.entries(turns)) {
    const node = json.nodes[nodeIndex(json, name)];
    if (node.matrix !== undefined) throw new Error(`node ${name} is given as a matrix`);
    const n = Math.hypot(...axis),
      h = (deg * Math.PI) / 360;
    const t = [...axis.map((v) => (v / n) * Math.sin(h)), Math.cos(h)];
    const q = (node.rotation as number[] | undefined) ?? [0, 0, 0, 1];
    // q * t (x, y, z, w)
    node.rotation = [
      q[3] * t[0] + q[0] * t[3] + q[1] * t[2] - q[2] * t[1],
      q[3] * t[1] - q[0] * t[2] + q[1] * t[3] + q[2] * t[0],
      q[3] * t[2] + q[0] * t[1] - q[1] * t[0] + q[2] * t[3],
      q[3] * t[3] - q[0] * t[0] - q[1] * t[1] - q[2] * t[2],
    ];
  }
  return packGlb(json, bin);
}

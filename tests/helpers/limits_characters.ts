// Humanoid test characters without IK extras, and their humanoid maps written out by hand (the
// recognition code is tested on its own): the project character built Mixamo-style from its model
// description, turned to face another way or with Mixamo's joint frames (knee hinge on local X),
// and the Blender-named test character of gltf_character.ts (bent limbs, rolls, a tilted world).
import { WebIO } from '@gltf-transform/core';

import { character } from '../../scripts/models/character.js';
import { buildDocument, type JointDef } from '../../scripts/models/model.js';
import { cross, normalize, sub, type Vec3 } from '../../scripts/models/vec.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import type { HumanoidMap, HumanoidRole, HumanoidSource } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { loadRig, specWithFileLimits } from '../../web/src/rig/load_rig.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';

export interface MixamoOptions {
  /** Turn of the whole character about +Y, degrees (0: facing +Z, 180: -Z, 90: +X). */
  yawDeg?: number;
  /**
   * Joint frames as Mixamo's files have them: a limb's flexion about the joint's local X rather
   * than its local Z (the project character's own frames put every hinge on local Z).
   */
  hingeOnLocalX?: boolean;
  /** Moves both knees forward by this much (cm; negative: back, a reverse-bent leg). Default 0: straight legs. */
  kneeForward?: number;
}

/** The joint moved so that the knees sit `forward` cm further forward (both thigh tails and shin heads). */
function moveKnees(j: JointDef, forward: number): JointDef {
  const shift = (p: Vec3): Vec3 => [p[0], p[1], p[2] + forward];
  if (/UpLeg$/.test(j.name)) return { ...j, tail: shift(j.tail) };
  if (/(Left|Right)Leg$/.test(j.name)) return { ...j, head: shift(j.head) };
  return j;
}

/** The project character (65 Mixamo-named joints) as .glb bytes, with no extras.ik at all. */
export async function mixamoCharacterGlb(options: MixamoOptions = {}): Promise<Uint8Array> {
  const half = ((options.yawDeg ?? 0) * Math.PI) / 360;
  const doc = buildDocument({
    ...character,
    armature: { ...character.armature, rotation: [0, Math.sin(half), 0, Math.cos(half)] },
    joints: character.joints.map((def) => {
      const j = moveKnees(def, options.kneeForward ?? 0);
      // local X = y x z is the old hinge when the new z is hinge x y (y along the bone).
      return { ...j, hinge: options.hingeOnLocalX ? cross(j.hinge, normalize(sub(j.tail, j.head))) : j.hinge };
    }),
  });
  for (const node of doc.getRoot().listNodes()) node.setExtras({});
  return new WebIO().writeBinary(doc);
}

const sided = (left: string, right: string, names: Record<string, string>): Partial<Record<HumanoidRole, string>> =>
  Object.fromEntries(
    Object.entries(names).flatMap(([role, name]) => [
      [`left${role}`, name.replace('#', left)],
      [`right${role}`, name.replace('#', right)],
    ]),
  );

/** Role -> joint name of the Mixamo character. */
export const MIXAMO_NAMES: Partial<Record<HumanoidRole, string>> = {
  hips: 'mixamorig:Hips',
  spine: 'mixamorig:Spine',
  chest: 'mixamorig:Spine1',
  upperChest: 'mixamorig:Spine2',
  neck: 'mixamorig:Neck',
  head: 'mixamorig:Head',
  ...sided('Left', 'Right', {
    Shoulder: 'mixamorig:#Shoulder',
    UpperArm: 'mixamorig:#Arm',
    LowerArm: 'mixamorig:#ForeArm',
    Hand: 'mixamorig:#Hand',
    UpperLeg: 'mixamorig:#UpLeg',
    LowerLeg: 'mixamorig:#Leg',
    Foot: 'mixamorig:#Foot',
    Toes: 'mixamorig:#ToeBase',
  }),
};

/** Role -> joint name of the Blender-named test character (scripts/rig_files/gltf_character.ts). */
export const BLENDER_NAMES: Partial<Record<HumanoidRole, string>> = {
  hips: 'hips',
  spine: 'spine',
  chest: 'chest',
  neck: 'neck',
  head: 'head',
  ...sided('L', 'R', {
    Shoulder: 'shoulder.#',
    UpperArm: 'upper_arm.#',
    LowerArm: 'forearm.#',
    Hand: 'hand.#',
    UpperLeg: 'thigh.#',
    LowerLeg: 'shin.#',
    Foot: 'foot.#',
    Toes: 'toe.#',
  }),
};

/** The humanoid map of `spec` from role -> bone name (every name must be a bone). */
export function mapByNames(
  spec: RigSpec,
  source: HumanoidSource,
  names: Partial<Record<HumanoidRole, string>>,
): HumanoidMap {
  const bones: HumanoidMap['bones'] = {};
  for (const [role, name] of Object.entries(names) as [HumanoidRole, string][]) {
    const i = spec.names.indexOf(name);
    if (i < 0) throw new Error(`no bone ${name}`);
    bones[role] = i;
  }
  return { source, bones, missing: [] };
}

export interface TestHumanoid {
  spec: RigSpec;
  map: HumanoidMap;
  /** The direction the character faces, as built (rig space). */
  forward: [number, number, number];
  /** Up, as built. */
  up: [number, number, number];
}

/** The Mixamo character loaded through the importer, with its map and its built facing. */
export async function mixamoHumanoid(options: MixamoOptions = {}): Promise<TestHumanoid> {
  const spec = specWithFileLimits(await loadRig(await mixamoCharacterGlb(options), 'mixamo-character.glb'));
  const yaw = ((options.yawDeg ?? 0) * Math.PI) / 180;
  return {
    spec,
    map: mapByNames(spec, 'mixamo', MIXAMO_NAMES),
    forward: [Math.sin(yaw), 0, Math.cos(yaw)],
    up: [0, 1, 0],
  };
}

/**
 * The Blender-named test character, standing on a world turned 30 degrees about +Y and an
 * Armature tilted 10 degrees about +Z (gltf_character.ts).
 */
export async function blenderHumanoid(): Promise<TestHumanoid> {
  const spec = specWithFileLimits(await loadRig(await testCharacterGlb(), 'blender-character.glb'));
  const s = Math.sin(Math.PI / 6),
    c = Math.cos(Math.PI / 6),
    t = (10 * Math.PI) / 180;
  // Armature: +Z stays +Z under the tilt about Z; up is +Y tilted; both then turned 30 degrees about Y.
  const up: [number, number, number] = [-Math.sin(t), Math.cos(t), 0];
  return {
    spec,
    map: mapByNames(spec, 'rigify', BLENDER_NAMES),
    forward: [s, 0, c],
    up: [c * up[0], up[1], -s * up[0]],
  };
}

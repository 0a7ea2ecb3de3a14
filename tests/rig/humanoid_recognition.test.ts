// Humanoid recognition on characters built in the test, one per naming convention (Mixamo,
// Unreal, Rigify, Biped, generic) and per VRM version: every role maps to the intended bone,
// helper bones (fingers, ends, twist and IK bones) and misplaced look-alikes are passed over,
// a VRM extension wins over names, and a rig without the hips and two limbs is no humanoid.
import { describe, expect, it } from 'vitest';

import { humanoidByName } from '../../web/src/rig/humanoid/humanoid_recognition.js';
import { HUMANOID_ROLES, type HumanoidRole } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { nodeIndex, packGlb, unpackGlb } from '../../scripts/rig_files/glb.js';
import { humanoidJoints, type HumanoidNaming } from '../helpers/named_humanoid.js';
import { skeletonGlb } from '../helpers/skeleton_glb.js';

type Limb = 'Shoulder' | 'UpperArm' | 'LowerArm' | 'Hand' | 'UpperLeg' | 'LowerLeg' | 'Foot' | 'Toes';
const LIMBS: Limb[] = ['Shoulder', 'UpperArm', 'LowerArm', 'Hand', 'UpperLeg', 'LowerLeg', 'Foot', 'Toes'];
interface SideNames {
  side: 'left' | 'right';
  Side: 'Left' | 'Right';
  L: 'L' | 'R';
  l: 'l' | 'r';
}
const SIDES: SideNames[] = [
  { side: 'left', Side: 'Left', L: 'L', l: 'l' },
  { side: 'right', Side: 'Right', L: 'R', l: 'r' },
];

/** Both sides' limb roles named by `name`. */
function limbNames(name: (limb: Limb, s: SideNames) => string): Partial<Record<HumanoidRole, string>> {
  return Object.fromEntries(SIDES.flatMap((s) => LIMBS.map((limb) => [`${s.side}${limb}`, name(limb, s)])));
}

type Vec3 = [number, number, number];

/** An extra bone on each side: its name, its parent (a role or bone name), its offset on the left (mirrored on the right). */
function onBothSides(
  name: (s: SideNames) => string,
  parent: (s: SideNames) => string,
  offset: Vec3,
): { name: string; parent: string; offset: Vec3 }[] {
  return SIDES.map((s) => ({
    name: name(s),
    parent: parent(s),
    offset: s.side === 'left' ? offset : [-offset[0], offset[1], offset[2]],
  }));
}

const M = 'mixamorig9:';
const mixamoWords: Record<Limb, string> = {
  Shoulder: 'Shoulder',
  UpperArm: 'Arm',
  LowerArm: 'ForeArm',
  Hand: 'Hand',
  UpperLeg: 'UpLeg',
  LowerLeg: 'Leg',
  Foot: 'Foot',
  Toes: 'ToeBase',
};
const mixamo: HumanoidNaming = {
  roles: {
    hips: `${M}Hips`,
    spine: `${M}Spine`,
    chest: `${M}Spine1`,
    upperChest: `${M}Spine2`,
    neck: `${M}Neck`,
    head: `${M}Head`,
    ...limbNames((limb, s) => `${M}${s.Side}${mixamoWords[limb]}`),
  },
  extra: [
    { name: `${M}HeadTop_End`, parent: 'head', offset: [0, 0.2, 0] },
    ...onBothSides(
      (s) => `${M}${s.Side}HandIndex1`,
      (s) => `${s.side}Hand`,
      [0.1, 0, 0.02],
    ),
    ...onBothSides(
      (s) => `${M}${s.Side}Toe_End`,
      (s) => `${s.side}Toes`,
      [0, 0, 0.06],
    ),
  ],
};

const unrealWords: Record<Limb, string> = {
  Shoulder: 'clavicle',
  UpperArm: 'upperarm',
  LowerArm: 'lowerarm',
  Hand: 'hand',
  UpperLeg: 'thigh',
  LowerLeg: 'calf',
  Foot: 'foot',
  Toes: 'ball',
};
const unreal: HumanoidNaming = {
  root: 'root',
  roles: {
    hips: 'pelvis',
    spine: 'spine_01',
    chest: 'spine_02',
    upperChest: 'spine_03',
    neck: 'neck_01',
    head: 'head',
    ...limbNames((limb, s) => `${unrealWords[limb]}_${s.l}`),
  },
  extra: [
    { name: 'ik_foot_root', parent: 'root', offset: [0, 0, 0] },
    ...onBothSides(
      (s) => `ik_foot_${s.l}`,
      () => 'ik_foot_root',
      [0.1, 0.08, 0],
    ),
    ...onBothSides(
      (s) => `upperarm_twist_01_${s.l}`,
      (s) => `${s.side}UpperArm`,
      [0.1, 0, 0],
    ),
    ...onBothSides(
      (s) => `index_01_${s.l}`,
      (s) => `${s.side}Hand`,
      [0.1, 0, 0.02],
    ),
  ],
};

// Rigify's deforming bones: the metarig's spine chain (spine = the hips, spine.004 the neck,
// spine.006 the head), limbs cut in two segments (upper_arm.L, upper_arm.L.001).
const rigifyWords: Record<Limb, string> = {
  Shoulder: 'shoulder',
  UpperArm: 'upper_arm',
  LowerArm: 'forearm',
  Hand: 'hand',
  UpperLeg: 'thigh',
  LowerLeg: 'shin',
  Foot: 'foot',
  Toes: 'toe',
};
const rigify: HumanoidNaming = {
  roles: {
    hips: 'DEF-spine',
    spine: 'DEF-spine.001',
    chest: 'DEF-spine.002',
    upperChest: 'DEF-spine.003',
    neck: 'DEF-spine.004',
    head: 'DEF-spine.006',
    ...limbNames((limb, s) => `DEF-${rigifyWords[limb]}.${s.L}`),
  },
  parents: {
    head: 'DEF-spine.005',
    leftLowerArm: 'DEF-upper_arm.L.001',
    rightLowerArm: 'DEF-upper_arm.R.001',
    leftLowerLeg: 'DEF-thigh.L.001',
    rightLowerLeg: 'DEF-thigh.R.001',
  },
  extra: [
    { name: 'DEF-spine.005', parent: 'neck', offset: [0, 0.05, 0] },
    ...onBothSides(
      (s) => `DEF-upper_arm.${s.L}.001`,
      (s) => `${s.side}UpperArm`,
      [0.14, 0, 0],
    ),
    ...onBothSides(
      (s) => `DEF-thigh.${s.L}.001`,
      (s) => `${s.side}UpperLeg`,
      [0, -0.2, 0],
    ),
    ...onBothSides(
      (s) => `DEF-pelvis.${s.L}`,
      () => 'hips',
      [0.08, 0, 0.05],
    ),
  ],
};

// 3ds Max Biped: the thighs hang off Bip01 Spine, the clavicles off Bip01 Neck.
const bipedWords: Record<Limb, string> = {
  Shoulder: 'Clavicle',
  UpperArm: 'UpperArm',
  LowerArm: 'Forearm',
  Hand: 'Hand',
  UpperLeg: 'Thigh',
  LowerLeg: 'Calf',
  Foot: 'Foot',
  Toes: 'Toe0',
};
const biped: HumanoidNaming = {
  root: 'Bip01',
  roles: {
    hips: 'Bip01 Pelvis',
    spine: 'Bip01 Spine',
    chest: 'Bip01 Spine1',
    upperChest: 'Bip01 Spine2',
    neck: 'Bip01 Neck',
    head: 'Bip01 Head',
    ...limbNames((limb, s) => `Bip01 ${s.L} ${bipedWords[limb]}`),
  },
  parents: { leftUpperLeg: 'spine', rightUpperLeg: 'spine', leftShoulder: 'neck', rightShoulder: 'neck' },
  extra: [
    { name: 'Bip01 HeadNub', parent: 'head', offset: [0, 0.2, 0] },
    ...onBothSides(
      (s) => `Bip01 ${s.L} Finger0`,
      (s) => `${s.side}Hand`,
      [0.03, 0, 0.03],
    ),
    ...onBothSides(
      (s) => `Bip01 ${s.L} Toe0Nub`,
      (s) => `${s.side}Toes`,
      [0, 0, 0.06],
    ),
  ],
};

// Generic names, a different style per side; no upper chest. The left hand is the wrist (a palm
// below it), and a bone named like a foot hangs off the pelvis, outside the leg.
const genericLeft: Record<Limb, string> = {
  Shoulder: 'l_clavicle',
  UpperArm: 'l_upperarm',
  LowerArm: 'l_elbow',
  Hand: 'l_wrist',
  UpperLeg: 'l_thigh',
  LowerLeg: 'l_knee',
  Foot: 'l_ankle',
  Toes: 'l_toe',
};
const generic: HumanoidNaming = {
  roles: {
    hips: 'Pelvis',
    spine: 'Spine',
    chest: 'Chest',
    neck: 'Neck',
    head: 'Head',
    ...limbNames((limb, s) => (s.side === 'left' ? genericLeft[limb] : `Right${limb}`)),
  },
  extra: [
    { name: 'l_palm', parent: 'leftHand', offset: [0.05, 0, 0] },
    { name: 'l_foot', parent: 'hips', offset: [0.1, -0.9, 0.05] },
  ],
};

async function load(
  naming: HumanoidNaming,
  edit?: (json: ReturnType<typeof unpackGlb>['json']) => void,
): Promise<LoadedRig> {
  const bytes = await skeletonGlb(humanoidJoints(naming));
  if (!edit) return loadRig(bytes, 'humanoid.glb');
  const { json, bin } = unpackGlb(bytes);
  edit(json);
  return loadRig(packGlb(json, bin), 'humanoid.glb');
}

/** The role -> bone name mapping the importer found (roles in HUMANOID_ROLES order). */
function mappedNames(rig: LoadedRig): Partial<Record<HumanoidRole, string>> {
  const bones = rig.gltf!.humanoid!.bones;
  return Object.fromEntries(
    HUMANOID_ROLES.flatMap((r) => (bones[r] === undefined ? [] : [[r, rig.spec.names[bones[r]]]])),
  );
}

/** `naming`'s roles in HUMANOID_ROLES order. */
const expectedNames = (roles: Partial<Record<HumanoidRole, string>>): Partial<Record<HumanoidRole, string>> =>
  Object.fromEntries(HUMANOID_ROLES.flatMap((r) => (roles[r] === undefined ? [] : [[r, roles[r]]])));

describe('humanoid recognition by name', () => {
  it.each([
    ['mixamo', mixamo],
    ['unreal', unreal],
    ['rigify', rigify],
    ['biped', biped],
    ['generic', generic],
  ] as const)('maps every role of a %s character to its bone', async (source, naming) => {
    const rig = await load(naming);
    expect(rig.gltf!.humanoid!.source).toBe(source);
    expect(mappedNames(rig)).toEqual(expectedNames(naming.roles));
    expect(rig.gltf!.humanoid!.missing).toEqual([]);
    expect(rig.warnings[0]).toBe(`humanoid (${source}): 14 of 14 core roles`);
  });

  it('reads Mixamo names with any prefix, or none', async () => {
    for (const prefix of ['mixamorig:', 'mixamorig1:', 'Character1_', '']) {
      const roles = Object.fromEntries(Object.entries(mixamo.roles).map(([r, n]) => [r, n.replace(M, prefix)]));
      const rig = await load({ roles });
      expect(rig.gltf!.humanoid!.source, prefix).toBe('mixamo');
      expect(mappedNames(rig), prefix).toEqual(expectedNames(roles));
    }
  });

  it('names the missing core roles of a humanoid with legs but no arms or head', async () => {
    const legsOnly = Object.fromEntries(
      Object.entries(mixamo.roles).filter(([r]) => /^(hips|spine|left.*Leg|right.*Leg|.*Foot)$/.test(r)),
    );
    const rig = await load({ roles: legsOnly });
    expect(rig.gltf!.humanoid!.missing).toEqual([
      'head',
      'leftUpperArm',
      'leftLowerArm',
      'leftHand',
      'rightUpperArm',
      'rightLowerArm',
      'rightHand',
    ]);
    expect(rig.warnings[0]).toBe(
      'humanoid (mixamo): 7 of 14 core roles; missing head, leftUpperArm, leftLowerArm, leftHand, rightUpperArm, rightLowerArm, rightHand',
    );
  });

  it('is no humanoid without the hips and both legs or both arms', async () => {
    const { rightLowerLeg: _leg, rightHand: _hand, ...oneSided } = mixamo.roles;
    const rig = await load({ roles: oneSided });
    expect(rig.gltf!.humanoid).toBeNull();
    expect(rig.warnings.some((w) => w.startsWith('humanoid'))).toBe(false);
    const { hips: _hips, ...noHips } = mixamo.roles;
    expect((await load({ roles: noHips, root: 'Armature_root' })).gltf!.humanoid).toBeNull();
  });
});

// Names that no convention reads: only a VRM extension can map them.
const anonymous: HumanoidNaming = {
  roles: Object.fromEntries(HUMANOID_ROLES.map((r, k) => [r, `joint ${k}`])),
};

/** The node index of each role's bone in `json`, by the names of `roles`. */
const roleNodes = (
  json: ReturnType<typeof unpackGlb>['json'],
  roles: Partial<Record<HumanoidRole, string>>,
): [HumanoidRole, number][] =>
  (Object.entries(roles) as [HumanoidRole, string][]).map(([r, n]) => [r, nodeIndex(json, n)]);

describe('humanoid recognition from a VRM extension', () => {
  it('maps a VRM 1.0 character by VRMC_vrm.humanoid.humanBones alone', async () => {
    const rig = await load(anonymous, (json) => {
      json.extensionsUsed = ['VRMC_vrm'];
      const humanBones = Object.fromEntries(roleNodes(json, anonymous.roles).map(([r, node]) => [r, { node }]));
      json.extensions = {
        VRMC_vrm: { specVersion: '1.0', humanoid: { humanBones: { ...humanBones, leftEye: { node: 0 } } } },
      };
    });
    expect(rig.gltf!.humanoid!.source).toBe('vrm1');
    expect(mappedNames(rig)).toEqual(expectedNames(anonymous.roles));
    expect(rig.warnings[0]).toBe('humanoid (vrm1): 14 of 14 core roles');
  });

  it('maps a VRM 0.x character by VRM.humanoid.humanBones alone', async () => {
    const rig = await load(anonymous, (json) => {
      json.extensionsUsed = ['VRM'];
      const humanBones = roleNodes(json, anonymous.roles).map(([bone, node]) => ({ bone, node }));
      json.extensions = { VRM: { humanoid: { humanBones: [...humanBones, { bone: 'leftThumbProximal', node: 1 }] } } };
    });
    expect(rig.gltf!.humanoid!.source).toBe('vrm0');
    expect(mappedNames(rig)).toEqual(expectedNames(anonymous.roles));
  });

  it('wins over names, and names a role whose node is no joint', async () => {
    const rig = await load(mixamo, (json) => {
      const humanBones = Object.fromEntries(roleNodes(json, mixamo.roles).map(([r, node]) => [r, { node }]));
      humanBones.leftHand = { node: nodeIndex(json, `${M}LeftHandIndex1`) };
      humanBones.leftToes = { node: 999 };
      json.extensions = { VRMC_vrm: { humanoid: { humanBones } } };
    });
    const names = mappedNames(rig);
    expect(rig.gltf!.humanoid!.source).toBe('vrm1');
    expect(names.leftHand).toBe(`${M}LeftHandIndex1`);
    expect(names.leftToes).toBeUndefined();
    expect(rig.warnings).toContain('the VRMC_vrm extension maps leftToes (node 999) to no joint of a skin; left out');
  });

  it('falls back to names when the extension cannot be read', async () => {
    const rig = await load(mixamo, (json) => {
      json.extensions = { VRMC_vrm: { humanoid: { humanBones: [] } } };
    });
    expect(rig.gltf!.humanoid!.source).toBe('mixamo');
    expect(rig.warnings).toContain(
      "the VRMC_vrm extension's humanoid.humanBones is not an object: bones recognised by name instead",
    );
  });
});

describe('humanoid recognition: the tree decides between look-alikes', () => {
  /** The role -> name map humanoidByName makes of `bones` (name, parent name), listed parents first. */
  function byName(bones: [string, string?][]): Partial<Record<HumanoidRole, string>> {
    const names = bones.map(([n]) => n);
    const { bones: roles } = humanoidByName(
      names,
      bones.map(([, p]) => (p === undefined ? -1 : names.indexOf(p))),
    );
    return Object.fromEntries(Object.entries(roles).map(([r, b]) => [r, names[b]]));
  }
  const leg = (s: string, top: string): [string, string?][] => [
    [`${s}_thigh`, top],
    [`${s}_knee`, `${s}_thigh`],
    [`${s}_ankle`, `${s}_knee`],
  ];

  it('takes as the hips a bone with the legs below it', () => {
    const roles = byName([['Root'], ['Hip', 'Root'], ['Pelvis', 'Root'], ...leg('l', 'Pelvis'), ...leg('r', 'Pelvis')]);
    expect(roles.hips).toBe('Pelvis');
    expect(roles.leftFoot).toBe('l_ankle');
  });

  it('sets aside words that only say "joint"', () => {
    const roles = byName([
      ['Hips_jnt'],
      ['L_UpLeg_jnt', 'Hips_jnt'],
      ['L_Knee_bind', 'L_UpLeg_jnt'],
      ['L_Ankle_joint', 'L_Knee_bind'],
    ]);
    expect(roles).toEqual({
      hips: 'Hips_jnt',
      leftUpperLeg: 'L_UpLeg_jnt',
      leftLowerLeg: 'L_Knee_bind',
      leftFoot: 'L_Ankle_joint',
    });
  });

  it('finds the spine between the hips and the neck in a rig rooted at the chest', () => {
    const roles = byName([
      ['chest'],
      ['neck', 'chest'],
      ['head', 'neck'],
      ['spine', 'chest'],
      ['hips', 'spine'],
      ...leg('l', 'hips'),
      ...leg('r', 'hips'),
    ]);
    expect(roles).toMatchObject({ hips: 'hips', spine: 'spine', chest: 'chest', neck: 'neck', head: 'head' });
    expect(roles.upperChest).toBeUndefined();
  });
});

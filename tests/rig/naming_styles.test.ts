// Humanoid recognition across naming styles of the generic convention (and Mixamo's): the side as
// a suffix or a prefix, with or without a separator, CamelCase or lower case; Palm, Wrist and
// Shoulder names; a number glued to a name (RobotExpressive's Palm2L). Names are checked against
// the tree: a look-alike outside its chain takes no role.
import { describe, expect, it } from 'vitest';

import { humanoidByName } from '../../web/src/rig/humanoid/humanoid_recognition.js';
import { readBoneName } from '../../web/src/rig/humanoid/humanoid_names.js';
import { CORE_HUMANOID_ROLES, HUMANOID_ROLES, type HumanoidRole } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { skeletonGlb, type SkeletonJoint } from '../helpers/skeleton_glb.js';
import { NAMING_STYLES, robotRig, styledHumanoid, styledRoles } from './synthetic_rigs.js';

async function load(joints: SkeletonJoint[]): Promise<LoadedRig> {
  return loadRig(await skeletonGlb(joints), 'styled.glb');
}

/** The role -> bone name map the importer found, in HUMANOID_ROLES order. */
function mappedNames(rig: LoadedRig): Partial<Record<HumanoidRole, string>> {
  const bones = rig.gltf!.humanoid!.bones;
  return Object.fromEntries(
    HUMANOID_ROLES.flatMap((r) => (bones[r] === undefined ? [] : [[r, rig.spec.names[bones[r]]]])),
  );
}

/** The role -> name map humanoidByName makes of `bones` (name, parent name), listed parents first. */
function byName(bones: [string, string?][]): Partial<Record<HumanoidRole, string>> {
  const names = bones.map(([n]) => n);
  const { bones: roles } = humanoidByName(
    names,
    bones.map(([, p]) => (p === undefined ? -1 : names.indexOf(p))),
  );
  return Object.fromEntries(Object.entries(roles).map(([r, b]) => [r, names[b]]));
}

describe('naming styles', () => {
  it.each(NAMING_STYLES.map((s) => [s]))('recognises a %s humanoid with every role in its place', async (style) => {
    const rig = await load(styledHumanoid(style));
    const roles = styledRoles(style);
    expect(rig.gltf!.humanoid!.source).toBe(style === 'mixamo' ? 'mixamo' : 'generic');
    expect(rig.gltf!.humanoid!.missing).toEqual([]);
    expect(mappedNames(rig)).toEqual(
      Object.fromEntries(HUMANOID_ROLES.flatMap((r) => (roles[r] === undefined ? [] : [[r, roles[r]]]))),
    );
    const effectors = Array.from(rig.spec.effectors, (b) => rig.spec.names[b]);
    expect(effectors).toEqual(
      ['head', 'leftHand', 'rightHand', 'leftFoot', 'rightFoot'].map((r) => roles[r as HumanoidRole]),
    );
    expect(rig.warnings[0]).toBe(`humanoid (${style === 'mixamo' ? 'mixamo' : 'generic'}): 14 of 14 core roles`);
  });

  it('reads the side and the part of each style', () => {
    for (const name of [
      'UpperLegL',
      'UpperLeg.L',
      'upperleg_l',
      'UpperLeg_L',
      'L_UpperLeg',
      'LUpperLeg',
      'upper_leg.l',
      'LeftUpperLeg',
      'Leg_Upper_L',
    ])
      expect(byName([['Hips'], [name, 'Hips'], ['LowerLegL', name], ['FootL', 'LowerLegL']]), name).toMatchObject({
        leftUpperLeg: name,
        leftLowerLeg: 'LowerLegL',
        leftFoot: 'FootL',
      });
    expect(readBoneName('LowerArmR')).toMatchObject({ side: 'right', endings: ['lowerarm', 'arm'] });
    expect(readBoneName('ShoulderL')).toMatchObject({ side: 'left', endings: ['shoulder'] });
  });

  it('reads a number glued to a name only after the names without one, and never a separated one', () => {
    expect(readBoneName('Palm2L')).toMatchObject({ side: 'left', endings: ['palm2', '2'], unnumbered: ['palm'] });
    expect(readBoneName('Hand01_R')?.unnumbered).toEqual(['hand']);
    expect(readBoneName('thigh.L.001')?.unnumbered).toBeUndefined();
    expect(readBoneName('hand_01_l')?.unnumbered).toBeUndefined();
    const arm = (hand: [string, string?][]): Partial<Record<HumanoidRole, string>> =>
      byName([['Hips'], ['ShoulderL', 'Hips'], ['UpperArmL', 'ShoulderL'], ['LowerArmL', 'UpperArmL'], ...hand]);
    expect(
      arm([
        ['Palm2L', 'LowerArmL'],
        ['Palm1L', 'LowerArmL'],
      ]).leftHand,
    ).toBe('Palm2L');
    expect(
      arm([
        ['Palm2L', 'LowerArmL'],
        ['PalmL', 'Palm2L'],
      ]).leftHand,
    ).toBe('PalmL');
  });

  it('recognises the RobotExpressive-style robot: Palm2L hands, Shoulder, UpperArm, LowerArm, UpperLeg, LowerLeg', async () => {
    const rig = await load(robotRig({ feet: 'legs' }));
    expect(mappedNames(rig)).toEqual({
      hips: 'Hips',
      spine: 'Abdomen',
      chest: 'Torso',
      neck: 'Neck',
      head: 'Head',
      leftShoulder: 'ShoulderL',
      leftUpperArm: 'UpperArmL',
      leftLowerArm: 'LowerArmL',
      leftHand: 'Palm2L',
      rightShoulder: 'ShoulderR',
      rightUpperArm: 'UpperArmR',
      rightLowerArm: 'LowerArmR',
      rightHand: 'Palm2R',
      leftUpperLeg: 'UpperLegL',
      leftLowerLeg: 'LowerLegL',
      leftFoot: 'FootL',
      rightUpperLeg: 'UpperLegR',
      rightLowerLeg: 'LowerLegR',
      rightFoot: 'FootR',
    });
  });

  it('gives no role by name alone: a part outside its chain, or on the wrong side, is passed over', () => {
    const roles = byName([
      ['Hips'],
      ['UpperLegL', 'Hips'],
      ['LowerLegL', 'UpperLegL'],
      ['FootL', 'LowerLegL'],
      ['UpperLegR', 'Hips'],
      ['LowerLegR', 'UpperLegR'],
      ['FootR', 'Hips'],
      ['L_Palm', 'LowerLegL'],
      ['HeadL', 'Hips'],
      ['UpperArmL', 'Hips'],
      ['LowerArmL', 'UpperArmL'],
    ]);
    expect(roles).toEqual({
      hips: 'Hips',
      leftUpperLeg: 'UpperLegL',
      leftLowerLeg: 'LowerLegL',
      leftFoot: 'FootL',
      rightUpperLeg: 'UpperLegR',
      rightLowerLeg: 'LowerLegR',
      leftUpperArm: 'UpperArmL',
      leftLowerArm: 'LowerArmL',
    });
    expect(CORE_HUMANOID_ROLES.filter((r) => roles[r] === undefined)).toContain('rightFoot');
  });
});

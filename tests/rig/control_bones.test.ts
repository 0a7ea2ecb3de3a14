// Control bones: IK targets and poles, and feet or hands named as a limb's end but
// hanging off the root beside the limbs (Blender IK controls, RobotExpressive's FootL), are no
// end effectors nor humanoid bones; the limb's own end takes their place, and the warnings name
// both. A real foot at the end of its leg stays the foot.
import { describe, expect, it } from 'vitest';

import { controlBones, limbChainEnd } from '../../web/src/rig/humanoid/control_bones.js';
import { effectorsByName } from '../../web/src/rig/gltf/effector_defaults.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { skeletonGlb, type SkeletonJoint } from '../helpers/skeleton_glb.js';
import { robotRig } from './synthetic_rigs.js';

async function load(joints: SkeletonJoint[]): Promise<LoadedRig> {
  return loadRig(await skeletonGlb(joints), 'robot.glb');
}
const effectorNames = (rig: LoadedRig): string[] => Array.from(rig.spec.effectors, (b) => rig.spec.names[b]);
const role = (rig: LoadedRig, r: string): string | undefined => {
  const b = (rig.gltf!.humanoid!.bones as Record<string, number | undefined>)[r];
  return b === undefined ? undefined : rig.spec.names[b];
};

/** The control bones (name: kind) of `bones` (name, parent name), listed parents first. */
function controlsOf(bones: [string, string?][]): Record<string, string> {
  const names = bones.map(([n]) => n);
  const parents = bones.map(([, p]) => (p === undefined ? -1 : names.indexOf(p)));
  return Object.fromEntries(controlBones(names, parents).map((c) => [names[c.bone], c.kind]));
}

describe('a robot whose feet are control bones off the root', () => {
  it('takes the ends of the legs as its feet, and names the control bones left out', async () => {
    const rig = await load(robotRig({ feet: 'controls' }));
    expect(rig.gltf!.humanoid!.missing).toEqual([]);
    expect(role(rig, 'leftFoot')).toBe('LowerLegL_end');
    expect(role(rig, 'rightFoot')).toBe('LowerLegR_end');
    expect(effectorNames(rig)).toEqual(['Head', 'Palm2L', 'Palm2R', 'LowerLegL_end', 'LowerLegR_end']);
    const mapped = Object.values(rig.gltf!.humanoid!.bones).map((b) => rig.spec.names[b]);
    for (const control of ['FootL', 'FootR', 'PoleTargetL', 'PoleTargetR']) expect(mapped).not.toContain(control);
    expect(rig.warnings).toContain(
      '4 control bones (FootL, FootR, PoleTargetL, PoleTargetR) off the root (IK targets, poles, or a hand or foot outside the limbs): ' +
        'not taken as default end effectors nor as humanoid bones',
    );
    expect(rig.warnings).toContain(
      'leftFoot is LowerLegL_end, the end of its limb, in place of the control bone FootL',
    );
    expect(rig.warnings).toContain(
      'rightFoot is LowerLegR_end, the end of its limb, in place of the control bone FootR',
    );
    expect(rig.warnings.some((w) => w.includes('root bone alone'))).toBe(false);
  });

  it('takes the lower legs themselves when nothing hangs below them', async () => {
    const rig = await load(robotRig({ feet: 'controls', legEnds: false }));
    expect(effectorNames(rig)).toEqual(['Head', 'Palm2L', 'Palm2R', 'LowerLegL', 'LowerLegR']);
    expect(rig.gltf!.humanoid!.missing).toEqual(['leftFoot', 'rightFoot']);
    expect(rig.warnings).toContain(
      'leftLowerLeg LowerLegL ends its limb: its tip is the end effector in place of the control bone FootL',
    );
    expect(rig.warnings).toContain(
      'no joint is flagged extras.ik.effector: end effectors are the hands, feet and head of the humanoid mapping, ' +
        'the ends of the limbs (LowerLegL, LowerLegR) in place of the control bones off the root (FootL, FootR) (Head, Palm2L, Palm2R, LowerLegL, LowerLegR)',
    );
  });

  it('takes the ends of the legs the humanoid mapping leaves out (legs off the body beside the hips, as in RobotExpressive)', async () => {
    const joints = robotRig({ feet: 'controls', legEnds: false }).map((j) =>
      j.name.startsWith('UpperLeg') ? { ...j, parent: 'Body' } : j,
    );
    const rig = await load(joints);
    expect(rig.gltf!.humanoid!.missing).toEqual([
      'leftUpperLeg',
      'leftLowerLeg',
      'leftFoot',
      'rightUpperLeg',
      'rightLowerLeg',
      'rightFoot',
    ]);
    expect(effectorNames(rig)).toEqual(['Head', 'Palm2L', 'Palm2R', 'LowerLegL', 'LowerLegR']);
    expect(rig.warnings).toContain(
      'no joint is flagged extras.ik.effector: end effectors are the hands, feet and head of the humanoid mapping, ' +
        'the ends of the limbs (LowerLegL, LowerLegR) in place of the control bones off the root (FootL, FootR) (Head, Palm2L, Palm2R, LowerLegL, LowerLegR)',
    );
  });

  it('keeps feet named FootL at the end of the legs as the feet', async () => {
    const rig = await load(robotRig({ feet: 'legs', poles: false }));
    expect(role(rig, 'leftFoot')).toBe('FootL');
    expect(role(rig, 'rightFoot')).toBe('FootR');
    expect(effectorNames(rig)).toEqual(['Head', 'Palm2L', 'Palm2R', 'FootL', 'FootR']);
    expect(rig.warnings.some((w) => w.includes('control bone'))).toBe(false);
  });

  it('takes the ends of the legs on a rig that is no humanoid, naming both bones', async () => {
    // No hips and no arms: the effectors come from names.
    const legs: SkeletonJoint[] = [
      { name: 'Bone', head: [0, 0, 0] },
      { name: 'Chassis', parent: 'Bone', head: [0, 1, 0] },
      { name: 'UpperLegL', parent: 'Chassis', head: [0.2, 1, 0] },
      { name: 'LowerLegL', parent: 'UpperLegL', head: [0.2, 0.5, 0.05] },
      { name: 'ShinTipL', parent: 'LowerLegL', head: [0.2, 0.05, 0] },
      { name: 'UpperLegR', parent: 'Chassis', head: [-0.2, 1, 0] },
      { name: 'LowerLegR', parent: 'UpperLegR', head: [-0.2, 0.5, 0.05] },
      { name: 'FootL', parent: 'Bone', head: [0.2, 0, 0] },
      { name: 'FootR', parent: 'Bone', head: [-0.2, 0, 0] },
      { name: 'KneePoleL', parent: 'Bone', head: [0.2, 0.5, 0.5] },
    ];
    const rig = await load(legs);
    expect(rig.gltf!.humanoid).toBeNull();
    expect(effectorNames(rig)).toEqual(['ShinTipL', 'LowerLegR']);
    expect(rig.warnings).toContain(
      'no joint is flagged extras.ik.effector: end effectors are the hands, feet and head found by name, ' +
        'the ends of the limbs (ShinTipL, LowerLegR) in place of the control bones off the root (FootL, FootR) (ShinTipL, LowerLegR)',
    );
    expect(rig.warnings).toContain(
      '3 control bones (FootL, FootR, KneePoleL) off the root (IK targets, poles, or a hand or foot outside the limbs): not taken as default end effectors nor as humanoid bones',
    );
    expect(rig.warnings.some((w) => w.includes('root bone alone'))).toBe(false);
  });
});

describe('control bones', () => {
  it('are IK targets and poles off the root or the armature, with control words all through their subtree', () => {
    expect(
      controlsOf([
        ['root'],
        ['hips', 'root'],
        ['thigh.L', 'hips'],
        ['shin.L', 'thigh.L'],
        ['foot.L', 'shin.L'],
        ['foot_ik.L', 'root'],
        ['MCH-foot_ik.L', 'foot_ik.L'],
        ['knee_pole.L', 'root'],
        ['IK_Target'],
        ['CTRL_body', 'root'],
        ['chest', 'CTRL_body'],
      ]),
    ).toEqual({ 'foot_ik.L': 'named', 'knee_pole.L': 'named', IK_Target: 'named' });
  });

  it('are hands and feet off the root beside limbs of their side, never a foot in its leg', () => {
    const body: [string, string?][] = [
      ['Bone'],
      ['Body', 'Bone'],
      ['UpperLegL', 'Body'],
      ['LowerLegL', 'UpperLegL'],
      ['UpperArmR', 'Body'],
      ['LowerArmR', 'UpperArmR'],
    ];
    expect(
      controlsOf([
        ...body,
        ['FootL', 'Bone'],
        ['HandR', 'Bone'],
        ['FootR', 'Bone'],
        ['Foot', 'Bone'],
        ['ToeL', 'Bone'],
      ]),
    ).toEqual({ FootL: 'limbEnd', HandR: 'limbEnd' });
    expect(controlsOf([...body, ['FootL', 'LowerLegL']])).toEqual({});
    // Off the hips (a root named hips or pelvis) a foot is a body part, not a control.
    expect(controlsOf([['Hips'], ['UpperLegL', 'Hips'], ['LowerLegL', 'UpperLegL'], ['FootL', 'Hips']])).toEqual({});
    // A foot with no leg deeper in the body (a robot whose feet are its base) is no control.
    expect(controlsOf([['base'], ['torso', 'base'], ['foot_l', 'base'], ['foot_r', 'base']])).toEqual({});
  });

  it('give way to the end of the limb in effectorsByName, and the end is found by name', () => {
    const names = ['Bone', 'Body', 'UpperLegL', 'LowerLegL', 'LowerLegL_end', 'FootL', 'Head'];
    const parents = [-1, 0, 1, 2, 3, 0, 1];
    expect(effectorsByName(names, parents).map((b) => names[b])).toEqual(['LowerLegL_end', 'Head']);
    expect(limbChainEnd(names, parents, 'leg', 'left', new Set([5]))).toBe(4);
    expect(limbChainEnd(names, parents, 'leg', 'right', new Set([5]))).toBeUndefined();
  });
});

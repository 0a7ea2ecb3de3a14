// Default end effectors: a humanoid's hands, feet and head by role (flags in extras.ik still
// win); for other rigs hands named palm, wrist, gripper or claw, or the bone ending an arm; a
// warning for effectors only the root moves; repeated skin warnings as one line.
import { describe, expect, it } from 'vitest';

import { effectorsByName } from '../../web/src/rig/gltf/effector_defaults.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { nodeIndex, packGlb, unpackGlb, type Json } from '../../scripts/rig_files/glb.js';
import { humanoidJoints } from '../helpers/named_humanoid.js';
import { skeletonGlb, type SkeletonJoint, type SkeletonOptions } from '../helpers/skeleton_glb.js';
import { chainParents, treeGlb } from '../../scripts/rig_files/tree_rigs.js';

const effectorNames = (rig: LoadedRig): string[] => Array.from(rig.spec.effectors, (b) => rig.spec.names[b]);

async function load(
  joints: SkeletonJoint[],
  options?: SkeletonOptions,
  edit?: (json: Json) => void,
): Promise<LoadedRig> {
  const bytes = await skeletonGlb(joints, options);
  if (!edit) return loadRig(bytes, 'rig.glb');
  const { json, bin } = unpackGlb(bytes);
  edit(json);
  return loadRig(packGlb(json, bin), 'rig.glb');
}

// Generic names; the left foot is l_ankle, and a bone named l_foot hangs off the pelvis.
const generic = humanoidJoints({
  roles: {
    hips: 'Pelvis',
    spine: 'Spine',
    neck: 'Neck',
    head: 'Head',
    leftUpperArm: 'l_upperarm',
    leftLowerArm: 'l_elbow',
    leftHand: 'l_wrist',
    rightUpperArm: 'RightUpperArm',
    rightLowerArm: 'RightLowerArm',
    rightHand: 'RightHand',
    leftUpperLeg: 'l_thigh',
    leftLowerLeg: 'l_knee',
    leftFoot: 'l_ankle',
    rightUpperLeg: 'RightUpperLeg',
    rightLowerLeg: 'RightLowerLeg',
    rightFoot: 'RightFoot',
  },
  extra: [
    { name: 'l_palm', parent: 'leftHand', offset: [0.05, 0, 0] },
    { name: 'l_foot', parent: 'hips', offset: [0.1, -0.9, 0.05] },
  ],
});

describe('default end effectors of a humanoid', () => {
  it('are its hands, feet and head by role: a wrist-named hand, the foot at the end of the leg', async () => {
    const rig = await load(generic);
    expect(effectorNames(rig)).toEqual(['Head', 'l_wrist', 'RightHand', 'l_ankle', 'RightFoot']);
    expect(rig.warnings[1]).toBe(
      'no joint is flagged extras.ik.effector: end effectors are the hands, feet and head of the humanoid mapping (Head, l_wrist, RightHand, l_ankle, RightFoot)',
    );
  });

  it('give way to effectors flagged in extras.ik, and never take one flagged false', async () => {
    const flagged = await load(
      generic,
      {},
      (json) => (json.nodes[nodeIndex(json, 'l_palm')].extras = { ik: { effector: true } }),
    );
    expect(effectorNames(flagged)).toEqual(['l_palm']);
    expect(flagged.warnings.some((w) => w.includes('no joint is flagged'))).toBe(false);
    const unflagged = await load(
      generic,
      {},
      (json) => (json.nodes[nodeIndex(json, 'Head')].extras = { ik: { effector: false } }),
    );
    expect(effectorNames(unflagged)).toEqual(['l_wrist', 'RightHand', 'l_ankle', 'RightFoot']);
  });
});

// A robot: no humanoid names, hands named gripper_l and claw (sided by its arm), feet straight
// off the root, four skins whose inverse bind matrices do not match the pose.
const robot: SkeletonJoint[] = [
  { name: 'base', head: [0, 0.5, 0] },
  { name: 'torso', parent: 'base', head: [0, 0.9, 0] },
  { name: 'head_unit', parent: 'torso', head: [0, 1.4, 0] },
  { name: 'arm_upper_l', parent: 'torso', head: [0.2, 1.2, 0] },
  { name: 'arm_lower_l', parent: 'arm_upper_l', head: [0.5, 1.2, 0] },
  { name: 'gripper_l', parent: 'arm_lower_l', head: [0.8, 1.2, 0] },
  { name: 'gripper_l_finger_a', parent: 'gripper_l', head: [0.9, 1.2, 0.02] },
  { name: 'gripper_l_finger_b', parent: 'gripper_l', head: [0.9, 1.2, -0.02] },
  { name: 'arm_upper_r', parent: 'torso', head: [-0.2, 1.2, 0] },
  { name: 'arm_lower_r', parent: 'arm_upper_r', head: [-0.5, 1.2, 0] },
  { name: 'claw', parent: 'arm_lower_r', head: [-0.8, 1.2, 0] },
  { name: 'claw_finger', parent: 'claw', head: [-0.9, 1.2, 0] },
  { name: 'foot_l', parent: 'base', head: [0.15, 0, 0.05] },
  { name: 'foot_r', parent: 'base', head: [-0.15, 0, 0.05] },
];

describe('default end effectors of a rig that is no humanoid', () => {
  it('take grippers and claws as hands, say that the feet swing the whole body, and group the skin warnings', async () => {
    const rig = await load(robot, { skins: 4, bindPose: false });
    expect(rig.gltf!.humanoid).toBeNull();
    expect(effectorNames(rig)).toEqual(['head_unit', 'gripper_l', 'claw', 'foot_l', 'foot_r']);
    expect(rig.warnings).toEqual([
      'no joint is flagged extras.ik.effector: end effectors are the hands, feet and head found by name (head_unit, gripper_l, claw, foot_l, foot_r)',
      '2 end effectors (foot_l, foot_r): moved by the root bone alone, so dragging swings the whole body',
      'no IK extras: every angle is limited to +-180 degrees',
      "4 skins (0, 1, 2, 3): the nodes are not in the bind pose; the rig's rest pose is the nodes' pose",
    ]);
  });

  it('take a palm, or else the bone that ends an arm, as a hand', async () => {
    const arms: SkeletonJoint[] = [
      { name: 'body', head: [0, 1, 0] },
      { name: 'upperarm.L', parent: 'body', head: [0.2, 1.2, 0] },
      { name: 'forearm.L', parent: 'upperarm.L', head: [0.5, 1.2, 0] },
      { name: 'palm.L', parent: 'forearm.L', head: [0.8, 1.2, 0] },
      { name: 'upperarm.R', parent: 'body', head: [-0.2, 1.2, 0] },
      { name: 'forearm.R', parent: 'upperarm.R', head: [-0.5, 1.2, 0] },
      { name: 'tool', parent: 'forearm.R', head: [-0.8, 1.2, 0] },
      { name: 'tool_tip', parent: 'tool', head: [-0.9, 1.2, 0] },
    ];
    expect(effectorNames(await load(arms, { skins: 2 }))).toEqual(['palm.L', 'tool']);
  });

  it('prefer a named hand to the bone that ends the arm, and side an unsided hand by its arm', () => {
    expect(effectorsByName(['base', 'forearm_r', 'tool', 'wrist_r'], [-1, 0, 1, 1])).toEqual([3]);
    expect(effectorsByName(['base', 'forearm_r', 'tool', 'strut'], [-1, 0, 1, 1])).toEqual([2]);
    expect(effectorsByName(['base', 'arm_l', 'claw', 'arm_r', 'claw'], [-1, 0, 1, 0, 3])).toEqual([2, 4]);
  });

  it('name an end effector that hangs off the root, or is the root', async () => {
    expect((await loadRig(treeGlb(chainParents(2)), 'two.glb')).warnings).toContain(
      'end effector link 1: moved by the root bone alone, so dragging swings the whole body',
    );
    expect((await loadRig(treeGlb(chainParents(1)), 'one.glb')).warnings).toContain(
      'end effector link 0: moved by the root bone alone, so dragging swings the whole body',
    );
    expect(
      (await loadRig(treeGlb(chainParents(3)), 'three.glb')).warnings.some((w) => w.includes('root bone alone')),
    ).toBe(false);
  });
});

// The humanoid bone roles a skeleton is mapped onto: the VRM humanoid set (VRM 1.0 names), the
// shared vocabulary of recognition (which bone plays which role), anatomical limits and the
// default end effectors. A map gives each recognised role its bone index in the RigSpec.

/** The VRM humanoid roles the importer recognises. */
export const HUMANOID_ROLES = [
  'hips',
  'spine',
  'chest',
  'upperChest',
  'neck',
  'head',
  'leftShoulder',
  'leftUpperArm',
  'leftLowerArm',
  'leftHand',
  'rightShoulder',
  'rightUpperArm',
  'rightLowerArm',
  'rightHand',
  'leftUpperLeg',
  'leftLowerLeg',
  'leftFoot',
  'leftToes',
  'rightUpperLeg',
  'rightLowerLeg',
  'rightFoot',
  'rightToes',
] as const;
export type HumanoidRole = (typeof HUMANOID_ROLES)[number];

/** The 14 roles every recognised humanoid must map: hips, head, and both sides' limbs. */
export const CORE_HUMANOID_ROLES: readonly HumanoidRole[] = [
  'hips',
  'head',
  'leftUpperArm',
  'leftLowerArm',
  'leftHand',
  'rightUpperArm',
  'rightLowerArm',
  'rightHand',
  'leftUpperLeg',
  'leftLowerLeg',
  'leftFoot',
  'rightUpperLeg',
  'rightLowerLeg',
  'rightFoot',
];

/** Where a mapping came from: a VRM extension (authoritative) or a naming convention. */
export type HumanoidSource = 'vrm1' | 'vrm0' | 'mixamo' | 'unreal' | 'rigify' | 'biped' | 'generic';

/** A skeleton's humanoid mapping: role -> bone index (into the RigSpec's bones). */
export interface HumanoidMap {
  source: HumanoidSource;
  bones: Partial<Record<HumanoidRole, number>>;
  /** Core roles no bone was found for (empty when the map is complete). */
  missing: HumanoidRole[];
}

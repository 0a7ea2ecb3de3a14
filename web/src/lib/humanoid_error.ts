// The Error for a skeleton recognised as no humanoid: which core roles the best naming convention
// found no bone for, so that a developer knows which bones to rename (or to map in a VRM file).
import type { RigSpec } from '../ik/rig_arrays.js';
import { humanoidByName } from '../rig/humanoid/humanoid_recognition.js';
import { CORE_HUMANOID_ROLES } from '../rig/humanoid/humanoid_roles.js';

/** The Error for `spec` (bone names and parents), named in the message as `where`. */
export function notHumanoidError(spec: RigSpec, where: string): Error {
  const best = humanoidByName(spec.names, spec.parents);
  const missing = CORE_HUMANOID_ROLES.filter((role) => best.bones[role] === undefined);
  return new Error(
    `AvatarIK.attach: no humanoid recognised in ${where}: its bone names (read as ${best.source} names) give no bone for ` +
      `${missing.join(', ')}; a humanoid needs the hips and both legs or both arms, the avatar also the head, hands and feet ` +
      '(VRM, Mixamo, Unreal, Rigify, 3ds Max Biped or plain names such as "LeftUpperArm", "hand.L")',
  );
}

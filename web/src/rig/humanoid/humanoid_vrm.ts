// The humanoid mapping a VRM file states, which wins over any name: VRM 1.0's
// `extensions.VRMC_vrm.humanoid.humanBones` ({"leftUpperLeg": {"node": 12}, ...}) or VRM 0.x's
// `extensions.VRM.humanoid.humanBones` ([{"bone": "leftUpperLeg", "node": 12}, ...]). Only the
// roles of humanoid_roles.ts are read (fingers, eyes and jaw are not); every value is checked.
import { listed, shown, type JsonObject } from '../gltf/gltf_json.js';
import { HUMANOID_ROLES, type HumanoidRole } from './humanoid_roles.js';
import type { RoleBones } from './humanoid_skeleton.js';

export interface VrmHumanoid {
  source: 'vrm1' | 'vrm0';
  /** The roles mapped to a joint; undefined when the extension's humanBones cannot be read. */
  bones: RoleBones | undefined;
  /** What was wrong with the extension, for the warnings ('' when nothing). */
  problem: string;
}

const isObject = (v: unknown): v is JsonObject => typeof v === 'object' && v !== null && !Array.isArray(v);
const isRole = (v: unknown): v is HumanoidRole =>
  typeof v === 'string' && (HUMANOID_ROLES as readonly string[]).includes(v);

/**
 * The VRM humanoid of a glTF document (VRM 1.0 first, then 0.x), with the node of each role
 * turned into a bone through `boneOfNode` (-1 for a node that is no joint); undefined when the file
 * has neither extension. A role naming no joint is left out and named in `problem`.
 */
export function readVrmHumanoid(json: JsonObject, boneOfNode: Int32Array): VrmHumanoid | undefined {
  const extensions = json.extensions;
  if (!isObject(extensions)) return undefined;
  const name = Object.hasOwn(extensions, 'VRMC_vrm')
    ? 'VRMC_vrm'
    : Object.hasOwn(extensions, 'VRM')
      ? 'VRM'
      : undefined;
  if (name === undefined) return undefined;
  const source = name === 'VRMC_vrm' ? 'vrm1' : 'vrm0';
  const ext = extensions[name];
  const humanBones = isObject(ext) && isObject(ext.humanoid) ? ext.humanoid.humanBones : undefined;

  // Role -> node entries, as 1.0 ({role: {node}}) or 0.x ([{bone, node}]) states them.
  const entries: [HumanoidRole, unknown][] = [];
  if (source === 'vrm1' && isObject(humanBones)) {
    for (const role of HUMANOID_ROLES) if (Object.hasOwn(humanBones, role)) entries.push([role, humanBones[role]]);
  } else if (source === 'vrm0' && Array.isArray(humanBones)) {
    for (const entry of humanBones) if (isObject(entry) && isRole(entry.bone)) entries.push([entry.bone, entry]);
  } else {
    const expected = source === 'vrm1' ? 'an object' : 'an array';
    return { source, bones: undefined, problem: `the ${name} extension's humanoid.humanBones is not ${expected}` };
  }

  const bones: RoleBones = {};
  const unmapped: string[] = [];
  for (const [role, entry] of entries) {
    if (bones[role] !== undefined) continue; // a role listed twice (0.x): the first counts
    const node = isObject(entry) ? entry.node : undefined;
    const bone =
      typeof node === 'number' && Number.isInteger(node) && node >= 0 && node < boneOfNode.length
        ? boneOfNode[node]
        : -1;
    if (bone >= 0) bones[role] = bone;
    else unmapped.push(`${role} (node ${shown(node)})`);
  }
  const problem = unmapped.length
    ? `the ${name} extension maps ${listed(unmapped)} to no joint of a skin; left out`
    : '';
  return { source, bones, problem };
}

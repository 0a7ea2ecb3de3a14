// A VRM file's humanoid mapping carried from a GLTFLoader result into the skeleton document
// (skeleton_gltf.ts), whose nodes are numbered anew: the file's VRMC_vrm (1.0) or VRM (0.x)
// humanoid is read with the project's reader, each role's node found as a three.js object through
// GLTFLoader's parser.associations and renumbered, and written back as a VRM 1.0 extension.
import type { Object3D } from 'three';

import type { JsonObject } from '../rig/gltf/gltf_json.js';
import { readVrmHumanoid } from '../rig/humanoid/humanoid_vrm.js';
import type { GltfParserLike } from './avatar_source.js';

/**
 * The `extensions` entry of the skeleton document holding the VRM humanoid of the file `parser`
 * read, each role mapped to its node in `nodeIndex` (three.js object -> skeleton document node);
 * undefined when the file has no VRM humanoid.
 */
export function vrmExtension(parser: GltfParserLike, nodeIndex: ReadonlyMap<Object3D, number>): JsonObject | undefined {
  const json = parser.json as JsonObject;
  const fileNodes = Array.isArray(json.nodes) ? json.nodes.length : 0;
  const vrm = readVrmHumanoid(
    json,
    Int32Array.from({ length: fileNodes }, (_, i) => i),
  );
  if (!vrm?.bones) return undefined;
  const objectOfNode = new Map<number, Object3D>();
  for (const [object, ref] of parser.associations)
    if (ref?.nodes !== undefined && !objectOfNode.has(ref.nodes)) objectOfNode.set(ref.nodes, object as Object3D);
  const humanBones: JsonObject = {};
  for (const [role, node] of Object.entries(vrm.bones)) {
    const object = node === undefined ? undefined : objectOfNode.get(node);
    const renumbered = object && nodeIndex.get(object);
    if (renumbered !== undefined) humanBones[role] = { node: renumbered };
  }
  return { VRMC_vrm: { humanoid: { humanBones } } };
}

// Finds the three.js objects that carry each rig bone: from a GLTFLoader result (through
// parser.associations, which maps objects to glTF node indices) or from a plain three.js
// skeleton / object tree by node name.
import { PropertyBinding, Skeleton, type Bone, type Object3D } from 'three';
import type { GLTF } from 'three/examples/jsm/loaders/GLTFLoader.js';

import type { GltfRigInfo } from '../rig/gltf/gltf_rig.js';

function isBone(o: Object3D): o is Bone {
  return (o as Bone).isBone === true;
}

/**
 * The three.js Bone of each rig bone (index = bone index), looked up by glTF node index in
 * `gltf.parser.associations`. Throws an Error naming the first node GLTFLoader did not make.
 */
export function bonesFromGltf(gltf: Pick<GLTF, 'parser'>, info: GltfRigInfo): Bone[] {
  const byNode = new Map<number, Bone>();
  for (const [object, ref] of gltf.parser.associations) {
    // Values can be undefined (GLTFLoader's default material has no glTF reference).
    if (ref?.nodes === undefined || !('isObject3D' in object) || !isBone(object as Object3D)) continue;
    if (!byNode.has(ref.nodes)) byNode.set(ref.nodes, object as Bone);
  }
  return Array.from(info.boneNodes, (node, b) => {
    const bone = byNode.get(node);
    if (!bone)
      throw new Error(`bone ${b}: glTF node ${node} "${info.nodeNames[b]}" has no three.js Bone in the loaded scene`);
    return bone;
  });
}

/**
 * The three.js Bone of each rig bone, found by node name in `source` (a Skeleton's bones or every
 * Bone under an Object3D). Names match exactly or as three.js sanitizes them
 * (PropertyBinding.sanitizeNodeName: "mixamorig:Hips" -> "mixamorigHips"). Throws an Error for a
 * missing name or a name that two bones share.
 */
export function bonesByName(source: Skeleton | Object3D, info: GltfRigInfo): Bone[] {
  const candidates: Bone[] = [];
  if (source instanceof Skeleton) candidates.push(...source.bones);
  else source.traverse((o) => isBone(o) && candidates.push(o));
  const byName = new Map<string, Bone[]>();
  for (const bone of candidates) {
    const list = byName.get(bone.name) ?? [];
    if (!list.includes(bone)) list.push(bone);
    byName.set(bone.name, list);
  }
  return info.nodeNames.map((name, b) => {
    const list = byName.get(name) ?? byName.get(PropertyBinding.sanitizeNodeName(name)) ?? [];
    if (list.length === 0) throw new Error(`bone ${b}: no three.js Bone is named "${name}"`);
    if (list.length > 1) throw new Error(`bone ${b}: ${list.length} three.js Bones are named "${name}"`);
    return list[0];
  });
}

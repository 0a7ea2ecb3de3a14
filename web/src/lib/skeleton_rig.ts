// The rig of a loaded three.js character, built by the project's glTF importer from its skeleton
// (skeleton_gltf.ts): bones, rest frames, anatomical limits and the humanoid mapping (a VRM file's
// own when given the GLTFLoader result, else the bone names: Mixamo, Unreal, Rigify, Biped, generic).
import type { Object3D } from 'three';

import type { RigSpec } from '../ik/rig_arrays.js';
import { importGltfRig, type GltfRigInfo } from '../rig/gltf/gltf_rig.js';
import type { HumanoidMap } from '../rig/humanoid/humanoid_roles.js';
import type { AvatarSource } from './avatar_source.js';
import { notHumanoidError } from './humanoid_error.js';
import { objectLabel, skeletonDocument } from './skeleton_gltf.js';
import { vrmExtension } from './vrm_extension.js';

export interface SkeletonRig {
  /** The rig, in `space`'s local coordinates (its units). */
  spec: RigSpec;
  /** The importer's bone -> node mapping (the skeleton document's nodes) and rest matrices. */
  info: GltfRigInfo;
  humanoid: HumanoidMap;
  /** The three.js object of each rig bone. */
  objects: Object3D[];
  /** The object whose local coordinates the rig lives in: it and its parents may move afterwards. */
  space: Object3D;
}

function isObject3D(v: unknown): v is Object3D {
  return typeof v === 'object' && v !== null && (v as Object3D).isObject3D === true;
}

/**
 * The rig of `source` as it stands now (its current pose is the rest pose). Rejects with an Error
 * naming the problem: not a three.js object or GLTFLoader result, no SkinnedMesh, a skeleton the importer
 * refuses, or no humanoid recognised (naming the core roles no bone was found for).
 */
export async function skeletonRig(source: AvatarSource): Promise<SkeletonRig> {
  const root = isObject3D(source) ? source : isObject3D(source?.scene) ? source.scene : undefined;
  if (!root)
    throw new Error(
      'AvatarIK.attach: expected a GLTFLoader result, or a three.js Object3D holding a skinned character (gltf.scene, a SkinnedMesh)',
    );
  const doc = skeletonDocument(root);
  const parser = isObject3D(source) ? undefined : source.parser;
  const vrm = parser && vrmExtension(parser, new Map(doc.nodes.map((o, i) => [o, i])));
  if (vrm) doc.json.extensions = vrm;
  const where = `the skeleton under ${objectLabel(doc.space)}`;
  const { spec, gltf: info } = await importGltfRig(new TextEncoder().encode(JSON.stringify(doc.json)), where).catch(
    (e: Error) => {
      throw new Error(`AvatarIK.attach: ${e.message}`);
    },
  );
  if (!info.humanoid) throw notHumanoidError(spec, where);
  return {
    spec,
    info,
    humanoid: info.humanoid,
    objects: Array.from(info.boneNodes, (n) => doc.nodes[n]),
    space: doc.space,
  };
}

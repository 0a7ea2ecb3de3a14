// A loaded three.js character's skeleton as a glTF 2.0 document, so that the project's glTF
// importer (web/src/rig/gltf/gltf_rig.ts) builds its rig: the same bone frames, humanoid recognition,
// anatomical limits and IK extras as a file gets on the page. The nodes are the skins' joints and
// the objects between them and `space`, the lowest object holding the model and every joint; the
// document's scene space is `space`'s local coordinates, the rig's space.
import type { Object3D, Skeleton, SkinnedMesh } from 'three';

import type { JsonObject } from '../rig/gltf/gltf_json.js';

export interface SkeletonDocument {
  /** The glTF document: asset, nodes (name, matrix, children, extras.ik from userData.ik), skins (joints), one scene. */
  json: JsonObject;
  /** The three.js object of each node (index = glTF node index). */
  nodes: Object3D[];
  /** The object whose local coordinates are the document's scene space. */
  space: Object3D;
}

/** "the object "Armature"": how errors name a three.js object. */
export function objectLabel(o: Object3D): string {
  return o.name ? `the ${o.type} "${o.name}"` : `an unnamed ${o.type}`;
}

/** The skeletons of the SkinnedMeshes at or under `root`, each once. */
function skeletonsUnder(root: Object3D): Skeleton[] {
  const found = new Set<Skeleton>();
  root.traverse((o) => {
    if ((o as SkinnedMesh).isSkinnedMesh) found.add((o as SkinnedMesh).skeleton);
  });
  return [...found];
}

function isAtOrBelow(o: Object3D, ancestor: Object3D): boolean {
  for (let x: Object3D | null = o; x; x = x.parent) if (x === ancestor) return true;
  return false;
}

/**
 * The skeleton document of the skinned character `root` (a scene, a group or a SkinnedMesh) as it
 * stands now. Throws an Error when `root` holds no SkinnedMesh, or when a joint lies in another
 * scene graph than `root`.
 */
export function skeletonDocument(root: Object3D): SkeletonDocument {
  const skeletons = skeletonsUnder(root);
  if (skeletons.length === 0)
    throw new Error(
      `AvatarIK.attach: no SkinnedMesh at or under ${objectLabel(root)}: pass a skinned character (gltf.scene from GLTFLoader, or its SkinnedMesh)`,
    );
  const joints = [...new Set(skeletons.flatMap((s) => s.bones))];
  let space: Object3D | null = root;
  while (space && !joints.every((j) => isAtOrBelow(j, space!))) space = space.parent;
  if (!space) throw new Error(`AvatarIK.attach: the bones of ${objectLabel(root)} are not in its scene graph`);
  space.updateWorldMatrix(true, true);

  const index = new Map<Object3D, number>();
  const nodes: Object3D[] = [];
  for (const joint of joints)
    for (let o: Object3D = joint; o !== space && !index.has(o); o = o.parent!) index.set(o, nodes.push(o) - 1);
  const json: JsonObject = {
    asset: { version: '2.0', generator: 'ik-web-avatar' },
    nodes: nodes.map((o) => ({
      name: o.name,
      matrix: Array.from(o.matrix.elements), // column-major, as glTF
      children: o.children.filter((c) => index.has(c)).map((c) => index.get(c)!),
      ...(o.userData.ik === undefined ? {} : { extras: { ik: o.userData.ik } }),
    })),
    skins: skeletons.map((s) => ({ joints: s.bones.map((b) => index.get(b)!) })),
    scenes: [{ nodes: nodes.flatMap((o, i) => (o.parent === space ? [i] : [])) }],
  };
  return { json, nodes, space };
}

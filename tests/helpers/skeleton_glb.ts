// Bare skeletons as .glb, built in memory with glTF-Transform for the recognition and effector
// tests: one node per joint, placed by its world position (translation from the parent joint, no
// rotation), under a scene root, listed by one or more skins; no mesh and no IK extras.
import { Document, WebIO, type Node } from '@gltf-transform/core';

import { type Vec3, sub } from '../../scripts/models/vec.js';

export interface SkeletonJoint {
  name: string;
  /** Name of the parent joint; omitted for a root. */
  parent?: string;
  /** World position of the joint (scene units). */
  head: Vec3;
}

export interface SkeletonOptions {
  /** Skins listing every joint (default 1). */
  skins?: number;
  /** False: the inverse bind matrices are identities, so the nodes are not in the bind pose. */
  bindPose?: boolean;
}

/** The joints ordered parents first (any order in); throws on an unknown parent or a cycle. */
function parentsFirst(joints: readonly SkeletonJoint[]): SkeletonJoint[] {
  const out: SkeletonJoint[] = [];
  const placed = new Set<string>();
  let left = [...joints];
  while (left.length) {
    const ready = left.filter((j) => j.parent === undefined || placed.has(j.parent));
    if (!ready.length)
      throw new Error(`joints without a placed parent: ${left.map((j) => `${j.name} (${j.parent})`).join(', ')}`);
    for (const j of ready) placed.add(j.name);
    out.push(...ready);
    left = left.filter((j) => !placed.has(j.name));
  }
  return out;
}

/** The skeleton as .glb bytes. */
export async function skeletonGlb(
  joints: readonly SkeletonJoint[],
  options: SkeletonOptions = {},
): Promise<Uint8Array> {
  const doc = new Document();
  const buffer = doc.createBuffer();
  const scene = doc.createScene('Scene');
  const nodes = new Map<string, { node: Node; head: Vec3 }>();
  for (const j of parentsFirst(joints)) {
    const parent = j.parent === undefined ? undefined : nodes.get(j.parent)!;
    const node = doc.createNode(j.name).setTranslation(parent ? sub(j.head, parent.head) : j.head);
    if (parent) parent.node.addChild(node);
    else scene.addChild(node);
    nodes.set(j.name, { node, head: j.head });
  }
  const list = [...nodes.values()];
  for (let s = 0; s < (options.skins ?? 1); s++) {
    // Column-major inverse bind matrices: a translation by -head (the bind pose), or the identity.
    const ibm = new Float32Array(16 * list.length);
    list.forEach((j, k) => {
      ibm.set([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0], 16 * k);
      ibm.set(options.bindPose === false ? [0, 0, 0, 1] : [-j.head[0], -j.head[1], -j.head[2], 1], 16 * k + 12);
    });
    const skin = doc
      .createSkin(`skin ${s}`)
      .setInverseBindMatrices(doc.createAccessor().setType('MAT4').setArray(ibm).setBuffer(buffer));
    list.forEach((j) => skin.addJoint(j.node));
  }
  return new WebIO().writeBinary(doc);
}

// A fox-like quadruped for the still-body tests: a .glb built in memory with
// glTF-Transform, bones only (one skin, bind pose, no mesh). Meters, Y up, facing +Z, 0.9 high.
// Like the glTF sample Fox, its root joint sits on the floor under the body, the body bone (the
// hips) carries the tail, the hind legs and the spine, and the spine carries the neck, the head
// and the front legs; four legs of four bones each (three leg bones and a paw). The paws and the
// head are its end effectors (extras.ik "effector": true); the tail is none, so it moves only as
// the body carries it. No limits anywhere (±180). No name is a humanoid's (no hips, thigh, arm,
// hand or foot), so the importer maps no humanoid.
import { Document, WebIO, type Node } from '@gltf-transform/core';

type Vec3 = [number, number, number];

interface QuadrupedJoint {
  name: string;
  parent?: string;
  /** World position of the joint, meters. */
  head: Vec3;
  /** extras.ik: a leaf's tail (joint-local offset, meters) and whether its tip is an end effector. */
  ik?: { tail?: Vec3; effector?: boolean };
}

function leg(front: boolean, side: 'L' | 'R'): QuadrupedJoint[] {
  const x = side === 'L' ? 0.1 : -0.1;
  const p = front ? 'fore' : 'hind';
  // Front: from the chest, elbow back, wrist forward; hind: from the body, knee forward, hock back.
  const z: number[] = front ? [0.22, 0.18, 0.24, 0.26] : [-0.32, -0.2, -0.36, -0.3];
  const y = [0.55, 0.33, 0.13, 0.05];
  const parent = front ? 'chest' : 'body';
  return [
    { name: `${p}1.${side}`, parent, head: [x, y[0], z[0]] },
    { name: `${p}2.${side}`, parent: `${p}1.${side}`, head: [x, y[1], z[1]] },
    { name: `${p}3.${side}`, parent: `${p}2.${side}`, head: [x, y[2], z[2]] },
    {
      name: `${p}_paw.${side}`,
      parent: `${p}3.${side}`,
      head: [x, y[3], z[3]],
      ik: { tail: [0, -0.05, 0.06], effector: true },
    },
  ];
}

/** The quadruped's joints, parents first. */
export const QUADRUPED_JOINTS: readonly QuadrupedJoint[] = [
  { name: 'root', head: [0, 0, -0.3] },
  { name: 'body', parent: 'root', head: [0, 0.6, -0.3] },
  { name: 'spine', parent: 'body', head: [0, 0.62, -0.05] },
  { name: 'chest', parent: 'spine', head: [0, 0.63, 0.2] },
  { name: 'neck', parent: 'chest', head: [0, 0.66, 0.32] },
  { name: 'head', parent: 'neck', head: [0, 0.82, 0.45], ik: { tail: [0, -0.02, 0.16], effector: true } },
  { name: 'tail1', parent: 'body', head: [0, 0.6, -0.42] },
  { name: 'tail2', parent: 'tail1', head: [0, 0.55, -0.6] },
  { name: 'tail3', parent: 'tail2', head: [0, 0.46, -0.77] },
  { name: 'tail4', parent: 'tail3', head: [0, 0.38, -0.92], ik: { tail: [0, -0.04, -0.15] } },
  ...leg(true, 'L'),
  ...leg(true, 'R'),
  ...leg(false, 'L'),
  ...leg(false, 'R'),
];

/** Bone names the tests measure: the body (hips) and the tail's last bone (its tip is the tail tip). */
export const QUADRUPED_BODY = 'body';
export const QUADRUPED_TAIL_TIP = 'tail4';

/** The quadruped as .glb bytes. */
export async function quadrupedGlb(): Promise<Uint8Array> {
  const doc = new Document();
  const buffer = doc.createBuffer();
  const scene = doc.createScene('Scene');
  const nodes = new Map<string, { node: Node; head: Vec3 }>();
  for (const j of QUADRUPED_JOINTS) {
    const parent = j.parent === undefined ? undefined : nodes.get(j.parent)!;
    const local: Vec3 = parent
      ? [j.head[0] - parent.head[0], j.head[1] - parent.head[1], j.head[2] - parent.head[2]]
      : j.head;
    const node = doc.createNode(j.name).setTranslation(local);
    if (j.ik) node.setExtras({ ik: j.ik });
    if (parent) parent.node.addChild(node);
    else scene.addChild(node);
    nodes.set(j.name, { node, head: j.head });
  }
  const list = [...nodes.values()];
  // Column-major inverse bind matrices: a translation by -head (the bind pose).
  const ibm = new Float32Array(16 * list.length);
  list.forEach((j, k) => ibm.set([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -j.head[0], -j.head[1], -j.head[2], 1], 16 * k));
  const skin = doc
    .createSkin('quadruped')
    .setInverseBindMatrices(doc.createAccessor().setType('MAT4').setArray(ibm).setBuffer(buffer));
  list.forEach((j) => skin.addJoint(j.node));
  return new WebIO().writeBinary(doc);
}

// A Blender-style test character built in memory with glTF-Transform: a "World" node with a
// translation and rotation above a scaled "Armature", Blender bone names (hand.L), joints with
// local +Y along the bone and a roll, two meshes under the Armature whose two skins share the
// skeleton (the second lists a subset of joints in another order), and no IK extras.
import { Document, WebIO, type Node } from '@gltf-transform/core';

import { boneAxes, quaternionFromAxes } from '../models/model.js';
import { block, frustum } from '../models/shapes.js';
import { type Vec3, mirrorX } from '../models/vec.js';
import { fromTRS, invertAffine, multiply } from '#rig/mat4.js';

interface TestJoint {
  name: string;
  parent?: string;
  head: Vec3;
  tail: Vec3;
  roll: Vec3;
}

function side(s: 'L' | 'R', joints: TestJoint[]): TestJoint[] {
  const m = (p: Vec3): Vec3 => (s === 'L' ? p : mirrorX(p));
  return joints.map((j) => ({
    name: `${j.name}.${s}`,
    parent: j.parent && j.parent.endsWith('.') ? `${j.parent}${s}` : j.parent,
    head: m(j.head),
    tail: m(j.tail),
    roll: m(j.roll),
  }));
}

/** The test character's joints in armature space (units: Armature scale 0.02 makes it ~1.8 m). */
export const testJoints: TestJoint[] = [
  { name: 'hips', head: [0, 50, 0], tail: [0, 56, 0], roll: [1, 0, 0] },
  { name: 'spine', parent: 'hips', head: [0, 56, 0], tail: [0, 66, 0], roll: [1, 0, 0.3] },
  { name: 'chest', parent: 'spine', head: [0, 66, 0], tail: [0, 76, 0], roll: [1, 0, 0] },
  { name: 'neck', parent: 'chest', head: [0, 76, 0], tail: [0, 80, 1], roll: [1, 0, 0] },
  { name: 'head', parent: 'neck', head: [0, 80, 1], tail: [0, 90, 1], roll: [1, 0, 0] },
  ...side('L', [
    { name: 'shoulder', parent: 'chest', head: [2, 74, 1], tail: [9, 74, 0], roll: [0, 0, 1] },
    { name: 'upper_arm', parent: 'shoulder.', head: [9, 74, 0], tail: [22, 62, -1], roll: [0, 0.3, 1] },
    { name: 'forearm', parent: 'upper_arm.', head: [22, 62, -1], tail: [32, 52, 2], roll: [-1, 0, 0] },
    { name: 'hand', parent: 'forearm.', head: [32, 52, 2], tail: [36, 47, 3], roll: [0, 0, 1] },
  ]),
  ...side('R', [
    { name: 'shoulder', parent: 'chest', head: [2, 74, 1], tail: [9, 74, 0], roll: [0, 0, 1] },
    { name: 'upper_arm', parent: 'shoulder.', head: [9, 74, 0], tail: [22, 62, -1], roll: [0, 0.3, 1] },
    { name: 'forearm', parent: 'upper_arm.', head: [22, 62, -1], tail: [32, 52, 2], roll: [-1, 0, 0] },
    { name: 'hand', parent: 'forearm.', head: [32, 52, 2], tail: [36, 47, 3], roll: [0, 0, 1] },
  ]),
  ...side('L', [
    { name: 'thigh', parent: 'hips', head: [5, 48, 0], tail: [6, 27, 1], roll: [1, 0, 0] },
    { name: 'shin', parent: 'thigh.', head: [6, 27, 1], tail: [6, 5, -1], roll: [1, 0, 0] },
    { name: 'foot', parent: 'shin.', head: [6, 5, -1], tail: [6, 1, 7], roll: [1, 0, 0] },
    { name: 'toe', parent: 'foot.', head: [6, 1, 7], tail: [6, 1, 11], roll: [1, 0, 0] },
  ]),
  ...side('R', [
    { name: 'thigh', parent: 'hips', head: [5, 48, 0], tail: [6, 27, 1], roll: [1, 0, 0] },
    { name: 'shin', parent: 'thigh.', head: [6, 27, 1], tail: [6, 5, -1], roll: [1, 0, 0] },
    { name: 'foot', parent: 'shin.', head: [6, 5, -1], tail: [6, 1, 7], roll: [1, 0, 0] },
    { name: 'toe', parent: 'foot.', head: [6, 1, 7], tail: [6, 1, 11], roll: [1, 0, 0] },
  ]),
];

/** Names of the joints the second ("Armor") skin lists, in its order. */
export const armorJoints = ['head', 'chest', 'upper_arm.R', 'upper_arm.L', 'spine'];

export interface TestCharacterOptions {
  /** Transform of the node above the Armature. */
  world?: { translation: Vec3; rotation: [number, number, number, number] };
  /** Uniform or per-axis scale of the Armature. */
  armatureScale?: Vec3;
}

/** The test character as a glTF-Transform Document. */
export function buildTestCharacter(options: TestCharacterOptions = {}): Document {
  const doc = new Document();
  const buffer = doc.createBuffer();
  const s15 = Math.sin(Math.PI / 12),
    c15 = Math.cos(Math.PI / 12);
  const w = options.world ?? { translation: [0.5, 0.2, -1], rotation: [0, s15, 0, c15] };
  const world = doc.createNode('World').setTranslation(w.translation).setRotation(w.rotation);
  const s10 = Math.sin(Math.PI / 36),
    c10 = Math.cos(Math.PI / 36);
  const armature = doc
    .createNode('Armature')
    .setScale(options.armatureScale ?? [0.02, 0.02, 0.02])
    .setRotation([0, 0, s10, c10]);
  world.addChild(armature);

  const nodes = new Map<string, { node: Node; frame: Float64Array }>();
  for (const j of testJoints) {
    const axes = boneAxes(j.head, j.tail, j.roll);
    const frame = fromTRS(j.head, quaternionFromAxes(...axes), [1, 1, 1]); // armature space
    const parent = j.parent ? nodes.get(j.parent)! : undefined;
    const local = parent ? multiply(invertAffine(parent.frame)!, frame) : frame;
    const q = quaternionFromAxes(
      [local[0], local[4], local[8]],
      [local[1], local[5], local[9]],
      [local[2], local[6], local[10]],
    );
    const node = doc.createNode(j.name).setTranslation([local[3], local[7], local[11]]).setRotation(q);
    (parent ? parent.node : armature).addChild(node);
    // The frame from the node's own numbers, so the inverse bind matrices match the nodes exactly.
    const own = fromTRS(node.getTranslation(), node.getRotation(), [1, 1, 1]);
    nodes.set(j.name, { node, frame: parent ? multiply(parent.frame, own) : own });
  }

  const skinOf = (names: string[]): ReturnType<Document['createSkin']> => {
    const ibm = new Float32Array(16 * names.length);
    names.forEach((n, k) => {
      const inv = invertAffine(nodes.get(n)!.frame)!;
      for (let r = 0; r < 4; r++) for (let c = 0; c < 4; c++) ibm[16 * k + 4 * c + r] = inv[4 * r + c];
    });
    const skin = doc
      .createSkin()
      .setInverseBindMatrices(doc.createAccessor().setType('MAT4').setArray(ibm).setBuffer(buffer));
    names.forEach((n) => skin.addJoint(nodes.get(n)!.node));
    return skin.setSkeleton(nodes.get('hips')!.node);
  };
  const allNames = testJoints.map((j) => j.name);

  const meshOf = (name: string, shapes: ReturnType<typeof frustum>[], jointNames: string[]): Node => {
    const positions: number[] = [],
      joints: number[] = [],
      weights: number[] = [],
      indices: number[] = [];
    for (const s of shapes) {
      const base = positions.length / 3;
      s.positions.forEach((p, v) => {
        positions.push(...p);
        const wv = s.weights[v];
        for (let k = 0; k < 4; k++) {
          joints.push(wv[k] ? jointNames.indexOf(wv[k][0]) : 0);
          weights.push(wv[k] ? wv[k][1] : 0);
        }
      });
      s.triangles.forEach((t) => indices.push(base + t[0], base + t[1], base + t[2]));
    }
    const prim = doc
      .createPrimitive()
      .setAttribute(
        'POSITION',
        doc.createAccessor().setType('VEC3').setArray(new Float32Array(positions)).setBuffer(buffer),
      )
      .setAttribute(
        'JOINTS_0',
        doc.createAccessor().setType('VEC4').setArray(new Uint16Array(joints)).setBuffer(buffer),
      )
      .setAttribute(
        'WEIGHTS_0',
        doc.createAccessor().setType('VEC4').setArray(new Float32Array(weights)).setBuffer(buffer),
      )
      .setIndices(doc.createAccessor().setType('SCALAR').setArray(new Uint32Array(indices)).setBuffer(buffer));
    return doc.createNode(name).setMesh(doc.createMesh(name).addPrimitive(prim));
  };

  const bodyShapes = testJoints.map((j) => {
    const start: [string, number][] = j.parent
      ? [
          [j.name, 0.6],
          [j.parent, 0.4],
        ]
      : [[j.name, 1]];
    return frustum('body', j.head, j.tail, 2.5, 2, 6, start, j.name);
  });
  const at = (n: string): TestJoint => testJoints.find((j) => j.name === n)!;
  const armorShapes = [
    block(
      'armor',
      [0, 64, 0],
      [0, 78, 0],
      16,
      10,
      [
        ['chest', 0.7],
        ['spine', 0.3],
      ],
      [1, 0, 0],
    ),
    block('armor', [0, 80, 1], [0, 91, 1], 8, 9, 'head', [1, 0, 0]),
    block('armor', at('upper_arm.L').head, at('upper_arm.L').tail, 5, 5, 'upper_arm.L'),
    block('armor', at('upper_arm.R').head, at('upper_arm.R').tail, 5, 5, 'upper_arm.R'),
  ];
  const body = meshOf('Body', bodyShapes, allNames).setSkin(skinOf(allNames));
  const armor = meshOf('Armor', armorShapes, armorJoints).setSkin(skinOf(armorJoints));
  armature.addChild(body).addChild(armor);
  doc.createScene('Scene').addChild(world);
  return doc;
}

/** The test character as .glb bytes. */
export async function testCharacterGlb(options: TestCharacterOptions = {}): Promise<Uint8Array> {
  return new WebIO().writeBinary(buildTestCharacter(options));
}

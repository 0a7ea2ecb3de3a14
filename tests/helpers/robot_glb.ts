// A stylised robot built like three.js's RobotExpressive, as .glb bytes for the browser
// test tests/browser/robot_legs.test.ts. Its skeleton as that file has it: a root bone "Bone"
// holding Body > Hips > Abdomen > Torso > Neck > Head, ShoulderL > UpperArmL > LowerArmL > Palm2L
// > Middle1L, the legs off the body beside the hips (Body > UpperLegL > LowerLegL, the lower leg
// a leaf joint), and beside the body the Blender IK controls FootL/FootR and PoleTargetL/R. Like
// the real file, the foot geometry is no skinned part of the legs: a rigid mesh node (FootMeshL,
// FootMeshR) hangs off each control bone FootL/FootR. The rest is one mesh skinned to the body,
// arms and legs. No IK extras: the importer finds effectors and limits itself. Y up, faces +Z.
import { WebIO, type Node } from '@gltf-transform/core';

import { buildDocument, type JointDef, type ModelDef, type Shape } from '../../scripts/models/model.js';
import { ball, block } from '../../scripts/models/shapes.js';
import { type Vec3, mirrorX } from '../../scripts/models/vec.js';
import { fromColumnMajor, invertAffine, transformPoint } from '../../web/src/rig/mat4.js';

const free: JointDef['limits'] = [
  [null, null, null],
  [null, null, null],
];
const X: Vec3 = [1, 0, 0],
  Z: Vec3 = [0, 0, 1];

/** Where the robot's left parts are (the right ones mirror them in x). */
export const ROBOT = {
  hip: [0.12, 0.95, 0] as Vec3,
  knee: [0.12, 0.4, 0.02] as Vec3,
  /** The control bone FootL's joint: at the ankle, on the floor's side of the shin. */
  footControl: [0.12, 0.06, 0.03] as Vec3,
  /** The foot block (world, at rest): min and max corners. */
  foot: { min: [0.05, 0, -0.07] as Vec3, max: [0.19, 0.1, 0.17] as Vec3 },
};

function joints(): JointDef[] {
  const j = (name: string, parent: string | undefined, head: Vec3, tail: Vec3, hinge: Vec3 = X): JointDef => ({
    name,
    parent,
    head,
    tail,
    hinge,
    limits: free,
  });
  const out: JointDef[] = [
    j('Bone', undefined, [0, 0, 0], [0, 0.3, 0]),
    j('Body', 'Bone', [0, 1, 0], [0, 1.05, 0]),
    j('Hips', 'Body', [0, 1.05, 0], [0, 1.15, 0]),
    j('Abdomen', 'Hips', [0, 1.15, 0], [0, 1.3, 0]),
    j('Torso', 'Abdomen', [0, 1.3, 0], [0, 1.55, 0]),
    j('Neck', 'Torso', [0, 1.55, 0], [0, 1.65, 0]),
    j('Head', 'Neck', [0, 1.65, 0], [0, 1.95, 0]),
  ];
  for (const [s, m] of [
    ['L', (v: Vec3) => v],
    ['R', mirrorX],
  ] as const) {
    out.push(
      j(`Shoulder${s}`, 'Torso', m([0.1, 1.5, 0]), m([0.25, 1.5, 0]), Z),
      j(`UpperArm${s}`, `Shoulder${s}`, m([0.25, 1.5, 0]), m([0.5, 1.5, -0.02]), [0, 1, 0]),
      j(`LowerArm${s}`, `UpperArm${s}`, m([0.5, 1.5, -0.02]), m([0.72, 1.5, 0]), [0, 1, 0]),
      j(`Palm2${s}`, `LowerArm${s}`, m([0.72, 1.5, 0]), m([0.8, 1.5, 0]), [0, 1, 0]),
      j(`Middle1${s}`, `Palm2${s}`, m([0.8, 1.5, 0]), m([0.86, 1.5, 0]), [0, 1, 0]),
      j(`UpperLeg${s}`, 'Body', m(ROBOT.hip), m(ROBOT.knee)),
      // A leaf, as in the real file: the importer puts its tip half its parent's length along it.
      j(`LowerLeg${s}`, `UpperLeg${s}`, m(ROBOT.knee), m([0.12, 0.1, 0])),
    );
  }
  for (const [s, m] of [
    ['L', (v: Vec3) => v],
    ['R', mirrorX],
  ] as const)
    out.push(
      j(`Foot${s}`, 'Bone', m(ROBOT.footControl), m([0.12, 0.06, 0.2])),
      j(`PoleTarget${s}`, 'Bone', m([0.12, 0.45, 0.6]), m([0.12, 0.55, 0.6])),
    );
  return out;
}

function shapes(): Shape[] {
  const out: Shape[] = [
    block('body', [0, 0.98, 0], [0, 1.2, 0], 0.34, 0.22, 'Hips', X),
    block('body', [0, 1.2, 0], [0, 1.56, 0], 0.36, 0.24, 'Torso', X),
    block('head', [0, 1.62, 0], [0, 1.9, 0], 0.26, 0.24, 'Head', X),
    ball('eye', [0.06, 1.8, 0.12], 0.03, 'Head'),
    ball('eye', [-0.06, 1.8, 0.12], 0.03, 'Head'),
  ];
  for (const m of [(v: Vec3) => v, mirrorX]) {
    const s = m === mirrorX ? 'R' : 'L';
    out.push(
      block('joint', m([0.18, 1.5, 0]), m([0.5, 1.5, -0.02]), 0.09, 0.09, `UpperArm${s}`, [0, 1, 0]),
      block('joint', m([0.5, 1.5, -0.02]), m([0.72, 1.5, 0]), 0.08, 0.08, `LowerArm${s}`, [0, 1, 0]),
      ball('body', m([0.78, 1.5, 0]), 0.06, `Palm2${s}`),
      block('joint', m(ROBOT.hip), m(ROBOT.knee), 0.11, 0.11, `UpperLeg${s}`, X),
      ball('body', m(ROBOT.knee), 0.07, `LowerLeg${s}`),
      block('joint', m(ROBOT.knee), m([0.12, 0.1, 0.02]), 0.09, 0.09, `LowerLeg${s}`, X),
    );
  }
  return out;
}

const model: ModelDef = {
  name: 'robot_legs',
  armature: {},
  joints: joints(),
  materials: [
    { name: 'body', color: [0.85, 0.55, 0.15], metallic: 0.1, roughness: 0.5 },
    { name: 'joint', color: [0.3, 0.32, 0.36], metallic: 0.3, roughness: 0.5 },
    { name: 'head', color: [0.85, 0.55, 0.15], metallic: 0.1, roughness: 0.5 },
    { name: 'eye', color: [0.1, 0.1, 0.1], metallic: 0, roughness: 0.3 },
  ],
  shapes: shapes(),
  plain: true,
};

/** A box's 8 corners and 12 triangles (counter-clockwise seen from outside). */
function box(min: Vec3, max: Vec3): { corners: Vec3[]; indices: number[] } {
  const corners: Vec3[] = [];
  for (let k = 0; k < 8; k++) corners.push([k & 1 ? max[0] : min[0], k & 2 ? max[1] : min[1], k & 4 ? max[2] : min[2]]);
  const quads = [
    [0, 2, 3, 1],
    [4, 5, 7, 6],
    [0, 1, 5, 4],
    [2, 6, 7, 3],
    [0, 4, 6, 2],
    [1, 3, 7, 5],
  ];
  return { corners, indices: quads.flatMap(([a, b, c, d]) => [a, b, c, a, c, d]) };
}

/** The robot as .glb bytes. */
export async function robotGlb(): Promise<Uint8Array> {
  const doc = buildDocument(model);
  const buffer = doc.getRoot().listBuffers()[0];
  const material = doc
    .createMaterial('foot')
    .setBaseColorFactor([0.25, 0.55, 0.85, 1])
    .setMetallicFactor(0.2)
    .setRoughnessFactor(0.5);
  const nodes = new Map<string, Node>(
    doc
      .getRoot()
      .listNodes()
      .map((n) => [n.getName(), n]),
  );
  for (const [s, m] of [
    ['L', (v: Vec3) => v],
    ['R', mirrorX],
  ] as const) {
    const control = nodes.get(`Foot${s}`)!;
    // The block's corners in the control bone's frame: its mesh node sits at the bone, unturned.
    const toLocal = invertAffine(fromColumnMajor(control.getWorldMatrix()))!;
    const a = m(ROBOT.foot.min),
      b = m(ROBOT.foot.max);
    const { corners, indices } = box([Math.min(a[0], b[0]), a[1], a[2]], [Math.max(a[0], b[0]), b[1], b[2]]);
    const positions = new Float32Array(corners.flatMap((c) => transformPoint(toLocal, c)));
    const prim = doc
      .createPrimitive()
      .setMaterial(material)
      .setAttribute('POSITION', doc.createAccessor().setType('VEC3').setArray(positions).setBuffer(buffer))
      .setIndices(doc.createAccessor().setType('SCALAR').setArray(new Uint16Array(indices)).setBuffer(buffer));
    control.addChild(doc.createNode(`FootMesh${s}`).setMesh(doc.createMesh(`FootMesh${s}`).addPrimitive(prim)));
  }
  return new WebIO().writeBinary(doc);
}

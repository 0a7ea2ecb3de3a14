// The description of one project rig (joints with IK metadata, and simple shapes skinned to them)
// and its conversion into a glTF-Transform Document: one Armature node, joint nodes whose local +Y
// points along the bone (as Blender exports them), one skinned mesh with a primitive per material.
// Everything is computed from the description alone, so the output is byte-for-byte reproducible.
import { Document, type Material, type Node } from '@gltf-transform/core';

import { chooseChainChild } from '#rig/chain_child.js';
import { fromTRS, invertAffine, multiply, transformPoint } from '#rig/mat4.js';
import { addClips, type ClipDef, type ClipJoint, type Quat } from './clips.js';
import { type Vec3, cross, dot, normalize, scale, sub } from './vec.js';

/** XZX limits in degrees: [min, max], each 3 numbers; null = unbounded. */
export type Limits = [(number | null)[], (number | null)[]];

export interface JointDef {
  name: string;
  /** Parent joint name; omitted for the root. */
  parent?: string;
  /** Joint position (armature space). */
  head: Vec3;
  /** End of the bone (armature space): the chain child's head, or the tip of a leaf. */
  tail: Vec3;
  /** Direction the joint's local +Z should follow (orthogonalised): the hinge axis of angle a1. */
  hinge: Vec3;
  limits: Limits;
  effector?: boolean;
}

/** A piece of the mesh: positions in armature space, each vertex skinned to one or two joints. */
export interface Shape {
  material: string;
  /** Vertex positions (armature space). */
  positions: Vec3[];
  /** Per vertex: [bone name, weight] pairs (weights sum to 1). */
  weights: [string, number][][];
  /** Triangles, counter-clockwise seen from outside. */
  triangles: [number, number, number][];
}

export interface MaterialDef {
  name: string;
  color: [number, number, number];
  metallic: number;
  roughness: number;
}

export interface ModelDef {
  name: string;
  /** Transform of the Armature node above the skeleton (a scale here is kept in the joints). */
  armature: { translation?: Vec3; rotation?: [number, number, number, number]; scale?: Vec3 };
  joints: JointDef[];
  materials: MaterialDef[];
  shapes: Shape[];
  /**
   * Write no extras.ik, as a character downloaded from the web arrives: the importer then finds
   * its effectors, tails and limits from the skeleton (humanoid recognition). The joints' limits
   * and effector flags still shape the mesh and are kept for tests to compare against.
   */
  plain?: boolean;
  /** Animation clips (clips.ts), written after the skeleton. */
  clips?: ClipDef[];
}

const round = (v: number, digits: number): number => {
  const r = Number(v.toFixed(digits));
  return r === 0 ? 0 : r;
};

/** Quaternion (x, y, z, w) of the rotation whose columns are the unit vectors x, y, z. */
export function quaternionFromAxes(x: Vec3, y: Vec3, z: Vec3): [number, number, number, number] {
  const [m00, m10, m20] = x,
    [m01, m11, m21] = y,
    [m02, m12, m22] = z;
  const tr = m00 + m11 + m22;
  let q: [number, number, number, number];
  if (tr > 0) {
    const s = 0.5 / Math.sqrt(tr + 1);
    q = [(m21 - m12) * s, (m02 - m20) * s, (m10 - m01) * s, 0.25 / s];
  } else if (m00 > m11 && m00 > m22) {
    const s = 2 * Math.sqrt(1 + m00 - m11 - m22);
    q = [0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s];
  } else if (m11 > m22) {
    const s = 2 * Math.sqrt(1 + m11 - m00 - m22);
    q = [(m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s];
  } else {
    const s = 2 * Math.sqrt(1 + m22 - m00 - m11);
    q = [(m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s];
  }
  if (q[3] < 0) q = q.map((v) => -v) as [number, number, number, number];
  return q;
}

/** Orthonormal axes with +Y from head to tail and +Z along the hint (orthogonalised). */
export function boneAxes(head: Vec3, tail: Vec3, zHint: Vec3): [Vec3, Vec3, Vec3] {
  const y = normalize(sub(tail, head));
  const z = normalize(sub(zHint, scale(y, dot(zHint, y))));
  return [cross(y, z), y, z];
}

/** The joint's rest orientation: +Y along the bone, +Z along the hinge hint. */
export function jointAxes(j: JointDef): [Vec3, Vec3, Vec3] {
  return boneAxes(j.head, j.tail, j.hinge);
}

/** Builds the glTF-Transform document of a model. */
export function buildDocument(model: ModelDef): Document {
  const doc = new Document();
  doc.getRoot().getAsset().extras = { source: 'scripts/generate-models.ts (npm run models)' };
  const buffer = doc.createBuffer();
  const a = model.armature;
  const armature = doc
    .createNode('Armature')
    .setTranslation(a.translation ?? [0, 0, 0])
    .setRotation(a.rotation ?? [0, 0, 0, 1])
    .setScale(a.scale ?? [1, 1, 1]);
  const armatureWorld = fromTRS(armature.getTranslation(), armature.getRotation(), armature.getScale());

  // Joints: node TRS relative to the parent joint, rounded; world matrices from the rounded values.
  const byName = new Map<string, { def: JointDef; node: Node; world: Float64Array; index: number }>();
  model.joints.forEach((def, index) => {
    if (byName.has(def.name)) throw new Error(`${model.name}: joint ${def.name} is defined twice`);
    const parent = def.parent === undefined ? undefined : byName.get(def.parent);
    if (def.parent !== undefined && !parent)
      throw new Error(`${model.name}: ${def.name} comes before its parent ${def.parent}`);
    const [x, y, z] = jointAxes(def);
    const q = quaternionFromAxes(x, y, z);
    const armatureFrame = fromTRS(def.head, q, [1, 1, 1]);
    const parentArmature = parent
      ? fromTRS(parent.def.head, quaternionFromAxes(...jointAxes(parent.def)), [1, 1, 1])
      : undefined;
    const local = parentArmature ? multiply(invertAffine(parentArmature)!, armatureFrame) : armatureFrame;
    // Local rotation as a quaternion of the local 3x3, translation from column 3.
    const rot = quaternionFromAxes(
      [local[0], local[4], local[8]],
      [local[1], local[5], local[9]],
      [local[2], local[6], local[10]],
    );
    const node = doc
      .createNode(def.name)
      .setTranslation([round(local[3], 6), round(local[7], 6), round(local[11], 6)])
      .setRotation(rot.map((v) => round(v, 9)) as [number, number, number, number]);
    if (!model.plain) node.setExtras({ ik: ikExtras(model, def) });
    (parent ? parent.node : armature).addChild(node);
    const world = multiply(
      parent ? parent.world : armatureWorld,
      fromTRS(node.getTranslation(), node.getRotation(), [1, 1, 1]),
    );
    byName.set(def.name, { def, node, world, index });
  });

  const joints = [...byName.values()];
  if (model.clips) {
    const clipJoints = new Map<string, ClipJoint>(
      joints.map((j) => [
        j.def.name,
        { node: j.node, restLocal: j.node.getRotation() as Quat, restFrame: quaternionFromAxes(...jointAxes(j.def)) },
      ]),
    );
    addClips(doc, buffer, model.clips, clipJoints, model.joints[0].name);
  }
  const ibm = new Float32Array(16 * joints.length);
  joints.forEach((j, k) => {
    const inv = invertAffine(j.world)!;
    for (let r = 0; r < 4; r++) for (let c = 0; c < 4; c++) ibm[16 * k + 4 * c + r] = inv[4 * r + c];
  });
  const skin = doc
    .createSkin(`${model.name}-skin`)
    .setSkeleton(joints[0].node)
    .setInverseBindMatrices(doc.createAccessor('inverseBindMatrices').setType('MAT4').setArray(ibm).setBuffer(buffer));
  joints.forEach((j) => skin.addJoint(j.node));

  const materials = new Map<string, Material>();
  for (const m of model.materials)
    materials.set(
      m.name,
      doc
        .createMaterial(m.name)
        .setBaseColorFactor([...m.color, 1])
        .setMetallicFactor(m.metallic)
        .setRoughnessFactor(m.roughness),
    );
  const mesh = doc.createMesh(model.name);
  for (const m of model.materials) {
    const shapes = model.shapes.filter((s) => s.material === m.name);
    if (shapes.length === 0) continue;
    const positions: number[] = [],
      jointIds: number[] = [],
      weights: number[] = [],
      indices: number[] = [];
    for (const s of shapes) {
      const base = positions.length / 3;
      s.positions.forEach((p, v) => {
        positions.push(...transformPoint(armatureWorld, p));
        const w = s.weights[v];
        const bytes = quantizeWeights(w.map(([, x]) => x));
        for (let k = 0; k < 4; k++) {
          const bone = w[k] ? byName.get(w[k][0]) : undefined;
          if (w[k] && !bone) throw new Error(`${model.name}: a shape is skinned to unknown joint ${w[k][0]}`);
          jointIds.push(bone ? bone.index : 0);
          weights.push(bytes[k] ?? 0);
        }
      });
      for (const t of s.triangles) indices.push(base + t[0], base + t[1], base + t[2]);
    }
    const prim = doc
      .createPrimitive()
      .setMaterial(materials.get(m.name)!)
      .setAttribute(
        'POSITION',
        doc.createAccessor().setType('VEC3').setArray(new Float32Array(positions)).setBuffer(buffer),
      )
      .setAttribute(
        'JOINTS_0',
        doc.createAccessor().setType('VEC4').setArray(new Uint8Array(jointIds)).setBuffer(buffer),
      )
      .setAttribute(
        'WEIGHTS_0',
        doc.createAccessor().setType('VEC4').setArray(new Uint8Array(weights)).setNormalized(true).setBuffer(buffer),
      )
      .setIndices(doc.createAccessor().setType('SCALAR').setArray(new Uint16Array(indices)).setBuffer(buffer));
    mesh.addPrimitive(prim);
  }
  const body = doc.createNode(`${model.name}-mesh`).setMesh(mesh).setSkin(skin);
  doc.createScene(model.name).addChild(armature).addChild(body);
  return doc;
}

/**
 * The joint's extras.ik: its limits, the effector flag, and what the importer needs to find the
 * bone's tail: `length` for a leaf, `tail` when the tail is no child's head, `child` when the
 * importer's default rule (chain_child.ts) would pick another child than the one at the tail.
 */
function ikExtras(model: ModelDef, def: JointDef): Record<string, unknown> {
  const ik: Record<string, unknown> = { xzx_min: def.limits[0], xzx_max: def.limits[1] };
  if (def.effector) ik.effector = true;
  const len = Math.hypot(...sub(def.tail, def.head));
  const kids = model.joints.filter((c) => c.parent === def.name);
  const atTail = kids.find((c) => Math.hypot(...sub(c.head, def.tail)) < 1e-9 * len);
  if (kids.length === 0) ik.length = round(len, 6);
  else if (!atTail) ik.tail = [0, round(len, 6), 0];
  else {
    const descendants = (name: string): number =>
      model.joints.filter((c) => c.parent === name).reduce((n, c) => n + 1 + descendants(c.name), 0);
    const candidates = kids
      .filter((c) => Math.hypot(...sub(c.head, def.head)) > 1e-9 * len)
      .map((c, bone) => ({ bone, name: c.name, descendants: descendants(c.name) }));
    if (chooseChainChild(candidates).name !== atTail.name) ik.child = atTail.name;
  }
  return ik;
}

/** Weights (summing to 1) as bytes summing to exactly 255. */
function quantizeWeights(w: number[]): number[] {
  const bytes = w.map((x) => Math.round(x * 255));
  bytes[0] += 255 - bytes.reduce((s, x) => s + x, 0);
  return bytes;
}

// Import -> forward kinematics (WebAssembly) -> write-back into three.js, checked against
// three.js's own bone world matrices and skinning, for every project rig and for the
// Blender-style test character (scaled Armature under a moved World node, two skins).
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { Matrix4, type Bone, type Vector3 } from 'three';
import type { GLTF } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { rigSize } from '../../web/src/rig/tolerances.js';
import { bonesByName, bonesFromGltf } from '../../web/src/view/find_bones.js';
import { PoseWriter } from '../../web/src/view/pose_writer.js';
import { maxAbsDiff, randomAngles, seeded } from '../helpers/a7.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';
import { applyRowMajor, parseGlb, skinnedMeshes, skinnedVertexWorld, vertexInfluences } from '../helpers/three_gltf.js';

const modelsDir = resolve(import.meta.dirname, '../../web/public/models');
const projectModels = ['lamp', 'robot-arm', 'knight', 'hand', 'beast', 'character'];

let ik: IkCoreModule;
beforeAll(async () => {
  ik = await loadIkNode();
});

interface Case {
  loaded: LoadedRig;
  gltf: GLTF;
  rig: IkRig;
  bones: Bone[];
  writer: PoseWriter;
  size: number;
}
const cases: Case[] = [];
afterAll(() => cases.forEach((c) => (c.writer.dispose(), c.rig.dispose())));

async function setUp(bytes: Uint8Array, file: string): Promise<Case> {
  const loaded = await loadRig(bytes, file);
  const gltf = await parseGlb(bytes);
  gltf.scene.updateMatrixWorld(true);
  const bones = bonesFromGltf(gltf, loaded.gltf!);
  const rig = new IkRig(ik, loaded.spec);
  const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
  const c = { loaded, gltf, rig, bones, writer: new PoseWriter(bones, loaded.spec, loaded.gltf!), size };
  cases.push(c);
  return c;
}

/** Every vertex of every skinned mesh, in world space. */
function allVertices(gltf: GLTF): Vector3[] {
  gltf.scene.updateMatrixWorld(true);
  return skinnedMeshes(gltf.scene).flatMap((m) =>
    Array.from({ length: m.geometry.getAttribute('position').count }, (_, v) => skinnedVertexWorld(m, v)),
  );
}

function checkPose(c: Case, angles: Float64Array, what: string): void {
  const { rig, gltf, bones, writer, loaded, size } = c;
  const info = loaded.gltf!;
  const poses = rig.poses(angles);
  writer.reset();
  gltf.scene.updateMatrixWorld(true);
  const restVertices = allVertices(gltf);
  writer.write(poses);
  gltf.scene.updateMatrixWorld(true);

  // Bone world matrices: T_i * restWorld_i.
  const expected = new Matrix4(),
    T = new Matrix4(),
    W = new Matrix4();
  bones.forEach((bone, i) => {
    T.set(...(Array.from(poses.subarray(16 * i, 16 * i + 16)) as Parameters<Matrix4['set']>));
    W.set(...(Array.from(info.restWorld.subarray(16 * i, 16 * i + 16)) as Parameters<Matrix4['set']>));
    expected.multiplyMatrices(T, W);
    const scale = Math.max(1, ...W.elements.map(Math.abs));
    expect(maxAbsDiff(bone.matrixWorld.elements, expected.elements), `${what}: bone ${i} world`).toBeLessThan(
      1e-9 * scale * Math.max(1, size),
    );
  });

  // Tips: forward kinematics through WebAssembly == three.js bone tips.
  expect(maxAbsDiff(writer.tips(), rig.boneTips(angles)), `${what}: tips`).toBeLessThan(1e-6 * size);

  // Skinned vertices: three.js's skinning == the linear blend of the rig's rigid motions.
  let k = 0;
  for (const mesh of skinnedMeshes(gltf.scene)) {
    const count = mesh.geometry.getAttribute('position').count;
    for (let v = 0; v < count; v += 7, k += 7) {
      const rest = restVertices[k];
      const blended = { x: 0, y: 0, z: 0 };
      for (const [bone, w] of vertexInfluences(mesh, v, bones)) {
        const p = applyRowMajor(poses, 16 * bone, rest);
        blended.x += w * p.x;
        blended.y += w * p.y;
        blended.z += w * p.z;
      }
      const got = skinnedVertexWorld(mesh, v);
      const err = Math.hypot(got.x - blended.x, got.y - blended.y, got.z - blended.z);
      expect(err, `${what}: ${mesh.name} vertex ${v}`).toBeLessThan(1e-6 * size);
    }
    k += count - Math.ceil(count / 7) * 7; // keep k at the start of the next mesh
  }
}

async function runCase(bytes: Uint8Array, file: string): Promise<void> {
  const c = await setUp(bytes, file);
  const rand = seeded(41);
  for (let s = 0; s < 5; s++) checkPose(c, randomAngles(c.loaded.spec, rand), `${file} pose ${s}`);

  // Zero angles leave every vertex where the file put it.
  c.writer.reset();
  const before = allVertices(c.gltf);
  c.writer.write(c.rig.poses(new Float64Array(c.rig.numAngles)));
  const after = allVertices(c.gltf);
  const moved = Math.max(...before.map((p, i) => p.distanceTo(after[i])));
  expect(moved, `${file}: largest vertex move at zero angles`).toBeLessThan(1e-9 * c.size);
}

describe('pose write-back into three.js', () => {
  it.each(projectModels)('%s.glb: bones, tips and skinned vertices follow the rig', async (name) => {
    await runCase(new Uint8Array(readFileSync(resolve(modelsDir, `${name}.glb`))), `${name}.glb`);
  });

  it('the Blender-style test character (scaled Armature under a moved node, two skins) follows the rig', async () => {
    await runCase(await testCharacterGlb(), 'test-character.glb');
  });

  it('also with a non-uniform Armature scale', async () => {
    await runCase(await testCharacterGlb({ armatureScale: [0.02, 0.03, 0.015] }), 'stretched-character.glb');
  });

  it('also with a mirroring Armature scale', async () => {
    await runCase(await testCharacterGlb({ armatureScale: [-0.02, 0.02, 0.02] }), 'mirrored-character.glb');
  });

  it('finds the same bones by node name (sanitized by three.js) as through parser.associations', async () => {
    const bytes = await testCharacterGlb();
    const loaded = await loadRig(bytes, 'test-character.glb');
    const gltf = await parseGlb(bytes);
    const viaNodes = bonesFromGltf(gltf, loaded.gltf!);
    expect(bonesByName(gltf.scene, loaded.gltf!)).toEqual(viaNodes);
    const skeleton = skinnedMeshes(gltf.scene).find((m) => m.skeleton.bones.length === viaNodes.length)!.skeleton;
    expect(bonesByName(skeleton, loaded.gltf!)).toEqual(viaNodes);
    expect(viaNodes.map((b) => b.name)).toContain('handL'); // three.js drops the '.' of "hand.L"
  });

  it('restores the rest pose and the bones matrixAutoUpdate on dispose', async () => {
    const bytes = new Uint8Array(readFileSync(resolve(modelsDir, 'knight.glb')));
    const loaded = await loadRig(bytes, 'knight.glb');
    const gltf = await parseGlb(bytes);
    const bones = bonesFromGltf(gltf, loaded.gltf!);
    const rest = bones.map((b) => b.matrix.clone());
    const rig = new IkRig(ik, loaded.spec);
    const writer = new PoseWriter(bones, loaded.spec, loaded.gltf!);
    expect(bones.every((b) => !b.matrixAutoUpdate)).toBe(true);
    writer.write(rig.poses(randomAngles(loaded.spec, seeded(5))));
    writer.dispose();
    rig.dispose();
    expect(bones.every((b) => b.matrixAutoUpdate)).toBe(true);
    bones.forEach((b, i) => expect(maxAbsDiff(b.matrix.elements, rest[i].elements)).toBeLessThan(1e-12));
    expect(() => writer.write(new Float64Array(3))).toThrow('poses has 3 values, expected 304');
  });
});

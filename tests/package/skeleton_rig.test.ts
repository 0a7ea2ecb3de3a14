// The package's rig from a loaded three.js character (web/src/lib/skeleton_rig.ts): the character
// parsed by three's GLTFLoader gives the same rig as the file does to the project's importer
// (bones, rest frames, limits, humanoid), from gltf.scene, from its SkinnedMesh and under a moved
// parent; a VRM file's humanoid extension is read from the GLTFLoader result; a scene with no
// skin or no humanoid is refused by an Error that names the problem.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { Group, PropertyBinding, type Object3D, type SkinnedMesh } from 'three';
import type { GLTF } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { beforeAll, describe, expect, it } from 'vitest';

import { skeletonRig, type SkeletonRig } from '../../web/src/lib/skeleton_rig.js';
import type { LoadedRig } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { packGlb, unpackGlb } from '../../scripts/rig_files/glb.js';
import { parseGlb, skinnedMeshes } from '../helpers/three_gltf.js';

const path = resolve(import.meta.dirname, '../../web/public/models/character.glb');
const bytes = new Uint8Array(readFileSync(path));
let file: LoadedRig;
beforeAll(async () => {
  file = await loadRigFromPath(path);
});

function maxDifference(a: ArrayLike<number>, b: ArrayLike<number>): number {
  expect(a.length).toBe(b.length);
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
}

/** Checks that `rig` is the file's rig: same bones (by three.js name), rest frames, lengths, limits and humanoid. */
function expectFileRig(rig: SkeletonRig): void {
  expect(rig.spec.names).toEqual(file.spec.names.map((n) => PropertyBinding.sanitizeNodeName(n)));
  expect(rig.objects.map((o) => o.name)).toEqual(rig.spec.names);
  expect(Array.from(rig.spec.parents)).toEqual(Array.from(file.spec.parents));
  expect(maxDifference(rig.spec.rest, file.spec.rest)).toBeLessThan(1e-9);
  expect(maxDifference(rig.spec.lengths, file.spec.lengths)).toBeLessThan(1e-9);
  expect(maxDifference(rig.spec.lower, file.spec.lower)).toBeLessThan(1e-6);
  expect(maxDifference(rig.spec.upper, file.spec.upper)).toBeLessThan(1e-6);
  expect(rig.humanoid.bones).toEqual(file.gltf!.humanoid!.bones);
}

/** Names every bone of the character "bone N", so that no naming convention recognises it. */
function renameBones(root: Object3D): void {
  let n = 0;
  root.traverse((o) => {
    if ((o as { isBone?: boolean }).isBone) o.name = `bone ${n++}`;
  });
}

describe('the rig of a three.js character', () => {
  it('is the rig the importer makes of the file, from gltf.scene, from its SkinnedMesh and under a moved parent', async () => {
    const gltf = await parseGlb(bytes);
    const fromScene = await skeletonRig(gltf.scene);
    expectFileRig(fromScene);
    expect(fromScene.space).toBe(gltf.scene);
    expect(fromScene.humanoid.source).toBe('mixamo');

    const [mesh] = skinnedMeshes(gltf.scene);
    expectFileRig(await skeletonRig(mesh));

    // The rig lives in the model's own coordinates: a moved, turned, scaled parent changes nothing.
    const parent = new Group();
    parent.position.set(3, -1, 2);
    parent.rotation.set(0.3, 1.1, -0.2);
    parent.scale.setScalar(2.5);
    parent.add(gltf.scene);
    const moved = await skeletonRig(gltf.scene);
    expectFileRig(moved);
    expect(moved.space).toBe(gltf.scene);
  });

  it('reads the humanoid from a VRM extension when given the GLTFLoader result, whatever the bone names', async () => {
    const { json, bin } = unpackGlb(bytes);
    const humanoid = file.gltf!.humanoid!;
    const humanBones = Object.fromEntries(
      Object.entries(humanoid.bones).map(([role, bone]) => [role, { node: file.gltf!.boneNodes[bone!] }]),
    );
    json.extensions = { VRMC_vrm: { specVersion: '1.0', humanoid: { humanBones } } };
    const gltf: GLTF = await parseGlb(packGlb(json, bin));
    renameBones(gltf.scene);
    const rig = await skeletonRig(gltf);
    expect(rig.humanoid.source).toBe('vrm1');
    expect(rig.humanoid.bones).toEqual(humanoid.bones);
    // Without the parser (gltf.scene alone) only the names are left, and they say nothing.
    await expect(skeletonRig(gltf.scene)).rejects.toThrow(/no humanoid recognised/);
  });

  it('refuses a skeleton with no humanoid names, naming the roles no bone was found for', async () => {
    const gltf = await parseGlb(bytes);
    renameBones(gltf.scene);
    await expect(skeletonRig(gltf.scene)).rejects.toThrow(
      'AvatarIK.attach: no humanoid recognised in the skeleton under the Group "character": its bone names (read as mixamo names) give no bone for ' +
        'hips, head, leftUpperArm, leftLowerArm, leftHand, rightUpperArm, rightLowerArm, rightHand, leftUpperLeg, leftLowerLeg, leftFoot, rightUpperLeg, rightLowerLeg, rightFoot',
    );
  });

  it('refuses an object with no SkinnedMesh, and what is no three.js object', async () => {
    const gltf = await parseGlb(bytes);
    const [mesh] = skinnedMeshes(gltf.scene);
    const unskinned = new Group();
    unskinned.name = 'props';
    await expect(skeletonRig(unskinned)).rejects.toThrow(
      'AvatarIK.attach: no SkinnedMesh at or under the Group "props"',
    );
    await expect(skeletonRig({} as SkinnedMesh)).rejects.toThrow(
      'AvatarIK.attach: expected a GLTFLoader result, or a three.js Object3D',
    );
    // A SkinnedMesh whose bones were taken out of its scene graph.
    mesh.skeleton.bones[0].removeFromParent();
    await expect(skeletonRig(mesh)).rejects.toThrow(
      /the bones of the SkinnedMesh "character_1" are not in its scene graph/,
    );
  });
});

// Pose export (web/src/view/pose_glb.ts): the original file with the bones' nodes posed, as one
// .glb. Checked by re-importing it (its rest pose is the posed rig), by three.js (bone world
// positions and skinned vertices follow the pose), and by the Khronos glTF validator.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { WebIO } from '@gltf-transform/core';
import { validateBytes } from 'gltf-validator';
import { Vector3 } from 'three';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { rigSize } from '../../web/src/rig/tolerances.js';
import { bonesFromGltf } from '../../web/src/view/find_bones.js';
import { decomposeLocal, posedGlb } from '../../web/src/view/pose_glb.js';
import { maxAbsDiff, randomAngles, seeded } from '../helpers/a7.js';
import { packGlb, unpackGlb } from '../../scripts/rig_files/glb.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';
import { applyRowMajor, parseGlb, skinnedMeshes, skinnedVertexWorld, vertexInfluences } from '../helpers/three_gltf.js';

const modelsDir = resolve(import.meta.dirname, '../../web/public/models');
const readModel = (name: string): Uint8Array => new Uint8Array(readFileSync(resolve(modelsDir, `${name}.glb`)));

let ik: IkCoreModule;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

function makeRig(loaded: LoadedRig): IkRig {
  const rig = new IkRig(ik, loaded.spec);
  rigs.push(rig);
  return rig;
}

/** Exports `bytes` posed at `angles` and checks re-import, three.js and the validator; returns the export. */
async function checkExport(
  bytes: Uint8Array,
  file: string,
  angles: Float64Array | null,
  readSibling?: (uri: string) => Promise<Uint8Array>,
  restGlb: Uint8Array = bytes, // the same model as .glb, for three.js's rest vertices
): Promise<Uint8Array> {
  const loaded = await loadRig(bytes, file, readSibling);
  const info = loaded.gltf!;
  const rig = makeRig(loaded);
  const a = angles ?? new Float64Array(rig.numAngles);
  const zero = new Float64Array(rig.numAngles);
  const size = rigSize(rig.boneTips(zero));
  const poses = rig.poses(a);
  const out = await posedGlb(bytes, file, info, loaded.spec, poses, readSibling);

  // (a) Re-imported, the exported file opens posed as the rig was (its start pose; its rest is
  // the bind pose, the model's own).
  const again = await loadRig(out, 'posed.glb');
  expect(again.spec.names).toEqual(loaded.spec.names);
  expect(Array.from(again.spec.parents)).toEqual(Array.from(loaded.spec.parents));
  const rig2 = makeRig(again);
  expect(
    maxAbsDiff(rig2.boneTips(again.gltf!.startAngles ?? zero), rig.boneTips(a)),
    `${file}: re-imported tips`,
  ).toBeLessThan(1e-6 * size);

  // (b) three.js: joint world positions and skinned vertices follow the pose.
  const gltf = await parseGlb(out);
  gltf.scene.updateMatrixWorld(true);
  const bones = bonesFromGltf(gltf, again.gltf!);
  bones.forEach((bone, i) => {
    const rest = new Vector3(info.restWorld[16 * i + 3], info.restWorld[16 * i + 7], info.restWorld[16 * i + 11]);
    const want = applyRowMajor(poses, 16 * i, rest);
    const got = new Vector3().setFromMatrixPosition(bone.matrixWorld);
    expect(got.distanceTo(want), `${file}: joint ${loaded.spec.names[i]} world position`).toBeLessThan(1e-6 * size);
  });
  const original = await parseGlb(restGlb);
  original.scene.updateMatrixWorld(true);
  const restMeshes = skinnedMeshes(original.scene);
  const meshes = skinnedMeshes(gltf.scene);
  expect(meshes.length).toBeGreaterThan(0);
  expect(meshes.length).toBe(restMeshes.length);
  const restBones = bonesFromGltf(original, info);
  meshes.forEach((mesh, m) => {
    const count = mesh.geometry.getAttribute('position').count;
    expect(count).toBeGreaterThan(0);
    for (let v = 0; v < count; v += 5) {
      // Reference: the linear blend of the rig's rigid motions of the file's own skinned vertex.
      const rest = skinnedVertexWorld(restMeshes[m], v);
      const blended = new Vector3();
      for (const [bone, w] of vertexInfluences(restMeshes[m], v, restBones))
        blended.addScaledVector(applyRowMajor(poses, 16 * bone, rest), w);
      const got = skinnedVertexWorld(mesh, v);
      expect(got.distanceTo(blended), `${file}: ${mesh.name} vertex ${v}`).toBeLessThan(1e-6 * size);
    }
  });

  // (c) Valid glTF.
  const report = await validateBytes(out);
  const errors = report.issues.messages.filter((m) => m.severity === 0).map((m) => `${m.code} ${m.pointer ?? ''}`);
  expect(report.issues.numErrors, `${file}: ${errors.join(', ')}`).toBe(0);
  // No warning the original file does not have (the Blender-style character's skinned meshes sit under the Armature).
  const warned = (r: typeof report): string[] =>
    r.issues.messages
      .filter((m) => m.severity === 1)
      .map((m) => `${m.code} ${m.pointer ?? ''}`)
      .sort();
  expect(warned(report), file).toEqual(warned(await validateBytes(restGlb)));
  return out;
}

describe('posedGlb', () => {
  it.each(['knight', 'character'])(
    '%s.glb: the export re-imports as the posed rig, three.js shows the pose, the validator accepts it',
    async (name) => {
      const bytes = readModel(name);
      const loaded = await loadRig(bytes, `${name}.glb`);
      const rand = seeded(7);
      for (let s = 0; s < 3; s++) {
        const angles = randomAngles(loaded.spec, rand);
        expect(Math.max(...angles.map(Math.abs)), 'the pose moves something').toBeGreaterThan(1);
        await checkExport(bytes, `${name}.glb`, angles);
      }
    },
  );

  it.each(['knight', 'character'])(
    '%s.glb: zero angles give back every node transform bit for bit and keep everything else',
    async (name) => {
      const bytes = readModel(name);
      const out = await checkExport(bytes, `${name}.glb`, null);
      const io = new WebIO();
      const [a, b] = [await io.readBinary(bytes), await io.readBinary(out)];
      const nodesA = a.getRoot().listNodes(),
        nodesB = b.getRoot().listNodes();
      expect(nodesB.map((n) => n.getName())).toEqual(nodesA.map((n) => n.getName()));
      nodesA.forEach((n, i) => {
        expect(nodesB[i].getTranslation(), n.getName()).toEqual(n.getTranslation());
        expect(nodesB[i].getRotation(), n.getName()).toEqual(n.getRotation());
        expect(nodesB[i].getScale(), n.getName()).toEqual(n.getScale());
        expect(nodesB[i].getExtras(), n.getName()).toEqual(n.getExtras());
      });
      const count = (d: typeof a) => {
        const r = d.getRoot();
        return [
          r.listMeshes().length,
          r.listSkins().length,
          r.listMaterials().length,
          r.listAccessors().length,
          r.listScenes().length,
        ];
      };
      expect(count(b)).toEqual(count(a));
      // The meshes' vertex data is unchanged.
      a.getRoot()
        .listAccessors()
        .forEach((acc, i) =>
          expect(Array.from(b.getRoot().listAccessors()[i].getArray()!)).toEqual(Array.from(acc.getArray()!)),
        );
    },
  );

  it('knight.glb: the posed bones change and extras.ik is kept', async () => {
    const bytes = readModel('knight');
    const loaded = await loadRig(bytes, 'knight.glb');
    const rig = makeRig(loaded);
    const angles = randomAngles(loaded.spec, seeded(3));
    const out = await posedGlb(bytes, 'knight.glb', loaded.gltf!, loaded.spec, rig.poses(angles));
    const json = unpackGlb(out).json,
      orig = unpackGlb(bytes).json;
    const withIk = orig.nodes.filter((n) => (n.extras as { ik?: unknown } | undefined)?.ik !== undefined).length;
    expect(withIk).toBeGreaterThan(0);
    expect(json.nodes.filter((n) => (n.extras as { ik?: unknown } | undefined)?.ik !== undefined).length).toBe(withIk);
    const moved = loaded.gltf!.boneNodes.filter(
      (k) => JSON.stringify(json.nodes[k].rotation) !== JSON.stringify(orig.nodes[k].rotation),
    );
    expect(moved.length).toBeGreaterThan(0);
  });

  it('the Blender-style character (scaled Armature under a moved World node, two skins) exports exactly', async () => {
    const bytes = await testCharacterGlb({ armatureScale: [0.01, 0.01, 0.01] });
    const loaded = await loadRig(bytes, 'test.glb');
    await checkExport(bytes, 'test.glb', randomAngles(loaded.spec, seeded(11)));
  });

  it('joints stored as `matrix` are written as valid TRS', async () => {
    const { json, bin } = unpackGlb(readModel('knight'));
    const io = new WebIO();
    const doc = await io.readBinary(readModel('knight'));
    doc
      .getRoot()
      .listNodes()
      .forEach((n, i) => {
        const node = json.nodes[i];
        if (node.translation === undefined && node.rotation === undefined && node.scale === undefined && i % 2 === 0)
          return;
        node.matrix = n.getMatrix();
        delete node.translation;
        delete node.rotation;
        delete node.scale;
      });
    expect(json.nodes.filter((n) => n.matrix !== undefined).length).toBeGreaterThan(3);
    const bytes = packGlb(json, bin);
    const loaded = await loadRig(bytes, 'matrix.glb');
    const out = await checkExport(bytes, 'matrix.glb', randomAngles(loaded.spec, seeded(5)));
    expect(unpackGlb(out).json.nodes.some((n) => n.matrix !== undefined)).toBe(false);
  });

  it('a .gltf with a side buffer and one with a data: URI export as one .glb', async () => {
    const { json, bin } = unpackGlb(readModel('knight'));
    const side = structuredClone(json);
    (side.buffers as { uri?: string }[])[0].uri = 'knight%20data.bin';
    const text = new TextEncoder().encode(JSON.stringify(side));
    const read = async (uri: string): Promise<Uint8Array> => {
      expect(uri).toBe('knight data.bin');
      return bin;
    };
    const loaded = await loadRig(text, 'knight.gltf', read);
    const angles = randomAngles(loaded.spec, seeded(9));
    await checkExport(text, 'knight.gltf', angles, read, readModel('knight'));
    await expect(
      posedGlb(text, 'knight.gltf', loaded.gltf!, loaded.spec, makeRig(loaded).poses(angles)),
    ).rejects.toThrow(/knight%20data\.bin.*no reader/);

    // An image beside the .gltf ends up inside the .glb.
    const png = Buffer.from(
      'iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mNk+M9QDwADhgGAWjR9awAAAABJRU5ErkJggg==',
      'base64',
    );
    const withImage = {
      ...structuredClone(side),
      images: [{ uri: 'skin.png', name: 'skin' }],
      textures: [{ source: 0 }],
    };
    const readBoth = async (uri: string): Promise<Uint8Array> => (uri === 'skin.png' ? new Uint8Array(png) : read(uri));
    const imaged = await checkExport(
      new TextEncoder().encode(JSON.stringify(withImage)),
      'knight.gltf',
      angles,
      readBoth,
      readModel('knight'),
    );
    const { json: outJson, bin: outBin } = unpackGlb(imaged);
    const image = (outJson.images as { bufferView?: number; uri?: string }[])[0];
    expect(image.uri).toBeUndefined();
    const view = (outJson.bufferViews as { byteOffset?: number; byteLength: number }[])[image.bufferView!];
    expect(
      Buffer.from(outBin.subarray(view.byteOffset ?? 0, (view.byteOffset ?? 0) + view.byteLength)).equals(png),
    ).toBe(true);

    const embedded = structuredClone(json);
    (embedded.buffers as { uri?: string }[])[0].uri =
      `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}`;
    await checkExport(
      new TextEncoder().encode(JSON.stringify(embedded)),
      'knight.gltf',
      angles,
      undefined,
      readModel('knight'),
    );
  });

  it('carries a material extension over', async () => {
    const bytes = readModel('knight');
    const loaded = await loadRig(bytes, 'knight.glb');
    const poses = makeRig(loaded).poses(new Float64Array(3 * loaded.spec.parents.length));
    const { json, bin } = unpackGlb(bytes);
    json.extensionsUsed = ['KHR_materials_emissive_strength'];
    (json.materials as { extensions?: unknown }[])[0].extensions = {
      KHR_materials_emissive_strength: { emissiveStrength: 4 },
    };
    const out = unpackGlb(await posedGlb(packGlb(json, bin), 'x.glb', loaded.gltf!, loaded.spec, poses)).json;
    expect(out.extensionsUsed).toEqual(['KHR_materials_emissive_strength']);
    expect((out.materials as { extensions?: Record<string, unknown> }[])[0].extensions).toEqual({
      KHR_materials_emissive_strength: { emissiveStrength: 4 },
    });
  });

  it('refuses compressed geometry or an unknown extension, a rig of another file, and wrong pose lengths', async () => {
    const bytes = readModel('knight');
    const loaded = await loadRig(bytes, 'knight.glb');
    const poses = makeRig(loaded).poses(new Float64Array(3 * loaded.spec.parents.length));
    const { json, bin } = unpackGlb(bytes);
    for (const name of ['EXT_meshopt_compression', 'VRMC_vrm']) {
      json.extensionsUsed = [name];
      await expect(posedGlb(packGlb(json, bin), 'x.glb', loaded.gltf!, loaded.spec, poses)).rejects.toThrow(
        new RegExp(`x\\.glb.*${name}`),
      );
    }
    await expect(posedGlb(readModel('character'), 'character.glb', loaded.gltf!, loaded.spec, poses)).rejects.toThrow(
      /character\.glb.*another file/,
    );
    await expect(posedGlb(bytes, 'knight.glb', loaded.gltf!, loaded.spec, poses.subarray(16))).rejects.toThrow(
      /poses has/,
    );
    const bad = poses.slice();
    bad[5] = NaN;
    await expect(posedGlb(bytes, 'knight.glb', loaded.gltf!, loaded.spec, bad)).rejects.toThrow(/not finite/);
  });
});

describe('decomposeLocal', () => {
  const file = {
    translation: [1, 2, 3] as [number, number, number],
    rotation: [0, 0, 0, 1] as [number, number, number, number],
    scale: [2, 2, 2] as [number, number, number],
  };

  it('keeps the file values it reproduces and rebuilds a rotated matrix', () => {
    const c = Math.cos(0.3),
      s = Math.sin(0.3);
    const m = [2 * c, -2 * s, 0, 1, 2 * s, 2 * c, 0, 2, 0, 0, 2, 3, 0, 0, 0, 1];
    const trs = decomposeLocal(m, file)!;
    expect(trs.translation).toEqual([1, 2, 3]);
    expect(trs.scale).toEqual([2, 2, 2]);
    expect(trs.rotation[2]).toBeCloseTo(Math.sin(0.15), 14);
    expect(trs.rotation[3]).toBeCloseTo(Math.cos(0.15), 14);
  });

  it('keeps a mirroring (negative) scale of the file', () => {
    const m = [-2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1];
    const trs = decomposeLocal(m, { ...file, scale: [-2, 2, 2] })!;
    expect(trs.scale).toEqual([-2, 2, 2]);
    expect(trs.rotation).toEqual([0, 0, 0, 1]);
  });

  it('refuses shear (a non-uniform scale under a rotation) and a singular matrix', () => {
    const m = [1, 0.5, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
    expect(decomposeLocal(m, file)).toBeNull();
    expect(decomposeLocal([0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], file)).toBeNull();
  });
});

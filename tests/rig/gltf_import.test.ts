// The glTF importer's rules: joints -> bones, rest frames from the nodes' world transforms,
// chain child, leaf lengths, default end effectors and limits, IK extras, .gltf side buffers.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { nameTokens } from '../../web/src/rig/bone_names.js';
import { chooseChainChild } from '../../web/src/rig/chain_child.js';
import { effectorsByName, leafBones } from '../../web/src/rig/gltf/effector_defaults.js';
import { fromTRS, multiply, transformPoint } from '../../web/src/rig/mat4.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { rigSize } from '../../web/src/rig/tolerances.js';
import { maxAbsDiff, randomAngles, referenceTips, seeded } from '../helpers/a7.js';
import { packGlb, unpackGlb, nodeIndex, type Json } from '../../scripts/rig_files/glb.js';
import { armorJoints, testCharacterGlb, testJoints } from '../../scripts/rig_files/gltf_character.js';

const modelsDir = resolve(import.meta.dirname, '../../web/public/models');
let ik: IkCoreModule;
let glb: Uint8Array;
let character: LoadedRig;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
  glb = await testCharacterGlb();
  character = await loadRig(glb, 'models/test-character.glb');
});
afterAll(() => rigs.forEach((r) => r.dispose()));

function rigOf(spec: RigSpec): IkRig {
  const rig = new IkRig(ik, spec);
  rigs.push(rig);
  return rig;
}

/** World matrix of the test character's Armature (World * Armature, as built by the helper). */
function armatureWorld(): Float64Array {
  const s15 = Math.sin(Math.PI / 12),
    c15 = Math.cos(Math.PI / 12),
    s5 = Math.sin(Math.PI / 36),
    c5 = Math.cos(Math.PI / 36);
  return multiply(
    fromTRS([0.5, 0.2, -1], [0, s15, 0, c15], [1, 1, 1]),
    fromTRS([0, 0, 0], [0, 0, s5, c5], [0.02, 0.02, 0.02]),
  );
}

const boneOrigin = (spec: RigSpec, b: number): number[] => [
  spec.rest[16 * b + 3],
  spec.rest[16 * b + 7],
  spec.rest[16 * b + 11],
];
const boneTip = (spec: RigSpec, b: number): number[] =>
  [0, 1, 2].map((r) => spec.rest[16 * b + 4 * r + 3] + spec.lengths[b] * spec.rest[16 * b + 4 * r]);

describe('glTF import of a Blender-style character without IK extras', () => {
  it('makes one bone per joint of both skins, parents first, named after the nodes', () => {
    const { spec, gltf, name, format } = character;
    expect(name).toBe('test-character');
    expect(format).toBe('glb');
    expect(spec.names).toEqual(testJoints.map((j) => j.name)); // depth-first order of the node tree
    expect(Array.from(spec.parents)).toEqual(testJoints.map((j) => (j.parent ? spec.names.indexOf(j.parent) : -1)));
    expect(gltf!.skinBones.length).toBe(2);
    expect(Array.from(gltf!.skinBones[1])).toEqual(armorJoints.map((n) => spec.names.indexOf(n)));
    expect(gltf!.nodeNames[0]).toBe('hips');
  });

  it('puts each bone at its joint (world space) and points it at the chain child', () => {
    const { spec } = character;
    const A = armatureWorld();
    testJoints.forEach((j, b) => {
      expect(maxAbsDiff(boneOrigin(spec, b), transformPoint(A, j.head)), j.name).toBeLessThan(1e-12);
      // Non-leaf joints of this rig have their child at the tail (hips -> spine, chest -> neck, foot -> toe).
      const isLeaf = !testJoints.some((c) => c.parent === j.name);
      if (!isLeaf) expect(maxAbsDiff(boneTip(spec, b), transformPoint(A, j.tail)), j.name).toBeLessThan(1e-12);
    });
  });

  it('gives a leaf half its parent length along the joint local +Y', () => {
    const { spec } = character;
    for (const leaf of ['head', 'hand.L', 'toe.R']) {
      const b = spec.names.indexOf(leaf),
        p = spec.parents[b];
      expect(spec.lengths[b]).toBeCloseTo(0.5 * spec.lengths[p], 12);
      // +Y of these joints runs from head to tail in the test rig.
      const j = testJoints[b],
        A = armatureWorld();
      const d = transformPoint(A, j.tail).map((v, k) => v - boneOrigin(spec, b)[k]);
      const n = Math.hypot(...d);
      expect(
        maxAbsDiff(
          [spec.rest[16 * b], spec.rest[16 * b + 4], spec.rest[16 * b + 8]],
          d.map((v) => v / n),
        ),
      ).toBeLessThan(1e-12);
    }
  });

  it('defaults to the hands, feet and head as end effectors, anatomical limits on the humanoid and +-180 elsewhere', () => {
    const { spec, warnings } = character;
    expect(Array.from(spec.effectors, (b) => spec.names[b])).toEqual(['head', 'hand.L', 'hand.R', 'foot.L', 'foot.R']);
    const own = character.gltf!.fileLimits!;
    expect(own.lower.every((v) => v === -180) && own.upper.every((v) => v === 180)).toBe(true);
    const mapped = new Set(Object.values(character.gltf!.humanoid!.bones));
    for (let b = 0; b < spec.parents.length; b++) {
      const limited = [0, 1, 2].some((k) => spec.lower[3 * b + k] !== -180 || spec.upper[3 * b + k] !== 180);
      expect(limited, spec.names[b]).toBe(mapped.has(b));
    }
    expect(warnings.join('\n')).toMatch(/end effectors are the hands, feet and head of the humanoid mapping/);
    expect(warnings.join('\n')).toMatch(/no IK extras/);
  });

  it('has rigid rest frames, and its tips agree with the reference composition', () => {
    const { spec } = character;
    const rig = rigOf(spec);
    const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
    const rand = seeded(3);
    for (let s = 0; s < 20; s++) {
      const a = randomAngles(spec, rand);
      expect(maxAbsDiff(rig.tips(a), referenceTips(spec, a))).toBeLessThan(1e-12 * size);
    }
  });

  it('reads node matrices the same as translation/rotation/scale', async () => {
    const { json, bin } = unpackGlb(glb);
    for (const name of ['forearm.L', 'shin.R', 'Armature']) {
      const node = json.nodes[nodeIndex(json, name)] as Record<string, number[] | undefined>;
      const m = fromTRS(node.translation ?? [0, 0, 0], node.rotation ?? [0, 0, 0, 1], node.scale ?? [1, 1, 1]);
      node.matrix = [0, 1, 2, 3].flatMap((c) => [0, 1, 2, 3].map((r) => m[4 * r + c]));
      delete node.translation;
      delete node.rotation;
      delete node.scale;
    }
    const viaMatrix = await loadRig(packGlb(json, bin), 'm.glb');
    expect(maxAbsDiff(viaMatrix.spec.rest, character.spec.rest)).toBeLessThan(1e-12);
    expect(maxAbsDiff(viaMatrix.spec.lengths, character.spec.lengths)).toBeLessThan(1e-12);
  });

  it('reads .gltf with side buffers (reader or disk) and with data: URIs, to the same rig', async () => {
    const { json, bin } = unpackGlb(glb);
    const side = structuredClone(json) as Json;
    (side.buffers as Record<string, unknown>[])[0].uri = 'test%20character.bin';
    const text = new TextEncoder().encode(JSON.stringify(side));
    const viaReader = await loadRig(text, 'c.gltf', async (uri) => {
      expect(uri).toBe('test character.bin');
      return bin;
    });
    expect(viaReader.format).toBe('gltf');
    expect(viaReader.spec).toEqual(character.spec);

    const dir = mkdtempSync(join(tmpdir(), 'ik-gltf-'));
    writeFileSync(join(dir, 'c.gltf'), text);
    writeFileSync(join(dir, 'test character.bin'), bin);
    expect((await loadRigFromPath(join(dir, 'c.gltf'))).spec).toEqual(character.spec);

    const embedded = structuredClone(json) as Json;
    (embedded.buffers as Record<string, unknown>[])[0].uri =
      `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}`;
    expect((await loadRig(new TextEncoder().encode(JSON.stringify(embedded)), 'e.gltf')).spec).toEqual(character.spec);
  });

  it('keeps mirrored joints (negative scale) rigid and in place', async () => {
    const mirrored = await loadRig(await testCharacterGlb({ armatureScale: [-0.02, 0.02, 0.02] }), 'mirror.glb');
    const rig = rigOf(mirrored.spec); // the core refuses non-rigid or mirroring rest frames
    const A = multiply(armatureWorld(), fromTRS([0, 0, 0], [0, 0, 0, 1], [-1, 1, 1]));
    testJoints.forEach((j, b) =>
      expect(maxAbsDiff(boneOrigin(mirrored.spec, b), transformPoint(A, j.head))).toBeLessThan(1e-12),
    );
    expect(rig.numBones).toBe(testJoints.length);
  });
});

describe('glTF import with IK extras', () => {
  async function withExtras(edit: (json: Json) => void): Promise<LoadedRig> {
    const { json, bin } = unpackGlb(glb);
    edit(json);
    return loadRig(packGlb(json, bin), 'extras.glb');
  }
  const setIk = (json: Json, name: string, ik: unknown): void => {
    json.nodes[nodeIndex(json, name)].extras = { ik };
  };

  it('reads limits (null or 1e10 = unbounded), effectors, leaf length, tail and child', async () => {
    const r = await withExtras((json) => {
      setIk(json, 'forearm.L', { xzx_min: [0, -10, null], xzx_max: [0, 150, 1e10], effector: true });
      setIk(json, 'hand.L', { length: 10, effector: false });
      setIk(json, 'head', { tail: [0, 0, 5], effector: true });
      setIk(json, 'chest', { child: 'shoulder.L' });
    });
    const { spec } = r;
    const b = (n: string): number => spec.names.indexOf(n);
    expect(Array.from(spec.lower.subarray(3 * b('forearm.L'), 3 * b('forearm.L') + 3))).toEqual([0, -10, -Infinity]);
    expect(Array.from(spec.upper.subarray(3 * b('forearm.L'), 3 * b('forearm.L') + 3))).toEqual([0, 150, Infinity]);
    // Joints without extras keep the default in the file's own limits (the spec has anatomical ones for the humanoid).
    expect(Array.from(r.gltf!.fileLimits!.lower.subarray(0, 3))).toEqual([-180, -180, -180]);
    expect(Array.from(spec.effectors, (e) => spec.names[e])).toEqual(['head', 'forearm.L']);
    expect(spec.lengths[b('hand.L')]).toBeCloseTo(10 * 0.02, 12); // joint units times the Armature scale
    expect(spec.lengths[b('head')]).toBeCloseTo(5 * 0.02, 12);
    const A = armatureWorld();
    const shoulder = transformPoint(A, testJoints[b('shoulder.L')].head);
    expect(maxAbsDiff(boneTip(spec, b('chest')), shoulder)).toBeLessThan(1e-12);
    expect(r.warnings.some((w) => w.includes('no IK extras'))).toBe(false);
    rigOf(spec);
  });

  it('leaves out joints flagged effector: false from the default effectors', async () => {
    const r = await withExtras((json) => setIk(json, 'head', { effector: false }));
    expect(Array.from(r.spec.effectors, (e) => r.spec.names[e])).toEqual(['hand.L', 'hand.R', 'foot.L', 'foot.R']);
  });

  it('the Mixamo-named character.glb gives the same bone axes and effectors with its extras removed', async () => {
    const bytes = new Uint8Array(readFileSync(resolve(modelsDir, 'character.glb')));
    const withIk = await loadRig(bytes, 'character.glb');
    const { json, bin } = unpackGlb(bytes);
    json.nodes.forEach((n) => delete n.extras);
    const bare = await loadRig(packGlb(json, bin), 'bare.glb');
    expect(bare.spec.names).toEqual(withIk.spec.names);
    expect(Array.from(bare.spec.effectors)).toEqual(Array.from(withIk.spec.effectors));
    const leaves = new Set(leafBones(bare.spec.parents));
    for (let b = 0; b < bare.spec.names.length; b++) {
      if (leaves.has(b)) continue;
      expect(bare.spec.lengths[b], bare.spec.names[b]).toBeCloseTo(withIk.spec.lengths[b], 12);
      expect(
        maxAbsDiff(bare.spec.rest.subarray(16 * b, 16 * b + 16), withIk.spec.rest.subarray(16 * b, 16 * b + 16)),
      ).toBeLessThan(1e-12);
    }
  });
});

describe('naming rules', () => {
  it('splits names into tokens across conventions', () => {
    expect(nameTokens('mixamorig:LeftHandIndex1')).toEqual(['mixamorig', 'left', 'hand', 'index', '1']);
    expect(nameTokens('hand.L')).toEqual(['hand', 'l']);
    expect(nameTokens('DEF-upper_arm.R.001')).toEqual(['def', 'upper', 'arm', 'r', '001']);
    expect(nameTokens('Bip01 L Hand')).toEqual(['bip', '01', 'l', 'hand']);
    expect(nameTokens('HeadTop_End')).toEqual(['head', 'top', 'end']);
  });

  /** The effectors effectorsByName picks among `names` chained one below the other. */
  const pick = (names: string[]): string[] =>
    effectorsByName(
      names,
      names.map((_, i) => i - 1),
    ).map((i) => names[i]);

  it('finds hands, feet and head by name in Mixamo, Blender, Unreal and Biped rigs', () => {
    expect(
      pick([
        'mixamorig:Hips',
        'mixamorig:Head',
        'mixamorig:HeadTop_End',
        'mixamorig:LeftHand',
        'mixamorig:LeftHandIndex1',
        'mixamorig:RightHand',
        'mixamorig:LeftFoot',
        'mixamorig:LeftToeBase',
        'mixamorig:RightFoot',
      ]),
    ).toEqual([
      'mixamorig:Head',
      'mixamorig:LeftHand',
      'mixamorig:RightHand',
      'mixamorig:LeftFoot',
      'mixamorig:RightFoot',
    ]);
    expect(pick(['root', 'hand.L', 'hand_ik.L', 'hand.R', 'foot.L', 'heel.L', 'foot.R', 'head'])).toEqual([
      'hand.L',
      'hand.R',
      'foot.L',
      'foot.R',
      'head',
    ]);
    expect(pick(['pelvis', 'hand_l', 'hand_r', 'foot_l', 'foot_r', 'head', 'thumb_01_l'])).toEqual([
      'hand_l',
      'hand_r',
      'foot_l',
      'foot_r',
      'head',
    ]);
    expect(pick(['Bip01', 'Bip01 Head', 'Bip01 L Hand', 'Bip01 R Hand', 'Bip01 L Foot', 'Bip01 R Foot'])).toEqual([
      'Bip01 Head',
      'Bip01 L Hand',
      'Bip01 R Hand',
      'Bip01 L Foot',
      'Bip01 R Foot',
    ]);
    expect(pick(['base', 'arm', 'gripper'])).toEqual(['gripper']); // a gripper is a hand
    expect(pick(['base', 'link', 'tool'])).toEqual([]);
  });

  it('continues a chain through the midline, then the biggest subtree, then spine/neck/middle, then the first', () => {
    const c = (name: string, descendants: number, bone = 0) => ({ name, descendants, bone });
    expect(
      chooseChainChild([c('mixamorig:LeftUpLeg', 4), c('mixamorig:Spine', 40), c('mixamorig:RightUpLeg', 4)]).name,
    ).toBe('mixamorig:Spine');
    expect(
      chooseChainChild([c('mixamorig:LeftShoulder', 24), c('mixamorig:Neck', 2), c('mixamorig:RightShoulder', 24)])
        .name,
    ).toBe('mixamorig:Neck');
    expect(chooseChainChild([c('tail', 3), c('spine', 12)]).name).toBe('spine');
    expect(chooseChainChild([c('LeftHandThumb1', 3), c('LeftHandIndex1', 3), c('LeftHandMiddle1', 3)]).name).toBe(
      'LeftHandMiddle1',
    );
    expect(chooseChainChild([c('a', 1), c('b', 1)]).name).toBe('a');
  });
});

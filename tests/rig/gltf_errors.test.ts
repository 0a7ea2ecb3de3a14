// A malformed rig file gives one RigFormatError naming the file and the problem: never a crash,
// never a half-loaded rig.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import { loadRig, RigFormatError } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { nodeIndex, packGlb, unpackGlb, type Json } from '../../scripts/rig_files/glb.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';

let glb: Uint8Array;
beforeAll(async () => {
  glb = await testCharacterGlb();
});

/** Expects loadRig to reject with a RigFormatError whose message starts with the file name. */
async function expectError(
  bytes: Uint8Array,
  file: string,
  message: string | RegExp,
  readSibling?: (uri: string) => Promise<Uint8Array>,
): Promise<void> {
  const error = await loadRig(bytes, file, readSibling).then(
    () => undefined,
    (e: unknown) => e,
  );
  expect(error).toBeInstanceOf(RigFormatError);
  const text = (error as Error).message;
  expect(text.startsWith(`${file}: `), text).toBe(true);
  if (typeof message === 'string') expect(text).toContain(message);
  else expect(text).toMatch(message);
}

function edited(edit: (json: Json, bin: Uint8Array) => void): Uint8Array {
  const { json, bin } = unpackGlb(glb);
  edit(json, bin);
  return packGlb(json, bin);
}

const text = (s: string): Uint8Array => new TextEncoder().encode(s);

describe('errors in glTF files', () => {
  it('truncated GLB', async () => {
    await expectError(
      glb.subarray(0, glb.length - 100),
      'cut.glb',
      /^cut\.glb: truncated GLB: the header says \d+ bytes, the file has \d+$/,
    );
    await expectError(glb.subarray(0, 10), 'tiny.glb', 'truncated GLB: 10 bytes');
    const noMagic = glb.slice();
    noMagic[0] = 0;
    await expectError(noMagic, 'nomagic.glb', 'not a GLB file');
  });

  it('bad JSON', async () => {
    await expectError(text('{ "asset": { "version": "2.0" }, nodes: [] }'), 'bad.gltf', /^bad\.gltf: bad JSON: /);
    await expectError(text('{"nodes": []}'), 'noasset.gltf', 'no asset.version');
    await expectError(text('{"asset": {"version": "1.0"}}'), 'old.gltf', 'glTF version 1.0 is not supported');
    await expectError(text('{"asset": {"version": "2.0"}, "nodes": {}}'), 'shape.gltf', 'nodes is not an array');
  });

  it('no skin', async () => {
    const bytes = edited((json) => {
      delete (json as Record<string, unknown>).skins;
      json.nodes.forEach((n) => delete n.skin);
    });
    await expectError(bytes, 'static.glb', 'no skin: the file has no skinned character');
  });

  it('a joint cycle, a node with two parents, a node that is its own child', async () => {
    const cycle = edited((json) => {
      const hips = nodeIndex(json, 'hips'),
        armature = nodeIndex(json, 'Armature');
      json.nodes[armature].children = (json.nodes[armature].children as number[]).filter((c) => c !== hips);
      json.nodes[nodeIndex(json, 'toe.L')].children = [hips];
    });
    await expectError(
      cycle,
      'cycle.glb',
      /node hierarchy has a cycle: node \d+ "hips" -> node \d+ "thigh\.L" -> .* -> node \d+ "toe\.L" -> node \d+ "hips"$/,
    );
    const twoParents = edited((json) => (json.nodes[nodeIndex(json, 'toe.L')].children = [nodeIndex(json, 'hips')]));
    await expectError(
      twoParents,
      'two.glb',
      /node \d+ "hips" is a child of both node \d+ "Armature" and node \d+ "toe\.L"/,
    );
    const self = edited((json) => (json.nodes[nodeIndex(json, 'neck')].children = [nodeIndex(json, 'neck')]));
    await expectError(self, 'self.glb', /node hierarchy has a cycle: node \d+ "neck" is its own child/);
  });

  it('a missing buffer', async () => {
    const { json } = unpackGlb(glb);
    (json.buffers as Record<string, unknown>[])[0].uri = 'character.bin';
    const gltf = text(JSON.stringify(json));
    await expectError(
      gltf,
      'side.gltf',
      'buffer 0 is in the side file "character.bin", and no reader for side files was given',
    );
    await expectError(
      gltf,
      'side.gltf',
      /buffer 0: cannot read the side file "character.bin" \(missing buffer\): ENOENT/,
      async () => {
        throw new Error('ENOENT: no such file');
      },
    );
    await expectError(
      gltf,
      'short.gltf',
      /buffer 0 has 100 bytes, its byteLength says \d+ \(truncated buffer\)/,
      async () => new Uint8Array(100),
    );
    const dir = mkdtempSync(join(tmpdir(), 'ik-gltf-'));
    writeFileSync(join(dir, 'side.gltf'), gltf);
    await expect(loadRigFromPath(join(dir, 'side.gltf'))).rejects.toThrow(
      /side\.gltf: buffer 0: cannot read the side file "character\.bin" \(missing buffer\)/,
    );
    const { json: j2 } = unpackGlb(glb);
    await expectError(
      packGlb(j2),
      'nobin.glb',
      'buffer 0 has no uri and there is no GLB binary chunk for it (missing buffer)',
    );
    await expect(loadRigFromPath(join(dir, 'nothing.glb'))).rejects.toThrow(/nothing\.glb: cannot read the file/);
  });

  it('NaN or infinity in a matrix', async () => {
    const nanIbm = edited((json, bin) => {
      const accessor = (json.accessors as Record<string, number>[])[json.skins[0].inverseBindMatrices as number];
      const view = (json.bufferViews as Record<string, number>[])[accessor.bufferView];
      new DataView(bin.buffer, bin.byteOffset).setFloat32(
        (view.byteOffset ?? 0) + (accessor.byteOffset ?? 0) + 64 * 3 + 4 * 5,
        NaN,
        true,
      );
    });
    await expectError(
      nanIbm,
      'nan.glb',
      /skins\[0\]\.inverseBindMatrices \(accessor \d+\): matrix 3 has a non-finite entry \(NaN or infinite\)/,
    );
    const { json, bin } = unpackGlb(glb);
    const i = nodeIndex(json, 'spine');
    json.nodes[i].matrix = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
    delete json.nodes[i].translation;
    delete json.nodes[i].rotation;
    const infText = JSON.stringify(json).replace(
      '"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]',
      '"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,1e999,0,0,1]',
    );
    await expectError(
      packGlb(JSON.parse(infText), bin),
      'inf.glb',
      `nodes[${i}].matrix[12] is not a finite number (NaN or infinite)`,
    );
    const nullT = edited((j) => (j.nodes[nodeIndex(j, 'neck')].translation = [0, null, 0]));
    await expectError(nullT, 'null.glb', /nodes\[\d+\]\.translation\[1\] is not a finite number/);
    const zero = edited((j) => (j.nodes[nodeIndex(j, 'neck')].scale = [0, 0, 0]));
    await expectError(zero, 'zero.glb', /node \d+ "neck": world matrix is singular/);
  });

  it('bad skins and accessors', async () => {
    await expectError(
      edited((j) => (j.skins[0].joints = [0, 999])),
      'range.glb',
      /skins\[0\]\.joints\[1\] = 999 is not an index in 0\.\.\d+/,
    );
    await expectError(
      edited((j) => (j.skins[1].joints = [3, 3])),
      'twice.glb',
      'skins[1].joints[1] repeats node 3',
    );
    await expectError(
      edited((j) => ((j.accessors as Record<string, unknown>[])[j.skins[0].inverseBindMatrices as number].count = 2)),
      'count.glb',
      /skins\[0\]\.inverseBindMatrices \(accessor \d+\) has 2 matrices, the skin has 21 joints/,
    );
    const ibmView = (j: Json): Record<string, unknown> =>
      (j.bufferViews as Record<string, unknown>[])[
        (j.accessors as Record<string, number>[])[j.skins[0].inverseBindMatrices as number].bufferView
      ];
    await expectError(
      edited((j) => (ibmView(j).byteLength = 1e9)),
      'view.glb',
      /bufferViews\[\d+\] \(bytes \d+ to 10000\d+\) lies outside buffers\[0\] \(\d+ bytes\)/,
    );
  });

  it('bad IK extras', async () => {
    const ik = (value: unknown): Uint8Array =>
      edited((j) => (j.nodes[nodeIndex(j, 'forearm.L')].extras = { ik: value }));
    await expectError(ik({ limits: [0, 1] }), 'x.glb', /node \d+ "forearm\.L": extras\.ik\.limits is not a known key/);
    await expectError(
      ik({ xzx_min: [0, 90, 0], xzx_max: [0, 10, 0] }),
      'x.glb',
      'extras.ik: xzx_min[1] = 90 is above xzx_max[1] = 10',
    );
    await expectError(ik({ xzx_min: [0, 'a', 0] }), 'x.glb', 'extras.ik.xzx_min[1] is not a number (degrees) or null');
    await expectError(ik({ xzx_min: [0, 200, 0] }), 'x.glb', 'extras.ik gives xzx_min[1] = 200 above xzx_max[1] = 180');
    await expectError(ik({ length: -1 }), 'x.glb', 'extras.ik.length must be a number in 0..1000000000');
    await expectError(ik({ effector: 'yes' }), 'x.glb', 'extras.ik.effector must be true or false');
    await expectError(ik({ child: 'head' }), 'x.glb', 'extras.ik.child "head" is not one of its child joints');
    await expectError(ik({ tail: [0, 1] }), 'x.glb', 'extras.ik.tail must be 3 numbers within +-1000000000');
    await expectError(ik('fast'), 'x.glb', 'extras.ik is not a JSON object');
  });

  it('unknown formats', async () => {
    await expectError(glb, 'rig.fbx', 'unknown rig format (expected .json for A7, .glb, .gltf or .urdf)');
    await expectError(text('{}'), 'rig.json', 'no "bones" array');
  });
});

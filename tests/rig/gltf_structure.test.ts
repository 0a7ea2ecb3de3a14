// A glTF whose references or byte ranges are broken gives one RigFormatError naming the file and
// the field (gltf_references.ts, gltf_ranges.ts), never "Offset is outside the bounds of the
// DataView" or "Cannot convert undefined or null to object" from our reader or three.js's.
import { beforeAll, describe, expect, it } from 'vitest';

import { loadRig } from '../../web/src/rig/load_rig.js';
import { nodeIndex, packGlb, unpackGlb, type Json } from '../../scripts/rig_files/glb.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';
import { loadError } from './synthetic_rigs.js';

let glb: Uint8Array;
beforeAll(async () => {
  glb = await testCharacterGlb();
});

type Obj = Record<string, unknown>;

/** The test character's .glb after `edit` changed its JSON. */
function edited(
  edit: (json: Json & { accessors: Obj[]; bufferViews: Obj[]; buffers: Obj[]; meshes: Obj[] }) => void,
): Uint8Array {
  const { json, bin } = unpackGlb(glb);
  edit(json as Parameters<typeof edit>[0]);
  return packGlb(json, bin);
}

/** The inverse bind matrices' accessor of skin 0. */
const ibm = (j: Json & { accessors: Obj[] }): Obj => j.accessors[j.skins[0].inverseBindMatrices as number];

describe('glTF references and byte ranges', () => {
  it('names a bad accessor offset, count or type instead of reading outside the buffer', async () => {
    expect(
      await loadError(
        edited((j) => (ibm(j).byteOffset = -1)),
        'x.glb',
      ),
    ).toBe('x.glb: accessors[5].byteOffset = -1 is not a whole number >= 0');
    expect(
      await loadError(
        edited((j) => (ibm(j).byteOffset = 2)),
        'x.glb',
      ),
    ).toBe(
      'x.glb: accessors[5]: byte 2 of bufferViews[2] (byte 14690 of its buffer) is not a multiple of its 4-byte components',
    );
    expect(
      await loadError(
        edited((j) => (ibm(j).byteOffset = 1024)),
        'x.glb',
      ),
    ).toBe('x.glb: accessors[5]: 21 elements from byte 1024 end at byte 2368, past the 1664 bytes of bufferViews[2]');
    expect(
      await loadError(
        edited((j) => (ibm(j).count = 3.7)),
        'x.glb',
      ),
    ).toBe('x.glb: accessors[5].count = 3.7 is not a whole number >= 1');
    expect(
      await loadError(
        edited((j) => delete ibm(j).componentType),
        'x.glb',
      ),
    ).toBe('x.glb: accessors[5].componentType is missing (a glTF component type (5120, 5121, 5122, 5123, 5125, 5126))');
    expect(
      await loadError(
        edited((j) => (j.accessors[0].max = null)),
        'x.glb',
      ),
    ).toBe('x.glb: accessors[0].max must be 3 finite numbers');
  });

  it('names a buffer view outside its buffer and a GLB whose binary chunk is shorter than its buffer', async () => {
    expect(
      await loadError(
        edited((j) => (j.bufferViews[1].byteOffset = 1e6)),
        'x.glb',
      ),
    ).toBe('x.glb: bufferViews[1] (bytes 1000000 to 1005616) lies outside buffers[0] (17504 bytes)');
    const { json, bin } = unpackGlb(glb);
    expect(await loadError(packGlb(json, bin.subarray(0, 1000)), 'cut.glb')).toBe(
      'cut.glb: buffers[0].byteLength = 17504 is more than the 1000 bytes of the GLB binary chunk (truncated file?)',
    );
    expect(
      await loadError(
        edited((j) => (j.bufferViews[0].byteStride = 30)),
        'x.glb',
      ),
    ).toBe('x.glb: bufferViews[0].byteStride = 30 is not a multiple of 4');
  });

  it('names a null where an object belongs and a dangling index', async () => {
    expect(
      await loadError(
        edited((j) => ((j.meshes[0].primitives as Obj[])[0].attributes = null)),
        'x.glb',
      ),
    ).toBe('x.glb: meshes[0].primitives[0].attributes is not a JSON object');
    expect(
      await loadError(
        edited((j) => (j.nodes[0].mesh = 7)),
        'x.glb',
      ),
    ).toBe('x.glb: nodes[0].mesh = 7 is not an index in 0..1');
    expect(
      await loadError(
        edited((j) => (j.skins[0].inverseBindMatrices = null)),
        'x.glb',
      ),
    ).toBe('x.glb: skins[0].inverseBindMatrices = null is not an index in 0..9');
    expect(
      await loadError(
        edited((j) => (j.nodes[0].children = [[[1]]])),
        'x.glb',
      ),
    ).toBe('x.glb: nodes[0].children[0] = an array is not an index in 0..24');
  });

  it('refuses a name that is not a string (names reach the core and three.js as strings)', async () => {
    expect(
      await loadError(
        edited((j) => (j.nodes[nodeIndex(j, 'neck')].name = 5)),
        'x.glb',
      ),
    ).toMatch(/^x\.glb: nodes\[\d+\]\.name is not a string$/);
    expect(
      await loadError(
        edited((j) => (j.meshes[0].name = null)),
        'x.glb',
      ),
    ).toBe('x.glb: meshes[0].name is not a string');
  });

  it('refuses a child listed twice (it would be two bones)', async () => {
    expect(
      await loadError(
        edited((j) => (j.nodes[nodeIndex(j, 'neck')].children = [nodeIndex(j, 'head'), nodeIndex(j, 'head')])),
        'x.glb',
      ),
    ).toMatch(/^x\.glb: nodes\[\d+\]\.children lists node \d+ "head" twice$/);
  });

  it('gives a RigFormatError naming the file for a GLB cut anywhere', async () => {
    for (let n = 0; n < glb.length; n += 97) await loadError(glb.subarray(0, n), 'cut.glb');
  });

  it('still loads the untouched character', async () => {
    expect((await loadRig(glb, 'x.glb')).spec.parents.length).toBe(21);
  });
});

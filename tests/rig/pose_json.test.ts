// The pose file (web/src/rig/pose_json.ts): round trip, bones keyed by name (or "#index" for bones
// without a name of their own, as in every A7 rig), every malformed file refused with its field
// named and the writer refusing the same, every angle clamped into the rig's limits, and the page
// refusing an oversized pose file before reading it.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import {
  MAX_POSE_CHARS,
  PoseFormatError,
  poseFromJson,
  poseToJson,
  type PoseInput,
} from '../../web/src/rig/pose_json.js';
import { loadA7, needsA7, randomAngles, seeded } from '../helpers/a7.js';

const modelsDir = resolve(import.meta.dirname, '../../web/public/models');

let knight: RigSpec;
beforeAll(async () => {
  knight = (await loadRig(new Uint8Array(readFileSync(resolve(modelsDir, 'knight.glb'))), 'knight.glb')).spec;
});

/** A pose of the knight at random angles, its own effectors with random targets, every other one with an orientation. */
function knightPose(seed: number): PoseInput {
  const rand = seeded(seed);
  const effectors = Array.from(knight.effectors);
  return {
    rigName: 'knight',
    boneNames: knight.names,
    angles: randomAngles(knight, rand),
    effectors,
    targets: Float64Array.from({ length: 3 * effectors.length }, () => 4 * rand() - 2),
    orientations: effectors.map((_, e) => {
      if (e % 2) return null;
      const q = [rand() - 0.5, rand() - 0.5, rand() - 0.5, rand() - 0.5];
      const n = Math.hypot(...q);
      return q.map((v) => v / n);
    }),
  };
}

const sameBits = (a: ArrayLike<number>, b: ArrayLike<number>): boolean =>
  a.length === b.length && Array.from(a).every((v, k) => Object.is(v, b[k]));

/** A small rig by name only: what poseFromJson reads. */
const small = {
  names: ['root', 'arm', 'hand', '__proto__'],
  lower: Float64Array.of(-180, -180, -180, -90, 0, -45, -10, -10, -10, -Infinity, -Infinity, -Infinity),
  upper: Float64Array.of(180, 180, 180, 90, 120, 45, 10, 10, 10, Infinity, Infinity, Infinity),
};

/** A valid file for `small`, as an object to break. */
function smallFile(): Record<string, unknown> {
  return {
    format: 'ik-pose',
    version: 1,
    rig: 'small',
    bones: { root: [1, 2, 3], arm: [4, 5, 6], hand: [0, 0, 0], ['__proto__']: [7, 8, 9] },
    effectors: [
      { bone: 'hand', target: [0, 1, 2], orientation: [0, 0, 0, 1] },
      { bone: 'arm', target: [1, 1, 1] },
    ],
  };
}
const text = (o: unknown): string => JSON.stringify(o);

describe('poseToJson / poseFromJson', () => {
  it('round trip: the same angles bit for bit, the same effectors, targets and orientations', () => {
    for (const seed of [1, 2, 3]) {
      const pose = knightPose(seed);
      const json = poseToJson(pose);
      const doc = JSON.parse(json);
      expect(doc.format).toBe('ik-pose');
      expect(doc.version).toBe(1);
      expect(Object.keys(doc.bones)).toEqual(knight.names);
      const read = poseFromJson(json, knight);
      expect(read.warnings).toEqual([]);
      expect(read.rigName).toBe('knight');
      expect(sameBits(read.angles, pose.angles), 'angles').toBe(true);
      expect(read.effectors).toEqual(Array.from(knight.effectors));
      expect(sameBits(read.targets, pose.targets), 'targets').toBe(true);
      read.orientations.forEach((q, e) => {
        const want = pose.orientations![e];
        if (want === null) expect(q).toBeNull();
        else expect(sameBits(q!, want), `orientation ${e}`).toBe(true);
      });
    }
  });

  it("a floating root's move round-trips bit for bit; a pose without one reads none; a bad one is refused by name", () => {
    const pose = { ...knightPose(4), root: [0.125, -0.3000000000000001, 1e-9] };
    const json = poseToJson(pose);
    expect(JSON.parse(json).root).toEqual(pose.root);
    const read = poseFromJson(json, knight);
    expect(sameBits(read.root!, pose.root), 'root').toBe(true);
    expect(poseFromJson(poseToJson(knightPose(4)), knight).root).toBeNull();
    expect(() => poseFromJson(json.replace('"root": [0.125', '"root": ["x"'), knight)).toThrow(/"root"/);
    expect(() => poseFromJson(json.replace('"root": [0.125,', '"root": ['), knight)).toThrow(/"root"/);
    expect(() => poseToJson({ ...pose, root: [NaN, 0, 0] })).toThrow(/"root"/);
  });

  it('bones listed in another order, and a rig whose bones come in another order, get the right angles', () => {
    const pose = knightPose(4);
    const doc = JSON.parse(poseToJson(pose));
    doc.bones = Object.fromEntries(Object.entries(doc.bones).reverse());
    const reversed = poseFromJson(text(doc), knight);
    expect(sameBits(reversed.angles, pose.angles)).toBe(true);

    // The same rig with its bones permuted: each bone's angles follow its name.
    const n = knight.names.length;
    const perm = Array.from({ length: n }, (_, i) => (i * 7 + 3) % n);
    expect(new Set(perm).size).toBe(n);
    const pick = (a: Float64Array): Float64Array =>
      Float64Array.from({ length: 3 * n }, (_, k) => a[3 * perm[Math.floor(k / 3)] + (k % 3)]);
    const permuted = { names: perm.map((i) => knight.names[i]), lower: pick(knight.lower), upper: pick(knight.upper) };
    const read = poseFromJson(poseToJson(pose), permuted);
    perm.forEach((old, i) => {
      expect(Array.from(read.angles.subarray(3 * i, 3 * i + 3)), permuted.names[i]).toEqual(
        Array.from(pose.angles).slice(3 * old, 3 * old + 3),
      );
    });
    expect(read.effectors.map((b) => permuted.names[b])).toEqual(Array.from(pose.effectors, (b) => knight.names[b]));
  });

  it('a bone called "__proto__" is an ordinary bone', () => {
    const read = poseFromJson(text(smallFile()), small);
    expect(Array.from(read.angles.subarray(9, 12))).toEqual([7, 8, 9]);
    const json = poseToJson({
      rigName: 's',
      boneNames: small.names,
      angles: read.angles,
      effectors: [3],
      targets: [1, 2, 3],
    });
    expect(Array.from(poseFromJson(json, small).angles)).toEqual(Array.from(read.angles));
    expect(poseFromJson(json, small).effectors).toEqual([3]);
  });

  it('angles outside the limits are clamped with a warning naming the bone', () => {
    const file = smallFile();
    (file.bones as Record<string, number[]>).arm = [100, -5, 45];
    (file.bones as Record<string, number[]>).hand = [0, 11, 0];
    const read = poseFromJson(text(file), small);
    expect(Array.from(read.angles.subarray(3, 9))).toEqual([90, 0, 45, 0, 10, 0]);
    expect(read.warnings).toHaveLength(1);
    expect(read.warnings[0]).toMatch(/clamped for 2 bone/);
    expect(read.warnings[0]).toMatch(/"arm" \[100, -5, 45\] -> \[90, 0, 45\]/);
    expect(read.warnings[0]).toMatch(/"hand"/);
    expect(read.warnings[0]).not.toMatch(/"root"/);
    // Other limits (e.g. the humanoid's) clamp instead of the spec's.
    const wide = { lower: new Float64Array(12).fill(-1000), upper: new Float64Array(12).fill(1000) };
    const free = poseFromJson(text(file), small, wide);
    expect(free.warnings).toEqual([]);
    expect(Array.from(free.angles.subarray(3, 6))).toEqual([100, -5, 45]);
  });

  it('bones the file lacks get 0 with a warning naming them', () => {
    const file = smallFile();
    delete (file.bones as Record<string, unknown>).arm;
    const read = poseFromJson(text(file), small);
    expect(Array.from(read.angles.subarray(3, 6))).toEqual([0, 0, 0]);
    expect(Array.from(read.angles.subarray(0, 3))).toEqual([1, 2, 3]);
    expect(read.warnings).toEqual([
      expect.stringMatching(/no angles for 1 bone\(s\), set to 0 or the nearest limit: "arm"$/),
    ]);
  });

  const broken: [string, (f: Record<string, unknown>) => unknown, RegExp][] = [
    ['not JSON', () => '{"format": "ik-pose",', /not JSON/],
    ['an array', () => [], /the JSON is an array, not an object/],
    ['no format', (f) => (delete f.format, f), /"format" is undefined, expected "ik-pose"/],
    ['another format', (f) => ({ ...f, format: 'glTF' }), /"format" is "glTF"/],
    ['version 2', (f) => ({ ...f, version: 2 }), /"version" is 2/],
    ['version "1"', (f) => ({ ...f, version: '1' }), /"version" is "1"/],
    ['rig not a string', (f) => ({ ...f, rig: 3 }), /"rig" is 3/],
    ['no bones', (f) => (delete f.bones, f), /"bones" is undefined/],
    ['bones an array', (f) => ({ ...f, bones: [[1, 2, 3]] }), /"bones" is an array/],
    [
      'unknown bones',
      (f) => ({ ...f, bones: { ...(f.bones as object), tail: [0, 0, 0], wing: [0, 0, 0] } }),
      /"bones" names 2 bone\(s\) the rig lacks: "tail", "wing"/,
    ],
    ['two angles', (f) => ({ ...f, bones: { arm: [1, 2] } }), /"bones"\["arm"\] has 2 values, expected 3/],
    ['angles not an array', (f) => ({ ...f, bones: { arm: 5 } }), /"bones"\["arm"\] is 5, not an array/],
    [
      'a string angle',
      (f) => ({ ...f, bones: { arm: [1, '2', 3] } }),
      /"bones"\["arm"\]\[1\] is "2", not a finite number/,
    ],
    ['a null angle', (f) => ({ ...f, bones: { hand: [1, 2, null] } }), /"bones"\["hand"\]\[2\] is null/],
    [
      'an infinite angle',
      (f) => JSON.stringify(f).replace('"root":[1,2,3]', '"root":[1,1e999,3]'),
      /"bones"\["root"\]\[1\] is Infinity/,
    ],
    ['no effectors', (f) => (delete f.effectors, f), /"effectors" is undefined/],
    ['effector not an object', (f) => ({ ...f, effectors: ['hand'] }), /"effectors"\[0\] is "hand", not an object/],
    [
      'effector without bone',
      (f) => ({ ...f, effectors: [{ target: [0, 0, 0] }] }),
      /"effectors"\[0\]\.bone is undefined/,
    ],
    [
      'effector of an unknown bone',
      (f) => ({ ...f, effectors: [{ bone: 'tail', target: [0, 0, 0] }] }),
      /"effectors"\[0\]\.bone "tail" is no bone/,
    ],
    [
      'effector twice',
      (f) => ({
        ...f,
        effectors: [
          { bone: 'arm', target: [0, 0, 0] },
          { bone: 'arm', target: [0, 0, 0] },
        ],
      }),
      /"effectors"\[1\]\.bone "arm" is listed twice/,
    ],
    [
      'short target',
      (f) => ({ ...f, effectors: [{ bone: 'arm', target: [0, 0] }] }),
      /"effectors"\[0\]\.target has 2 values, expected 3/,
    ],
    [
      'target far away',
      (f) => ({ ...f, effectors: [{ bone: 'arm', target: [0, 2e9, 0] }] }),
      /"effectors"\[0\]\.target\[1\] = 2000000000 lies beyond/,
    ],
    [
      'bad target number',
      (f) => ({ ...f, effectors: [{ bone: 'arm', target: [0, true, 0] }] }),
      /"effectors"\[0\]\.target\[1\] is true/,
    ],
    [
      'orientation of 3',
      (f) => ({ ...f, effectors: [{ bone: 'arm', target: [0, 0, 0], orientation: [0, 0, 1] }] }),
      /"effectors"\[0\]\.orientation has 3 values, expected 4/,
    ],
    [
      'orientation not unit',
      (f) => ({ ...f, effectors: [{ bone: 'arm', target: [0, 0, 0], orientation: [0, 0, 0, 2] }] }),
      /"effectors"\[0\]\.orientation has length 2, not a unit quaternion/,
    ],
    [
      'too many effectors',
      (f) => ({ ...f, effectors: Array.from({ length: 65 }, () => ({ bone: 'arm', target: [0, 0, 0] })) }),
      /"effectors": 65 end effectors; at most 64/,
    ],
    ['too deep', () => `${'['.repeat(100)}${']'.repeat(100)}`, /nests deeper/],
  ];
  it.each(broken)('refuses %s, naming the field', (_, make, message) => {
    const made = make(smallFile());
    const t = typeof made === 'string' ? made : text(made);
    expect(() => poseFromJson(t, small)).toThrow(PoseFormatError);
    expect(() => poseFromJson(t, small)).toThrow(message);
  });

  it('refuses a file over the size bound with a clear message', () => {
    const file = smallFile();
    file.padding = ' '.repeat(MAX_POSE_CHARS);
    expect(() => poseFromJson(text(file), small)).toThrow(/MB of text, more than a pose file holds/);
  });

  it('refuses a bone name the rig gives two bones, which the file keys by index', () => {
    const twin = {
      names: ['a', 'a', 'b'],
      lower: new Float64Array(9).fill(-180),
      upper: new Float64Array(9).fill(180),
    };
    const file = { format: 'ik-pose', version: 1, bones: { a: [0, 0, 0], b: [0, 0, 0] }, effectors: [] };
    expect(() => poseFromJson(text(file), twin)).toThrow(
      /"bones" names "a", which is not the key of one bone: .* is keyed "#index"$/,
    );
    expect(() =>
      poseFromJson(text({ ...file, bones: { b: [1, 1, 1] }, effectors: [{ bone: 'a', target: [0, 0, 0] }] }), twin),
    ).toThrow(/"effectors"\[0\]\.bone "a", which is not the key of one bone/);
    const read = poseFromJson(
      text({
        ...file,
        bones: { '#0': [1, 2, 3], '#1': [4, 5, 6], b: [7, 8, 9] },
        effectors: [{ bone: '#1', target: [0, 0, 0] }],
      }),
      twin,
    );
    expect(Array.from(read.angles)).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9]);
    expect(read.effectors).toEqual([1]);
  });

  it('keys bones without a name of their own by index, and reads those keys back', () => {
    // '' twice, a name two bones share, a name that looks like an index key, and two usable names.
    const names = ['', 'arm', '', 'arm', '#7', 'hand'];
    const limits = { lower: new Float64Array(18).fill(-90), upper: new Float64Array(18).fill(90) };
    // -0 too: JSON.stringify would write it as 0.
    const pose: PoseInput = {
      rigName: 'r',
      boneNames: names,
      angles: Array.from({ length: 18 }, (_, k) => (k ? k : -0)),
      effectors: [2, 5],
      targets: [1, -0, 3, 4, 5, 6],
    };
    const json = poseToJson(pose);
    const doc = JSON.parse(json);
    expect(Object.keys(doc.bones)).toEqual(['#0', '#1', '#2', '#3', '#4', 'hand']);
    expect(doc.effectors.map((e: { bone: string }) => e.bone)).toEqual(['#2', 'hand']);
    const read = poseFromJson(json, { names, ...limits });
    expect(read.warnings).toEqual([]);
    expect(sameBits(read.angles, pose.angles)).toBe(true);
    expect(sameBits(read.targets, pose.targets)).toBe(true);
    expect(read.effectors).toEqual([2, 5]);
  });

  it('saves and loads a pose of an A7 rig, whose bones have no names', needsA7, () => {
    const spec = loadA7('knight');
    expect(spec.names.every((n) => n === '')).toBe(true);
    const angles = randomAngles(spec, seeded(5));
    const effectors = Array.from(spec.effectors);
    const json = poseToJson({
      rigName: 'knight',
      boneNames: spec.names,
      angles,
      effectors,
      targets: new Float64Array(3 * effectors.length).fill(0.5),
    });
    const read = poseFromJson(json, spec);
    expect(read.warnings).toEqual([]);
    expect(sameBits(read.angles, angles)).toBe(true);
    expect(read.effectors).toEqual(effectors);
  });

  it('clamps every angle into the limits, also those of bones the file lacks', async () => {
    const character = (
      await loadRig(new Uint8Array(readFileSync(resolve(modelsDir, 'character.glb'))), 'character.glb')
    ).spec;
    const { lower, upper } = character;
    const outside = Array.from(lower, (lo, k) => lo > 0 || upper[k] < 0).filter(Boolean).length;
    expect(outside, 'angles whose range leaves out 0').toBeGreaterThan(0);
    const read = poseFromJson(text({ format: 'ik-pose', version: 1, bones: {}, effectors: [] }), character);
    read.angles.forEach((v, k) =>
      expect(v >= lower[k] && v <= upper[k], `angle ${k} = ${v} in [${lower[k]}, ${upper[k]}]`).toBe(true),
    );
    expect(Array.from(read.angles).filter((v) => v !== 0)).toHaveLength(outside);
  });

  it('poseToJson refuses inconsistent input, naming the field', () => {
    const ok: PoseInput = {
      rigName: 'r',
      boneNames: ['a', 'b'],
      angles: [1, 2, 3, 4, 5, 6],
      effectors: [1],
      targets: [1, 2, 3],
    };
    expect(() => poseToJson(ok)).not.toThrow();
    expect(() => poseToJson({ ...ok, angles: [1, 2, 3] })).toThrow(/angles has 3 values for 2 bones/);
    expect(() => poseToJson({ ...ok, angles: [1, 2, 3, 4, NaN, 6] })).toThrow(
      /^poseToJson: "bones"\["b"\]\[1\] is NaN, not a finite number$/,
    );
    expect(() => poseToJson({ ...ok, effectors: [2] })).toThrow(
      /^poseToJson: "effectors"\[0\] is bone 2, not a bone index in 0\.\.1$/,
    );
    expect(() => poseToJson({ ...ok, effectors: [1, 1], targets: [1, 2, 3, 1, 2, 3] })).toThrow(
      /^poseToJson: "effectors"\[1\]\.bone "b" is listed twice$/,
    );
    expect(() => poseToJson({ ...ok, targets: [1, 2] })).toThrow(/targets has 2 values for 1 effectors/);
    expect(() => poseToJson({ ...ok, orientations: [] })).toThrow(/orientations has 0 entries for 1 effectors/);
  });

  // Values the reader refuses: the writer refuses them too, with the same words for the same field.
  const unreadable: [string, Partial<PoseInput>][] = [
    ['a non-unit quaternion', { orientations: [[0, 0, 0, 2]] }],
    ['an orientation of 3 numbers', { orientations: [[0, 0, 1]] }],
    ['a 1e10 target', { targets: [0, 1e10, 0] }],
    ['an infinite target', { targets: [1, Infinity, 3] }],
    ['65 effectors', { effectors: Array.from({ length: 65 }, (_, k) => k), targets: new Float64Array(195) }],
  ];
  it.each(unreadable)('poseToJson refuses %s as poseFromJson does', (_, change) => {
    const names = Array.from({ length: 70 }, (_, k) => `bone ${k}`);
    const rig = { names, lower: new Float64Array(210).fill(-180), upper: new Float64Array(210).fill(180) };
    const pose: PoseInput = {
      rigName: 'r',
      boneNames: names,
      angles: new Float64Array(210),
      effectors: [3],
      targets: [1, 2, 3],
      ...change,
    };
    const written = (() => {
      try {
        poseToJson(pose);
      } catch (e) {
        return (e as Error).message;
      }
      throw new Error('poseToJson wrote it');
    })();
    const effectors = Array.from(pose.effectors, (b, e) => ({
      bone: names[b],
      target: Array.from(pose.targets).slice(3 * e, 3 * e + 3),
      ...(pose.orientations?.[e] ? { orientation: Array.from(pose.orientations[e]!) } : {}),
    }));
    // JSON cannot hold Infinity: 1e999 reads back as it.
    const file = text({ format: 'ik-pose', version: 1, bones: {}, effectors }).replace('null', '1e999');
    expect(() => poseFromJson(file, rig)).toThrow(PoseFormatError);
    const read = (() => {
      try {
        poseFromJson(file, rig);
      } catch (e) {
        return (e as Error).message;
      }
    })();
    expect(written.replace(/^poseToJson: /, '')).toBe(read!.replace(/^pose file: /, ''));
  });

  it('the page refuses a pose file over the size bound without reading it', async () => {
    const { readPoseFile } = await import('../../web/src/page/pose_files.js');
    let read = false;
    const big = { name: 'big.json', size: 200 * 1024 * 1024, text: async () => ((read = true), '') } as unknown as File;
    await expect(readPoseFile(big, {} as never)).rejects.toThrow(
      /^pose file big\.json: 200\.0 MB, more than a pose file holds \(at most 8 MB\)$/,
    );
    expect(read).toBe(false);
  });
});

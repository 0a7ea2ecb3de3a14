// Byte-level damage to a file: truncation, flipped bytes, bad GLB header and chunk fields,
// garbage appended, invalid UTF-8, a byte-order mark. Each returns the new bytes and one line.
import type { Rand } from './random.js';

export interface Mutated {
  bytes: Uint8Array;
  description: string;
}

const U32_VALUES = [0, 1, 3, 7, 0x7fffffff, 0x80000000, 0xffffffff, 0xfffffff8];

/** The 32-bit little-endian fields of a GLB header and its chunk headers: [offset, name]. */
function glbFields(bytes: Uint8Array): [number, string][] {
  const fields: [number, string][] = [
    [4, 'GLB version'],
    [8, 'GLB total length'],
  ];
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let at = 12, k = 0; at + 8 <= bytes.byteLength; k++) {
    fields.push([at, `chunk ${k} length`], [at + 4, `chunk ${k} type`]);
    at += 8 + view.getUint32(at, true);
  }
  return fields;
}

/** One random byte-level mutation of `bytes` (a .glb, .gltf, .bin or .json file). */
export function mutateBytes(r: Rand, bytes: Uint8Array, name: string): Mutated {
  const isGlb =
    bytes.byteLength >= 12 && new DataView(bytes.buffer, bytes.byteOffset).getUint32(0, true) === 0x46546c67;
  return r.weighted<() => Mutated>([
    [
      3,
      () => {
        const length = r.int(bytes.byteLength);
        return {
          bytes: bytes.slice(0, length),
          description: `${name} truncated to ${length} of ${bytes.byteLength} bytes`,
        };
      },
    ],
    [
      3,
      () => {
        const out = bytes.slice();
        const count = r.pick([1, 2, 8, 64]);
        for (let k = 0; k < count; k++) out[r.int(out.length)] ^= 1 << r.int(8);
        return { bytes: out, description: `${name}: ${count} random bits flipped` };
      },
    ],
    [
      isGlb ? 4 : 0,
      () => {
        const [at, field] = r.pick(glbFields(bytes));
        const out = bytes.slice();
        const old = new DataView(out.buffer).getUint32(at, true);
        const value = r.chance(0.5) ? r.pick(U32_VALUES) : (old + r.pick([-8, -4, -1, 1, 4, 8])) >>> 0;
        new DataView(out.buffer).setUint32(at, value, true);
        return { bytes: out, description: `${name}: ${field} ${old} -> ${value}` };
      },
    ],
    [
      1,
      () => {
        const extra = r.pick([1, 7, 8, 4096]);
        const out = new Uint8Array(bytes.byteLength + extra);
        out.set(bytes);
        for (let k = bytes.byteLength; k < out.length; k++) out[k] = r.int(256);
        return { bytes: out, description: `${name}: ${extra} garbage bytes appended` };
      },
    ],
    [
      1,
      () => {
        const out = bytes.slice();
        const at = r.int(out.length),
          length = Math.min(r.intIn(1, 16), out.length - at);
        out.fill(0xff, at, at + length);
        return { bytes: out, description: `${name}: ${length} bytes at ${at} set to 0xff (invalid UTF-8)` };
      },
    ],
    [
      1,
      () => {
        const out = new Uint8Array(bytes.byteLength + 3);
        out.set([0xef, 0xbb, 0xbf]);
        out.set(bytes, 3);
        return { bytes: out, description: `${name}: a UTF-8 byte-order mark prepended` };
      },
    ],
  ])();
}

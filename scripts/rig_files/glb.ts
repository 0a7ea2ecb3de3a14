// Taking a .glb apart and putting it back together, to make variants and broken files in tests.
import { parseGltfContainer } from '#rig/gltf/gltf_file.js';

export type Json = Record<string, unknown> & { nodes: Record<string, unknown>[]; skins: Record<string, unknown>[] };

/** The JSON and the BIN chunk (fresh copies) of .glb bytes. */
export function unpackGlb(bytes: Uint8Array): { json: Json; bin: Uint8Array } {
  const c = parseGltfContainer(bytes, 'x.glb');
  return { json: structuredClone(c.json) as Json, bin: c.bin ? c.bin.slice() : new Uint8Array(0) };
}

/** A .glb from JSON and an optional BIN chunk. */
export function packGlb(json: unknown, bin?: Uint8Array): Uint8Array {
  return packGlbText(JSON.stringify(json), bin);
}

/**
 * A .glb from JSON text (which may hold what JSON.stringify cannot write: the fuzzer's mutants) and
 * an optional BIN chunk, both chunks padded to 4 bytes as the format wants.
 */
export function packGlbText(jsonText: string, bin?: Uint8Array): Uint8Array {
  const pad = (n: number): number => (n + 3) & ~3;
  const text = new TextEncoder().encode(jsonText);
  const jsonLen = pad(text.length),
    binLen = bin ? pad(bin.length) : 0;
  const total = 12 + 8 + jsonLen + (bin ? 8 + binLen : 0);
  const out = new Uint8Array(total);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, 0x46546c67, true);
  dv.setUint32(4, 2, true);
  dv.setUint32(8, total, true);
  dv.setUint32(12, jsonLen, true);
  dv.setUint32(16, 0x4e4f534a, true);
  out.fill(0x20, 20, 20 + jsonLen);
  out.set(text, 20);
  if (bin) {
    const at = 20 + jsonLen;
    dv.setUint32(at, binLen, true);
    dv.setUint32(at + 4, 0x004e4942, true);
    out.set(bin, at + 8);
  }
  return out;
}

/** Index of the node named `name`. */
export function nodeIndex(json: Json, name: string): number {
  const i = json.nodes.findIndex((n) => n.name === name);
  if (i < 0) throw new Error(`no node ${name}`);
  return i;
}

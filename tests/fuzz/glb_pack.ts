// A .glb from JSON text (which may hold what JSON.stringify cannot write, see json_text.ts) and a
// BIN chunk: tests/helpers/glb.ts packGlb() takes a document instead.

/** The GLB bytes of `jsonText` and `bin`, both chunks padded to 4 bytes as the format wants. */
export function packGlbText(jsonText: string, bin: Uint8Array): Uint8Array {
  const pad = (n: number): number => (n + 3) & ~3;
  const text = new TextEncoder().encode(jsonText);
  const jsonLength = pad(text.length), binLength = pad(bin.length);
  const total = 12 + 8 + jsonLength + 8 + binLength;
  const out = new Uint8Array(total);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true);
  out.fill(0x20, 20, 20 + jsonLength);
  out.set(text, 20);
  view.setUint32(20 + jsonLength, binLength, true);
  view.setUint32(24 + jsonLength, 0x004e4942, true);
  out.set(bin, 28 + jsonLength);
  return out;
}

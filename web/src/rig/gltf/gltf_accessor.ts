// Reads a skin's inverse bind matrices (a FLOAT MAT4 accessor) from its buffer, so a missing or
// short buffer or a NaN gives an error that names it. Byte ranges were checked by checkRanges
// (gltf_ranges.ts) against the declared buffer lengths, and loadBuffer checks each buffer's bytes
// against its declared length, so every read here lies inside the loaded bytes.
import { failIn } from '../rig_format_error.js';
import { loadBuffer, type GltfContainer, type SiblingReader } from './gltf_file.js';
import type { GltfLists } from './gltf_references.js';
import { fromColumnMajor } from '../mat4.js';

const FLOAT = 5126;

/** Loads buffers on demand, once each. */
export class BufferCache {
  private readonly loaded = new Map<number, Promise<Uint8Array>>();

  constructor(
    private readonly container: GltfContainer,
    private readonly lists: GltfLists,
    private readonly file: string,
    private readonly readSibling: SiblingReader | undefined,
  ) {}

  /** The bytes of buffer `index` (at least its declared byteLength). */
  get(index: number): Promise<Uint8Array> {
    let p = this.loaded.get(index);
    if (!p) {
      const def = this.lists.buffers[index];
      p = loadBuffer(
        this.container,
        index,
        def.uri as string | undefined,
        def.byteLength as number,
        this.file,
        this.readSibling,
      );
      this.loaded.set(index, p);
    }
    return p;
  }
}

/**
 * The first `count` matrices of MAT4 FLOAT accessor `accessorIndex`, as row-major 4x4 matrices
 * (16 numbers each). `where` names the user (e.g. "skins[0].inverseBindMatrices") in errors.
 */
export async function readMat4Accessor(
  lists: GltfLists,
  buffers: BufferCache,
  accessorIndex: number,
  count: number,
  where: string,
  file: string,
): Promise<Float64Array> {
  const a = lists.accessors[accessorIndex];
  const at = `${where} (accessor ${accessorIndex})`;
  if (a.type !== 'MAT4' || a.componentType !== FLOAT) failIn(file, `${at} must be MAT4 of FLOAT`);
  if ((a.count as number) < count) failIn(file, `${at} has ${String(a.count)} matrices, the skin has ${count} joints`);
  if (a.sparse !== undefined) failIn(file, `${at} is sparse, which the rig importer does not read`);
  // glTF: an accessor without a bufferView is all zeros: not invertible as a bind matrix.
  if (a.bufferView === undefined) failIn(file, `${at} has no bufferView (all-zero matrices)`);
  const view = lists.bufferViews[a.bufferView as number];
  const data = await buffers.get(view.buffer as number);
  const viewOffset = (view.byteOffset as number | undefined) ?? 0;
  const stride = (view.byteStride as number | undefined) ?? 64;
  const offset = (a.byteOffset as number | undefined) ?? 0;
  const dv = new DataView(data.buffer, data.byteOffset + viewOffset, view.byteLength as number);
  const out = new Float64Array(16 * count);
  const column = new Float64Array(16);
  for (let j = 0; j < count; j++) {
    for (let k = 0; k < 16; k++) column[k] = dv.getFloat32(offset + stride * j + 4 * k, true);
    out.set(fromColumnMajor(column), 16 * j);
  }
  for (let k = 0; k < out.length; k++)
    if (!Number.isFinite(out[k]))
      failIn(file, `${at}: matrix ${Math.floor(k / 16)} has a non-finite entry (NaN or infinite)`);
  return out;
}

// Reads a skin's inverse bind matrices (a FLOAT MAT4 accessor) from its buffer, with every range
// checked, so a missing or short buffer or a NaN gives an error that names it.
import { failIn, loadBuffer, type GltfContainer, type SiblingReader } from './gltf_file.js';
import { asIndex, asObject, asObjectList, type JsonObject } from './gltf_nodes.js';
import { fromColumnMajor } from './mat4.js';

const FLOAT = 5126;

/** Loads buffers on demand, once each. */
export class BufferCache {
  private readonly loaded = new Map<number, Promise<Uint8Array>>();
  private readonly defs: JsonObject[];

  constructor(
    private readonly container: GltfContainer,
    private readonly file: string,
    private readonly readSibling: SiblingReader | undefined,
  ) {
    this.defs = asObjectList(container.json.buffers, 'buffers', file);
  }

  /** The bytes of buffer `index` (checked against its declared byteLength). */
  get(index: number): Promise<Uint8Array> {
    let p = this.loaded.get(index);
    if (!p) {
      const def = this.defs[index];
      const uri = def.uri;
      if (uri !== undefined && typeof uri !== 'string') failIn(this.file, `buffers[${index}].uri is not a string`);
      const length = def.byteLength;
      if (typeof length !== 'number' || !Number.isInteger(length) || length < 0)
        failIn(this.file, `buffers[${index}].byteLength is missing or not a whole number`);
      p = loadBuffer(this.container, index, uri, length, this.file, this.readSibling);
      this.loaded.set(index, p);
    }
    return p;
  }

  get count(): number {
    return this.defs.length;
  }
}

/**
 * The first `count` matrices of MAT4 FLOAT accessor `accessorIndex`, as row-major 4x4 matrices
 * (16 numbers each). `where` names the user (e.g. "skins[0].inverseBindMatrices") in errors.
 */
export async function readMat4Accessor(
  json: JsonObject,
  buffers: BufferCache,
  accessorIndex: number,
  count: number,
  where: string,
  file: string,
): Promise<Float64Array> {
  const accessors = asObjectList(json.accessors, 'accessors', file);
  const a = asObject(accessors[asIndex(accessorIndex, accessors.length, where, file)], `accessors[${accessorIndex}]`, file);
  const at = `${where} (accessor ${accessorIndex})`;
  if (a.type !== 'MAT4' || a.componentType !== FLOAT) failIn(file, `${at} must be MAT4 of FLOAT`);
  if (typeof a.count !== 'number' || a.count < count)
    failIn(file, `${at} has ${String(a.count)} matrices, the skin has ${count} joints`);
  if (a.sparse !== undefined) failIn(file, `${at} is sparse, which the rig importer does not read`);
  const out = new Float64Array(16 * count);
  if (a.bufferView === undefined) {
    // glTF: an accessor without a bufferView is all zeros: not invertible as a bind matrix.
    failIn(file, `${at} has no bufferView (all-zero matrices)`);
  }
  const views = asObjectList(json.bufferViews, 'bufferViews', file);
  const viewIndex = asIndex(a.bufferView, views.length, `accessors[${accessorIndex}].bufferView`, file);
  const view = views[viewIndex];
  const bufferIndex = asIndex(view.buffer, buffers.count, `bufferViews[${viewIndex}].buffer`, file);
  const data = await buffers.get(bufferIndex);
  const viewOffset = typeof view.byteOffset === 'number' ? view.byteOffset : 0;
  const viewLength = typeof view.byteLength === 'number' ? view.byteLength : -1;
  if (viewLength < 0 || viewOffset < 0 || viewOffset + viewLength > data.byteLength)
    failIn(file, `bufferViews[${viewIndex}] (offset ${viewOffset}, length ${viewLength}) lies outside buffer ${bufferIndex} (${data.byteLength} bytes)`);
  const stride = typeof view.byteStride === 'number' ? view.byteStride : 64;
  const offset = typeof a.byteOffset === 'number' ? a.byteOffset : 0;
  if (stride < 64 || (count > 0 && offset + stride * (count - 1) + 64 > viewLength))
    failIn(file, `${at} reads past the end of bufferView ${viewIndex}`);
  const dv = new DataView(data.buffer, data.byteOffset + viewOffset, viewLength);
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

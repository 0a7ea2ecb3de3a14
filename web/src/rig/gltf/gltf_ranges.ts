// The byte ranges of a glTF document: every buffer view inside its buffer, every accessor (and
// sparse accessor) inside its buffer view and aligned to its components, every size a whole number.
// Checked against the lengths the JSON declares (a buffer's bytes are compared with its declared
// length when it is loaded), so that no reader, ours or three.js's, ever indexes past a buffer.
// The bytes of all accessors together are capped, those without a buffer view (zeros that a loader
// allocates: forty of 512 MiB in a 9 KB file made three.js ask for 20 GiB) included.
// Run after checkReferences (gltf_references.ts): every index here is already in range.
import { failIn } from '../rig_format_error.js';
import { type GltfContainer } from './gltf_file.js';
import { asIndex, asInteger, asObject, badValue, type JsonObject } from './gltf_json.js';
import type { GltfLists } from './gltf_references.js';

/** Bytes per component of each glTF componentType. */
const COMPONENT_BYTES: ReadonlyMap<unknown, number> = new Map([
  [5120, 1],
  [5121, 1],
  [5122, 2],
  [5123, 2],
  [5125, 4],
  [5126, 4],
]);

/** Bytes per index of the componentTypes a sparse accessor's indices may have. */
const SPARSE_INDEX_BYTES: ReadonlyMap<unknown, number> = new Map([
  [5121, 1],
  [5123, 2],
  [5125, 4],
]);

/** Components per element of each accessor type. */
const TYPE_COMPONENTS: ReadonlyMap<unknown, number> = new Map([
  ['SCALAR', 1],
  ['VEC2', 2],
  ['VEC3', 3],
  ['VEC4', 4],
  ['MAT2', 4],
  ['MAT3', 9],
  ['MAT4', 16],
]);

/** Largest byte count or element count the checks accept (2^53: exact in a double). */
const MAX_SIZE = Number.MAX_SAFE_INTEGER;

/**
 * Most bytes of accessor data in one file, all accessors summed (count x element size, with or
 * without a buffer view), 256 MiB: a character of 100,000 vertices with its animations holds a
 * few MB.
 */
export const MAX_ACCESSOR_BYTES = 256 * 1024 * 1024;

/** Bytes of one element: matrix columns start on 4-byte boundaries (glTF 2.0, "Data Alignment"). */
function elementBytes(type: string, components: number, componentBytes: number): number {
  if (!type.startsWith('MAT')) return components * componentBytes;
  const n = Math.sqrt(components);
  return n * (Math.ceil((n * componentBytes) / 4) * 4);
}

/** Checks the byte ranges of buffers, buffer views and accessors. Throws RigFormatError naming the field. */
export function checkRanges(container: GltfContainer, lists: GltfLists, file: string): void {
  const bufferLengths = checkBuffers(lists.buffers, container.bin, file);
  const views = checkBufferViews(lists.bufferViews, bufferLengths, file);
  let accessorBytes = 0;
  lists.accessors.forEach((a, i) => {
    const where = `accessors[${i}]`;
    const elements = accessorElements(a, where, file);
    accessorBytes += elements.count * elements.element;
    if (accessorBytes > MAX_ACCESSOR_BYTES) failIn(file, tooManyAccessorBytes(accessorBytes, i, a, elements));
    checkAccessorData(a, elements, views, where, file);
  });
}

/** Where a buffer view lies in its buffer (first byte and length, bytes) and its byteStride (bytes; undefined: packed). */
interface ViewRange {
  offset: number;
  length: number;
  stride: number | undefined;
}

/** A run of data: `count` elements of `element` bytes each (elementBytes), in components of `componentBytes` bytes. */
interface Elements {
  count: number;
  element: number;
  componentBytes: number;
}

/**
 * Each buffer's byteLength (bytes), checked, and its uri a string where given; a buffers[0]
 * without a uri must fit in the GLB binary chunk `bin` (when there is one).
 */
function checkBuffers(buffers: JsonObject[], bin: Uint8Array | undefined, file: string): number[] {
  return buffers.map((b, i) => {
    const length = asInteger(b.byteLength, 1, MAX_SIZE, `buffers[${i}].byteLength`, file);
    if (b.uri !== undefined && typeof b.uri !== 'string') failIn(file, `buffers[${i}].uri is not a string`);
    if (i === 0 && b.uri === undefined && bin !== undefined && bin.byteLength < length)
      failIn(
        file,
        `buffers[0].byteLength = ${length} is more than the ${bin.byteLength} bytes of the GLB binary chunk (truncated file?)`,
      );
    return length;
  });
}

/** Each buffer view's range, checked to lie inside its buffer (`bufferLengths`, bytes) with a valid byteStride. */
function checkBufferViews(bufferViews: JsonObject[], bufferLengths: number[], file: string): ViewRange[] {
  return bufferViews.map((v, i) => {
    const where = `bufferViews[${i}]`;
    const offset = asInteger(v.byteOffset, 0, MAX_SIZE, `${where}.byteOffset`, file, 0);
    const length = asInteger(v.byteLength, 1, MAX_SIZE, `${where}.byteLength`, file);
    const stride =
      v.byteStride === undefined ? undefined : asInteger(v.byteStride, 4, 252, `${where}.byteStride`, file);
    if (stride !== undefined && stride % 4 !== 0)
      failIn(file, `${where}.byteStride = ${stride} is not a multiple of 4`);
    const buffer = v.buffer as number;
    if (offset + length > bufferLengths[buffer])
      failIn(
        file,
        `${where} (bytes ${offset} to ${offset + length}) lies outside buffers[${buffer}] (${bufferLengths[buffer]} bytes)`,
      );
    return { offset, length, stride };
  });
}

/**
 * The elements of accessor `a` (`where` names it): its count, its element's bytes and its
 * component's bytes, from its componentType, type and count; its min and max are checked too.
 */
function accessorElements(a: JsonObject, where: string, file: string): Elements {
  const componentBytes = COMPONENT_BYTES.get(a.componentType);
  if (componentBytes === undefined)
    failIn(
      file,
      badValue(
        a.componentType,
        `${where}.componentType`,
        `a glTF component type (${[...COMPONENT_BYTES.keys()].join(', ')})`,
      ),
    );
  const components = TYPE_COMPONENTS.get(a.type);
  if (components === undefined)
    failIn(file, badValue(a.type, `${where}.type`, `a glTF accessor type (${[...TYPE_COMPONENTS.keys()].join(', ')})`));
  const count = asInteger(a.count, 1, MAX_SIZE, `${where}.count`, file);
  const element = elementBytes(a.type as string, components, componentBytes);
  checkMinMax(a, components, where, file);
  return { count, element, componentBytes };
}

/** Checks that accessor `a`'s min and max, where given, are `components` finite numbers each. */
function checkMinMax(a: JsonObject, components: number, where: string, file: string): void {
  for (const key of ['min', 'max'] as const) {
    const v = a[key];
    if (
      v !== undefined &&
      (!Array.isArray(v) || v.length !== components || !v.every((x) => typeof x === 'number' && Number.isFinite(x)))
    )
      failIn(file, `${where}.${key} must be ${components} finite numbers`);
  }
}

/**
 * The message for `total` bytes of accessor data in accessors[0..i], more than MAX_ACCESSOR_BYTES,
 * naming accessors[i] (`a`, with its `elements`), the one that passed the cap.
 */
function tooManyAccessorBytes(total: number, i: number, a: JsonObject, elements: Elements): string {
  const where = `accessors[${i}]`;
  const zeros = a.bufferView === undefined ? ' without a bufferView, zeros to allocate' : '';
  return `${total} bytes of accessor data in ${i === 0 ? where : `accessors[0..${i}]`} (${where}: ${elements.count} elements of ${elements.element} bytes${zeros}); at most ${MAX_ACCESSOR_BYTES} bytes (256 MiB) in one file`;
}

/** Checks that accessor `a`'s data (`elements`) and its sparse data, where it has them, lie inside their buffer views. */
function checkAccessorData(a: JsonObject, elements: Elements, views: ViewRange[], where: string, file: string): void {
  if (a.bufferView !== undefined) {
    const offset = asInteger(a.byteOffset, 0, MAX_SIZE, `${where}.byteOffset`, file, 0);
    checkSpan(views, a.bufferView as number, offset, elements, where, file);
  }
  if (a.sparse !== undefined)
    checkSparse(asObject(a.sparse, `${where}.sparse`, file), elements, views, `${where}.sparse`, file);
}

/**
 * Checks the sparse data `s` of an accessor whose elements are `elements`: at most their count of
 * indices, of a sparse index type, and values of the accessor's elements, each inside its view.
 */
function checkSparse(s: JsonObject, elements: Elements, views: ViewRange[], where: string, file: string): void {
  const count = asInteger(s.count, 1, elements.count, `${where}.count`, file);
  const indices = asObject(s.indices, `${where}.indices`, file);
  const indexBytes = SPARSE_INDEX_BYTES.get(indices.componentType);
  if (indexBytes === undefined)
    failIn(file, badValue(indices.componentType, `${where}.indices.componentType`, '5121, 5123 or 5125'));
  const indexElements = { count, element: indexBytes, componentBytes: indexBytes };
  checkSparsePart(indices, indexElements, views, `${where}.indices`, file);
  const valueElements = { count, element: elements.element, componentBytes: elements.componentBytes };
  checkSparsePart(asObject(s.values, `${where}.values`, file), valueElements, views, `${where}.values`, file);
}

/** Checks that the sparse indices or values `o` (`elements`, packed) lie inside their buffer view. */
function checkSparsePart(o: JsonObject, elements: Elements, views: ViewRange[], at: string, file: string): void {
  const v = asIndex(o.bufferView, views.length, `${at}.bufferView`, file);
  checkSpan(views, v, asInteger(o.byteOffset, 0, MAX_SIZE, `${at}.byteOffset`, file, 0), elements, at, file, true);
}

/**
 * Checks that `elements` from byte `offset` of view `v` (of `views`) are aligned to their
 * components and lie inside the view; `packed` (sparse data) ignores the view's byteStride.
 */
function checkSpan(
  views: ViewRange[],
  v: number,
  offset: number,
  elements: Elements,
  where: string,
  file: string,
  packed = false,
): void {
  const { count, element, componentBytes } = elements;
  const view = views[v];
  if (offset % componentBytes !== 0 || (view.offset + offset) % componentBytes !== 0)
    failIn(
      file,
      `${where}: byte ${offset} of bufferViews[${v}] (byte ${view.offset + offset} of its buffer) is not a multiple of its ${componentBytes}-byte components`,
    );
  const stride = packed ? element : (view.stride ?? element);
  if (stride < element)
    failIn(file, `${where}: bufferViews[${v}].byteStride = ${stride} is less than its ${element}-byte elements`);
  const end = offset + stride * (count - 1) + element;
  if (end > view.length)
    failIn(
      file,
      `${where}: ${count} elements from byte ${offset} end at byte ${end}, past the ${view.length} bytes of bufferViews[${v}]`,
    );
}

// The glTF 2.0 container: .glb (binary, JSON chunk + BIN chunk) or .gltf (JSON text), and the
// buffers it refers to (GLB BIN chunk, base64 data: URIs, or side files read through a reader the
// caller supplies). Only what the rig importer needs is read; meshes, images and extensions are
// never decoded, so a Draco- or meshopt-compressed character still gives its skeleton.
import { failIn } from '../rig_format_error.js';
import { jsonBudgetProblem } from '../json_budget.js';

/** Reads a file next to the glTF (a buffer's relative `uri`, already URI-decoded). */
export type SiblingReader = (uri: string) => Promise<Uint8Array>;

/** A parsed glTF: its JSON document and, for .glb, the BIN chunk. */
export interface GltfContainer {
  json: Record<string, unknown>;
  bin: Uint8Array | undefined;
}

const GLB_MAGIC = 0x46546c67; // 'glTF'
const CHUNK_JSON = 0x4e4f534a;
const CHUNK_BIN = 0x004e4942;

/**
 * Parses `bytes` as .glb (detected by its magic, whatever the extension) or as glTF JSON text.
 * `file` names the source in errors. Throws RigFormatError on a truncated GLB or bad JSON.
 */
export function parseGltfContainer(bytes: Uint8Array, file: string): GltfContainer {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (bytes.byteLength >= 4 && view.getUint32(0, true) === GLB_MAGIC) return parseGlb(bytes, view, file);
  if (file.toLowerCase().endsWith('.glb')) failIn(file, 'not a GLB file (it does not start with "glTF")');
  return { json: parseJsonText(bytes, file), bin: undefined };
}

function parseGlb(bytes: Uint8Array, view: DataView, file: string): GltfContainer {
  if (bytes.byteLength < 20) failIn(file, `truncated GLB: ${bytes.byteLength} bytes, less than a header and a chunk`);
  const version = view.getUint32(4, true);
  if (version !== 2) failIn(file, `GLB version ${version} is not supported (need 2)`);
  const total = view.getUint32(8, true);
  if (total > bytes.byteLength)
    failIn(file, `truncated GLB: the header says ${total} bytes, the file has ${bytes.byteLength}`);
  let json: Record<string, unknown> | undefined;
  let bin: Uint8Array | undefined;
  let at = 12;
  for (let chunk = 0; at < total; chunk++) {
    if (at + 8 > total) failIn(file, `truncated GLB: chunk ${chunk} header runs past the end`);
    const length = view.getUint32(at, true);
    const type = view.getUint32(at + 4, true);
    const start = at + 8;
    if (start + length > total)
      failIn(file, `truncated GLB: chunk ${chunk} needs ${length} bytes, ${total - start} are left`);
    const data = bytes.subarray(start, start + length);
    if (chunk === 0 && type !== CHUNK_JSON) failIn(file, 'bad GLB: the first chunk is not JSON');
    if (type === CHUNK_JSON && json === undefined) json = parseJsonText(data, file);
    else if (type === CHUNK_BIN && bin === undefined) bin = data;
    at = start + length;
  }
  if (json === undefined) failIn(file, 'bad GLB: no JSON chunk');
  return { json, bin };
}

function parseJsonText(bytes: Uint8Array, file: string): Record<string, unknown> {
  let text: string;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    return failIn(file, 'bad JSON: the text is not UTF-8');
  }
  const tooBig = jsonBudgetProblem(text);
  if (tooBig) failIn(file, tooBig);
  let doc: unknown;
  try {
    doc = JSON.parse(text.charCodeAt(0) === 0xfeff ? text.slice(1) : text);
  } catch (e) {
    return failIn(file, `bad JSON: ${(e as Error).message}`);
  }
  if (typeof doc !== 'object' || doc === null || Array.isArray(doc))
    failIn(file, 'bad glTF: the JSON is not an object');
  const asset = (doc as Record<string, unknown>).asset;
  const version = typeof asset === 'object' && asset !== null ? (asset as Record<string, unknown>).version : undefined;
  if (typeof version !== 'string') failIn(file, 'bad glTF: no asset.version (is this a glTF file?)');
  if (!version.startsWith('2.')) failIn(file, `glTF version ${version} is not supported (need 2.0)`);
  return doc as Record<string, unknown>;
}

/**
 * The bytes of buffer `index`: the GLB BIN chunk, a base64 data: URI, or a side file through
 * `readSibling`. `byteLength` is the length the JSON declares; a shorter buffer is an error.
 */
export async function loadBuffer(
  container: GltfContainer,
  index: number,
  uri: string | undefined,
  byteLength: number,
  file: string,
  readSibling: SiblingReader | undefined,
): Promise<Uint8Array> {
  const where = `buffer ${index}`;
  let data: Uint8Array;
  if (uri === undefined) {
    if (index !== 0 || container.bin === undefined)
      failIn(file, `${where} has no uri and there is no GLB binary chunk for it (missing buffer)`);
    data = container.bin;
  } else if (uri.startsWith('data:')) {
    const comma = uri.indexOf(',');
    if (comma < 0 || !uri.slice(0, comma).endsWith(';base64')) failIn(file, `${where}: data URI is not base64`);
    try {
      const text = atob(uri.slice(comma + 1));
      data = new Uint8Array(text.length);
      for (let k = 0; k < text.length; k++) data[k] = text.charCodeAt(k);
    } catch {
      return failIn(file, `${where}: data URI is not valid base64`);
    }
  } else {
    let path: string;
    try {
      path = decodeURIComponent(uri);
    } catch {
      return failIn(file, `${where}: uri "${uri}" is not a valid URI`);
    }
    if (!readSibling) failIn(file, `${where} is in the side file "${path}", and no reader for side files was given`);
    try {
      data = await readSibling(path);
    } catch (e) {
      return failIn(file, `${where}: cannot read the side file "${path}" (missing buffer): ${(e as Error).message}`);
    }
  }
  if (data.byteLength < byteLength)
    failIn(file, `${where} has ${data.byteLength} bytes, its byteLength says ${byteLength} (truncated buffer)`);
  return data;
}
